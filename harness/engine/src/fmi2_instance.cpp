#include "engine/fmi2_instance.hpp"

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <iostream>

#include "engine/cosim_error.hpp"
#include "engine/value_text.hpp"
#include "same_bits.hpp"

namespace cosim {

namespace {

// FMI loggers are printf-like: format the message with its arguments before storing it.
void logger(fmi2ComponentEnvironment env, fmi2String, fmi2Status status, fmi2String, fmi2String message, ...) {
    if (!env || !message) return;
    va_list args;
    va_start(args, message);
    va_list copy;
    va_copy(copy, args);
    const int n = std::vsnprintf(nullptr, 0, message, copy);
    va_end(copy);
    std::string text(n > 0 ? static_cast<std::size_t>(n) : 0, '\0');
    if (n > 0) std::vsnprintf(text.data(), text.size() + 1, message, args);
    va_end(args);
    static_cast<Fmi2Instance*>(env)->record(status, std::move(text));
}

const char* status_name(fmi2Status s) {
    switch (s) {
        case fmi2OK:
            return "OK";
        case fmi2Warning:
            return "Warning";
        case fmi2Discard:
            return "Discard";
        case fmi2Error:
            return "Error";
        case fmi2Fatal:
            return "Fatal";
        case fmi2Pending:
            return "Pending";
    }
    return "?";
}

}  // namespace

Fmi2Instance::Fmi2Instance(fmi_loader::Fmu& fmu, fmi_loader::FmuKind kind, std::string instance_name, bool logging_on)
    : fmu_(fmu),
      lib_(fmu.library(kind)),
      name_(std::move(instance_name)),
      callbacks_{logger, std::calloc, std::free, nullptr, this} {
    const auto& md = fmu_.description();
    component_ = lib_->fmi2Instantiate(
        name_.c_str(), kind == fmi_loader::FmuKind::model_exchange ? fmi2ModelExchange : fmi2CoSimulation,
        md.guid.c_str(), fmu_.archive().resource_uri().c_str(), &callbacks_, fmi2False,
        logging_on ? fmi2True : fmi2False);
    if (!component_) {
        std::string why = messages_.empty() ? "no message from the FMU" : messages_.back().second;
        throw CosimError(name_ + ": fmi2Instantiate failed: " + why);
    }
}

Fmi2Instance::~Fmi2Instance() {
    if (component_) lib_->fmi2FreeInstance(component_);
}

// Warnings and discards are printed as they come; an error's message is held and said once, in the
// exception of the call that failed (it was printed here and again in that exception).
void Fmi2Instance::record(fmi2Status status, std::string message) {
    if (status >= fmi2Error)
        ++unreported_errors_;
    else if (status >= fmi2Warning)
        std::cerr << name_ << " [" << status_name(status) << "] " << message << "\n";
    messages_.emplace_back(status, std::move(message));
}

void Fmi2Instance::check(fmi2Status status, const char* function) {
    const std::size_t held = std::min(unreported_errors_, messages_.size());
    unreported_errors_ = 0;
    if (status < fmi2Error) {
        // An error logged by a call that did not fail: said now, not lost.
        for (std::size_t i = messages_.size() - held; i < messages_.size(); ++i)
            if (messages_[i].first >= fmi2Error)
                std::cerr << name_ << " [" << status_name(messages_[i].first) << "] " << messages_[i].second << "\n";
        return;
    }
    std::string why = messages_.empty() ? "no message from the FMU" : messages_.back().second;
    throw CosimError(name_ + ": " + function + " returned " + status_name(status) + ": " + why);
}

void Fmi2Instance::setup_experiment(double start_time, std::optional<double> stop_time,
                                    std::optional<double> tolerance) {
    changed();
    check(lib_->fmi2SetupExperiment(component_, tolerance ? fmi2True : fmi2False, tolerance.value_or(0.0), start_time,
                                    stop_time ? fmi2True : fmi2False, stop_time.value_or(0.0)),
          "fmi2SetupExperiment");
}

void Fmi2Instance::enter_initialization_mode() {
    changed();
    check(lib_->fmi2EnterInitializationMode(component_), "fmi2EnterInitializationMode");
}
void Fmi2Instance::exit_initialization_mode() {
    changed();
    check(lib_->fmi2ExitInitializationMode(component_), "fmi2ExitInitializationMode");
}
void Fmi2Instance::terminate() {
    changed();
    check(lib_->fmi2Terminate(component_), "fmi2Terminate");
}

double Fmi2Instance::get_real(fmi2ValueReference vr) {
    fmi2Real x = 0.0;
    check(lib_->fmi2GetReal(component_, &vr, 1, &x), "fmi2GetReal");
    return x;
}

void Fmi2Instance::do_step(double t, double h) {
    changed();
    check(lib_->fmi2DoStep(component_, t, h, fmi2True), "fmi2DoStep");
}

void Fmi2Instance::set_real_input_derivatives(std::span<const fmi2ValueReference> vr, std::span<const double> dx) {
    changed();
    if (first_order_.size() < vr.size()) first_order_.resize(vr.size(), 1);
    check(lib_->fmi2SetRealInputDerivatives(component_, vr.data(), vr.size(), first_order_.data(), dx.data()),
          "fmi2SetRealInputDerivatives");
}

void Fmi2Instance::get_reals(std::span<const fmi2ValueReference> vr, std::span<double> x) {
    check(lib_->fmi2GetReal(component_, vr.data(), vr.size(), x.data()), "fmi2GetReal");
}

void Fmi2Instance::set_reals(std::span<const fmi2ValueReference> vr, std::span<const double> x) {
    changed();
    check(lib_->fmi2SetReal(component_, vr.data(), vr.size(), x.data()), "fmi2SetReal");
}

void Fmi2Instance::set_real(fmi2ValueReference vr, double x) {
    changed();
    check(lib_->fmi2SetReal(component_, &vr, 1, &x), "fmi2SetReal");
}

fmi2Integer Fmi2Instance::get_integer(fmi2ValueReference vr) {
    fmi2Integer x = 0;
    check(lib_->fmi2GetInteger(component_, &vr, 1, &x), "fmi2GetInteger");
    return x;
}

void Fmi2Instance::set_integer(fmi2ValueReference vr, fmi2Integer x) {
    changed();
    check(lib_->fmi2SetInteger(component_, &vr, 1, &x), "fmi2SetInteger");
}

bool Fmi2Instance::get_boolean(fmi2ValueReference vr) {
    fmi2Boolean x = 0;
    check(lib_->fmi2GetBoolean(component_, &vr, 1, &x), "fmi2GetBoolean");
    return x != fmi2False;
}

void Fmi2Instance::set_boolean(fmi2ValueReference vr, bool x) {
    changed();
    const fmi2Boolean b = x ? fmi2True : fmi2False;
    check(lib_->fmi2SetBoolean(component_, &vr, 1, &b), "fmi2SetBoolean");
}

std::string Fmi2Instance::get_string(fmi2ValueReference vr) {
    fmi2String x = nullptr;
    check(lib_->fmi2GetString(component_, &vr, 1, &x), "fmi2GetString");
    return x ? x : "";
}

void Fmi2Instance::set_string(fmi2ValueReference vr, const std::string& x) {
    changed();
    const fmi2String s = x.c_str();
    check(lib_->fmi2SetString(component_, &vr, 1, &s), "fmi2SetString");
}

void Fmi2Instance::set_time(double t) {
    if (time_given_ && time_given_after_ == other_changes_ && same_bits(*time_given_, t)) return;
    time_given_.reset();  // unknown if the call fails
    ++version_;
    check(lib_->fmi2SetTime(component_, t), "fmi2SetTime");
    time_given_ = t;
    time_given_after_ = other_changes_;
}

void Fmi2Instance::set_states(const double* x, std::size_t n) {
    if (states_known_ && states_given_after_ == other_changes_ && same_bits(states_given_, std::span(x, n))) return;
    states_known_ = false;
    ++version_;
    check(lib_->fmi2SetContinuousStates(component_, x, n), "fmi2SetContinuousStates");
    states_given_.assign(x, x + n);
    states_known_ = true;
    states_given_after_ = other_changes_;
}

void Fmi2Instance::get_states(double* x, std::size_t n) {
    check(lib_->fmi2GetContinuousStates(component_, x, n), "fmi2GetContinuousStates");
}

void Fmi2Instance::get_derivatives(double* dx, std::size_t n) {
    check(lib_->fmi2GetDerivatives(component_, dx, n), "fmi2GetDerivatives");
}

void Fmi2Instance::get_nominals(double* nominal, std::size_t n) {
    check(lib_->fmi2GetNominalsOfContinuousStates(component_, nominal, n), "fmi2GetNominalsOfContinuousStates");
}

void Fmi2Instance::get_event_indicators(double* z, std::size_t n) {
    check(lib_->fmi2GetEventIndicators(component_, z, n), "fmi2GetEventIndicators");
}

void Fmi2Instance::enter_event_mode() {
    changed();
    check(lib_->fmi2EnterEventMode(component_), "fmi2EnterEventMode");
}

fmi2EventInfo Fmi2Instance::new_discrete_states() {
    changed();
    fmi2EventInfo info{};
    check(lib_->fmi2NewDiscreteStates(component_, &info), "fmi2NewDiscreteStates");
    return info;
}

void Fmi2Instance::enter_continuous_time_mode() {
    changed();
    check(lib_->fmi2EnterContinuousTimeMode(component_), "fmi2EnterContinuousTimeMode");
}

bool Fmi2Instance::completed_integrator_step(bool* terminate) {
    changed();
    fmi2Boolean enter = fmi2False, stop = fmi2False;
    check(lib_->fmi2CompletedIntegratorStep(component_, fmi2True, &enter, &stop), "fmi2CompletedIntegratorStep");
    if (terminate) *terminate = stop != fmi2False;
    return enter != fmi2False;
}

}  // namespace cosim
