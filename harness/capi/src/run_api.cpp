// pvatt_run and pvatt_result_*: a run from start to stop into a table of doubles, as `cosim run`
// samples it; the interrupt flag and SIGINT.
#include <atomic>
#include <cmath>
#include <csignal>
#include <cstring>

#include "capi_error.hpp"
#include "capi_handles.hpp"
#include "engine/interrupt.hpp"
#include "engine/run_defaults.hpp"

using namespace pvatt_capi;

namespace {

std::atomic<bool> catch_sigint{false};
volatile std::sig_atomic_t sigint_caught = 0;
struct sigaction previous_sigint {};

extern "C" void on_sigint(int) {
    sigint_caught = 1;
    cosim::record_interrupt(SIGINT);  // an atomic store: safe in a handler
}

// For the functions that return a value, not a status: whether the handle is open, with the message of
// a refusal as the last error when it is not.
bool usable(const pvatt_result* r) {
    return guarded([&] { open_result(r); }) == PVATT_OK;
}

}  // namespace

namespace pvatt_capi {

Recorder::Recorder(const cosim::System& system, const char* const* columns, std::size_t count, pvatt_result& result)
    : result_(result) {
    const auto& comps = system.components();
    if (count == 0) {
        for (std::size_t i = 0; i < comps.size(); ++i)
            for (const auto& v : comps[i].description().model_variables)
                if (v.causality == fmi_loader::Causality::output && v.type != fmi_loader::VariableType::string)
                    columns_.push_back({i, &v});
    } else {
        required(columns, "columns");
        for (std::size_t k = 0; k < count; ++k) {
            const auto ref = find_variable(system, required(columns[k], "columns[k]"));
            if (ref.variable->type == fmi_loader::VariableType::string)
                throw InvalidArgument(std::string(columns[k]) + " is a String: a result column holds numbers");
            columns_.push_back(ref);
        }
    }
    result_.names = {"time"};
    for (const auto& c : columns_) result_.names.push_back(comps[c.component].name + "." + c.variable->name);
}

void Recorder::sample(double t, cosim::System& system) {
    cosim::throw_if_interrupted();  // as cosim run: an output point is a clean place to stop
    auto& comps = system.components();
    result_.data.push_back(t);
    for (const auto& c : columns_) {
        auto& instance = *comps[c.component].instance;
        const auto vr = c.variable->value_reference;
        switch (c.variable->type) {
            case fmi_loader::VariableType::real:
                result_.data.push_back(instance.get_real(vr));
                break;
            case fmi_loader::VariableType::integer:
            case fmi_loader::VariableType::enumeration:
                result_.data.push_back(instance.get_integer(vr));
                break;
            case fmi_loader::VariableType::boolean:
                result_.data.push_back(instance.get_boolean(vr) ? 1.0 : 0.0);
                break;
            case fmi_loader::VariableType::string:
                break;
        }
    }
    last_time_ = t;
}

cosim::ExecutionOptions execution_options(const pvatt_system& handle, const cosim::System& system,
                                          const pvatt_run_options* options) {
    cosim::ExecutionOptions ex;
    ex.start_time = handle.description.start_time.value_or(0.0);
    const double stop =
        options && !std::isnan(options->stop_time) ? options->stop_time : handle.description.stop_time.value_or(NAN);
    if (std::isnan(stop))
        throw InvalidArgument(handle.description.file.string() +
                              " has no DefaultExperiment stopTime: give a stop time");
    if (!std::isfinite(stop) || !(stop > ex.start_time))
        throw InvalidArgument("the stop time " + std::to_string(stop) + " s must be finite and after the start time " +
                              std::to_string(ex.start_time) + " s");
    ex.stop_time = stop;
    const auto defaults = cosim::run_defaults(system, ex.start_time, ex.stop_time);
    ex.output_interval =
        options && !std::isnan(options->output_interval) ? options->output_interval : defaults.output_interval;
    if (!std::isfinite(ex.output_interval) || !(ex.output_interval > 0.0) ||
        ex.output_interval > ex.stop_time - ex.start_time)
        throw InvalidArgument("the output interval " + std::to_string(ex.output_interval) +
                              " s must be positive, finite and not longer than the run");
    if ((ex.stop_time - ex.start_time) / ex.output_interval > cosim::max_run_points)
        throw InvalidArgument("the output interval " + std::to_string(ex.output_interval) + " s makes more than " +
                              std::to_string(cosim::max_run_points) + " rows (cosim::max_run_points)");
    ex.relative_tolerance = defaults.tolerance;
    ex.reference = options && options->reference != 0;
    return ex;
}

BlockingCall::BlockingCall() {
    cosim::clear_interrupt();
    sigint_caught = 0;
    if (!catch_sigint.load()) return;
    struct sigaction action {};
    action.sa_handler = on_sigint;
    sigemptyset(&action.sa_mask);
    installed_ = sigaction(SIGINT, &action, &previous_sigint) == 0;
}

BlockingCall::~BlockingCall() {
    cosim::clear_interrupt();  // the flag stopped this call or came too late for it: never the next call's
    if (!installed_) return;
    sigaction(SIGINT, &previous_sigint, nullptr);
    if (sigint_caught && !reported_) std::raise(SIGINT);
}

}  // namespace pvatt_capi

extern "C" {

void pvatt_interrupt(void) {
    cosim::record_interrupt(SIGINT);
}

void pvatt_catch_sigint(int enable) {
    catch_sigint.store(enable != 0);
}

void pvatt_run_options_init(pvatt_run_options* options) {
    if (!options) return;
    options->stop_time = NAN;
    options->output_interval = NAN;
    options->reference = 0;
}

pvatt_status pvatt_run(pvatt_system* system, const pvatt_run_options* options, const char* const* columns,
                       size_t column_count, pvatt_result** out) {
    std::unique_ptr<pvatt_result> result;
    bool recording = false;  // a result is handed out once its columns are known (not for a bad column name)
    const pvatt_status status = guarded([&] {
        required(out, "out");
        *out = nullptr;
        open_system(system);
        refuse_in_callback("pvatt_run");
        const SystemUse use(system);  // a pvatt_system_close from a callback frees it after the run
        BlockingCall blocking;
        auto sys = build_system(*system, options && options->reference);
        const auto ex = execution_options(*system, *sys, options);
        result = std::make_unique<pvatt_result>();
        Recorder recorder(*sys, columns, column_count, *result);
        recording = true;
        const std::size_t rows = static_cast<std::size_t>((ex.stop_time - ex.start_time) / ex.output_interval) + 2;
        result->data.reserve(rows * result->names.size());
        cosim::Execution execution(*sys, ex);
        try {
            execution.run({&recorder});
        } catch (const cosim::Interrupted&) {
            blocking.reported();
            throw;
        }
    });
    if (out && result && recording) {  // the rows so far, also after an interrupt or a failure
        register_handle(result.get());
        *out = result.release();
    }
    return status;
}

size_t pvatt_result_rows(const pvatt_result* result) {
    return usable(result) ? result->rows() : 0;
}

size_t pvatt_result_columns(const pvatt_result* result) {
    return usable(result) ? result->names.size() : 0;
}

const char* pvatt_result_column_name(const pvatt_result* result, size_t column) {
    return usable(result) && column < result->names.size() ? result->names[column].c_str() : nullptr;
}

const double* pvatt_result_data(const pvatt_result* result) {
    return usable(result) ? result->data.data() : nullptr;
}

pvatt_status pvatt_result_read_column(const pvatt_result* result, size_t column, double* buffer, size_t size) {
    return guarded([&] {
        open_result(result);
        required(buffer, "buffer");
        const std::size_t n = result->rows(), columns = result->names.size();
        if (column >= columns)
            throw InvalidArgument("column " + std::to_string(column) + " out of range (" + std::to_string(columns) +
                                  " columns)");
        if (size < n)
            throw BufferTooSmall("the buffer of " + std::to_string(size) + " doubles is too small for " +
                                 std::to_string(n) + " rows");
        for (std::size_t r = 0; r < n; ++r) buffer[r] = result->data[r * columns + column];
    });
}

void pvatt_result_free(pvatt_result* result) {
    if (!result) return;
    if (!unregister_handle(result)) {
        set_last_error("pvatt_result_free: the result is not open (freed already, or never returned by the library)");
        return;
    }
    delete result;
}

}  // extern "C"
