#include "fmi_session.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace conformance {

using namespace fmi_loader;

const char* status_name(fmi2Status s) {
    switch (s) {
        case fmi2OK:
            return "fmi2OK";
        case fmi2Warning:
            return "fmi2Warning";
        case fmi2Discard:
            return "fmi2Discard";
        case fmi2Error:
            return "fmi2Error";
        case fmi2Fatal:
            return "fmi2Fatal";
        case fmi2Pending:
            return "fmi2Pending";
    }
    return "invalid status";
}

bool LogSink::has_since(std::size_t mark, fmi2Status min_status) const {
    for (std::size_t i = mark; i < records.size(); ++i)
        if (records[i].status >= min_status && records[i].status != fmi2Pending) return true;
    return false;
}

std::string LogSink::dump() const {
    std::string out;
    for (const auto& r : records)
        out += std::string("  [") + status_name(r.status) + "] " + r.category + ": " + r.message + "\n";
    return out;
}

namespace {

// The FMI logger: `message` is a printf format with the variadic arguments (section 2.1.5).
void record_log(fmi2ComponentEnvironment env, fmi2String, fmi2Status status, fmi2String category, fmi2String message,
                ...) {
    auto* sink = static_cast<LogSink*>(env);
    if (!sink) return;
    char buffer[2048] = "";
    if (message) {
        va_list args;
        va_start(args, message);
        std::vsnprintf(buffer, sizeof buffer, message, args);
        va_end(args);
    }
    sink->records.push_back({status, category ? category : "", buffer});
}

}  // namespace

Instance::Instance(Fmu& fmu, FmuKind kind, const std::string& name, std::optional<std::string> guid)
    : f_(&fmu.library(kind).functions()), md_(&fmu.description()), sink_(std::make_unique<LogSink>()) {
    callbacks_.reset(new fmi2CallbackFunctions{record_log, std::calloc, std::free, nullptr, sink_.get()});
    const std::string uri = fmu.archive().resource_uri();
    c_ = f_->fmi2Instantiate(name.c_str(), kind == FmuKind::model_exchange ? fmi2ModelExchange : fmi2CoSimulation,
                             guid ? guid->c_str() : md_->guid.c_str(), uri.c_str(), callbacks_.get(), fmi2False,
                             fmi2True);
}

Instance::~Instance() {
    free();
}

void Instance::free() {
    if (c_) f_->fmi2FreeInstance(c_);
    c_ = nullptr;
}

fmi2Status Instance::initialize(double start_time, std::optional<double> stop_time) {
    fmi2Status s = f_->fmi2SetupExperiment(c_, fmi2False, 0.0, start_time, stop_time ? fmi2True : fmi2False,
                                           stop_time.value_or(0.0));
    if (s > fmi2Warning) return s;
    s = f_->fmi2EnterInitializationMode(c_);
    if (s > fmi2Warning) return s;
    return f_->fmi2ExitInitializationMode(c_);
}

fmi2Status Instance::set_real(std::uint32_t vr, double value) {
    return f_->fmi2SetReal(c_, &vr, 1, &value);
}
fmi2Status Instance::set_integer(std::uint32_t vr, int value) {
    return f_->fmi2SetInteger(c_, &vr, 1, &value);
}
fmi2Status Instance::get_real(std::uint32_t vr, double& value) {
    return f_->fmi2GetReal(c_, &vr, 1, &value);
}

fmi2Status Instance::set_start(const ScalarVariable& v) {
    const fmi2ValueReference vr = v.value_reference;
    switch (v.type) {
        case VariableType::real: {
            const fmi2Real x = v.start_as_real().value_or(0.0);
            return f_->fmi2SetReal(c_, &vr, 1, &x);
        }
        case VariableType::integer:
        case VariableType::enumeration: {
            const fmi2Integer x = static_cast<fmi2Integer>(v.start_as_real().value_or(0.0));
            return f_->fmi2SetInteger(c_, &vr, 1, &x);
        }
        case VariableType::boolean: {
            const fmi2Boolean x = v.start_as_boolean().value_or(false) ? fmi2True : fmi2False;
            return f_->fmi2SetBoolean(c_, &vr, 1, &x);
        }
        case VariableType::string: {
            const fmi2String x = v.start ? v.start->c_str() : "";
            return f_->fmi2SetString(c_, &vr, 1, &x);
        }
    }
    return fmi2Error;
}

fmi2Status Instance::get_text(const ScalarVariable& v, std::string& text) {
    const fmi2ValueReference vr = v.value_reference;
    fmi2Status s = fmi2Error;
    switch (v.type) {
        case VariableType::real: {
            fmi2Real x = std::nan("");
            s = f_->fmi2GetReal(c_, &vr, 1, &x);
            char buf[64];
            std::snprintf(buf, sizeof buf, "%.17g", x);
            text = buf;
            break;
        }
        case VariableType::integer:
        case VariableType::enumeration: {
            fmi2Integer x = 0;
            s = f_->fmi2GetInteger(c_, &vr, 1, &x);
            text = std::to_string(x);
            break;
        }
        case VariableType::boolean: {
            fmi2Boolean x = fmi2False;
            s = f_->fmi2GetBoolean(c_, &vr, 1, &x);
            text = x ? "true" : "false";
            break;
        }
        case VariableType::string: {
            fmi2String x = nullptr;
            s = f_->fmi2GetString(c_, &vr, 1, &x);
            text = x ? x : "<null>";
            if (!x && s <= fmi2Warning) s = fmi2Error;  // a successful get must deliver a string
            break;
        }
    }
    return s;
}

std::size_t Experiment::steps() const {
    return static_cast<std::size_t>(std::llround((stop - start) / step));
}

Experiment experiment_of(const ModelDescription& md, double max_seconds, std::size_t max_steps) {
    Experiment e;
    const auto& de = md.default_experiment;
    e.start = de && de->start_time ? *de->start_time : 0.0;
    const double stop = de && de->stop_time ? *de->stop_time : e.start + 1.0;
    e.stop = std::min(stop, e.start + max_seconds);
    e.step = de && de->step_size ? *de->step_size : (e.stop - e.start) / 100.0;
    e.step = std::max(e.step, (e.stop - e.start) / static_cast<double>(max_steps));
    // Whole number of steps so the last communication point is exactly `stop`.
    e.stop = e.start + static_cast<double>(std::max<std::size_t>(1, e.steps())) * e.step;
    return e;
}

std::vector<std::uint64_t> real_output_bits(Instance& inst) {
    std::vector<std::uint64_t> bits;
    for (const auto& v : inst.md().model_variables) {
        if (v.causality != Causality::output || v.type != VariableType::real) continue;
        double x = 0.0;
        inst.get_real(v.value_reference, x);
        std::uint64_t b;
        std::memcpy(&b, &x, sizeof b);
        bits.push_back(b);
    }
    return bits;
}

IsolatedResult run_isolated(const std::function<fmi2Status(bool& logged, std::string& log)>& call) {
    IsolatedResult result;
    int fds[2];
    if (pipe(fds) != 0) {
        result.crash = "pipe() failed";
        return result;
    }
    std::fflush(nullptr);
    const pid_t pid = fork();
    if (pid < 0) {
        result.crash = "fork() failed";
        return result;
    }
    if (pid == 0) {
        close(fds[0]);
        bool logged = false;
        std::string log;
        const fmi2Status s = call(logged, log);
        const int header[2] = {static_cast<int>(s), logged ? 1 : 0};
        [[maybe_unused]] ssize_t w = write(fds[1], header, sizeof header);
        w = write(fds[1], log.data(), log.size());
        close(fds[1]);
        _exit(0);  // no destructors, no gtest teardown in the child
    }
    close(fds[1]);
    int header[2] = {0, 0};
    const ssize_t got = read(fds[0], header, sizeof header);
    char buf[4096];
    ssize_t n;
    while ((n = read(fds[0], buf, sizeof buf)) > 0) result.log.append(buf, static_cast<std::size_t>(n));
    close(fds[0]);
    int wstatus = 0;
    waitpid(pid, &wstatus, 0);
    if (WIFSIGNALED(wstatus)) {
        result.crash = std::string("crashed with signal ") + strsignal(WTERMSIG(wstatus));
    } else if (!WIFEXITED(wstatus) || WEXITSTATUS(wstatus) != 0 || got != static_cast<ssize_t>(sizeof header)) {
        result.crash = "child exited abnormally (exit code " +
                       std::to_string(WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : -1) + ")";
    } else {
        result.completed = true;
        result.status = static_cast<fmi2Status>(header[0]);
        result.logged = header[1] != 0;
    }
    return result;
}

}  // namespace conformance
