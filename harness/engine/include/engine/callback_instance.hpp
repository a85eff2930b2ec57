// A component whose block is a function of the caller's (a Python callable through the C API, say),
// in place of its FMU as the hardware bridge puts a board in place of one. It keeps the block's
// modelDescription (ports, units and wiring as with the FMU) and acts as a Model Exchange component
// without states: at each sample instant t0 + k * period it calls the function with its current
// inputs and applies the outputs at that same instant. Between samples its outputs hold.
//
// At an instant where other components sample too, the master calls every component in event mode once
// per round, in the system's order, and propagates values between rounds (execution.cpp, event_iteration):
// the function's first call sees its inputs as they were just before the instant (a sampled source's
// previous output). With `current_inputs` it is called again at the same instant whenever its inputs
// changed after its last call there, until they settle, so that its last call sees the instant's final
// inputs (a sensor model whose output must follow a command issued at this very instant).
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "engine/component_instance.hpp"

namespace cosim {

// The function: time, the component's inputs (causality input, model-description order, as doubles),
// its outputs to write (causality output, same order). It throws to stop the run.
using StepFunction = std::function<void(double t, std::span<const double> inputs, std::span<double> outputs)>;

class CallbackInstance final : public ComponentInstance {
public:
    CallbackInstance(const fmi_loader::ModelDescription& description, std::string name, double period,
                     StepFunction step, bool current_inputs = false);

    const std::string& name() const override { return name_; }
    const fmi_loader::ModelDescription& description() const override { return description_; }

    void setup_experiment(double start_time, std::optional<double> stop_time, std::optional<double> tolerance) override;
    void enter_initialization_mode() override {}
    void exit_initialization_mode() override {}
    void terminate() override {}

    double get_real(fmi2ValueReference vr) override { return values_[slot(vr)]; }
    void set_real(fmi2ValueReference vr, double x) override { values_[slot(vr)] = x; }
    fmi2Integer get_integer(fmi2ValueReference vr) override;
    void set_integer(fmi2ValueReference vr, fmi2Integer x) override { values_[slot(vr)] = x; }
    bool get_boolean(fmi2ValueReference vr) override { return values_[slot(vr)] != 0.0; }
    void set_boolean(fmi2ValueReference vr, bool x) override { values_[slot(vr)] = x ? 1.0 : 0.0; }
    std::string get_string(fmi2ValueReference vr) override;
    void set_string(fmi2ValueReference vr, const std::string& x) override;

    void do_step(double t, double h) override;
    void set_real_input_derivatives(std::span<const fmi2ValueReference>, std::span<const double>) override {}

    void set_time(double t) override { time_ = t; }
    void set_states(const double*, std::size_t) override {}
    void get_states(double*, std::size_t) override {}
    void get_derivatives(double*, std::size_t) override {}
    void get_nominals(double*, std::size_t) override {}
    void get_event_indicators(double*, std::size_t) override {}
    void enter_event_mode() override {}
    fmi2EventInfo new_discrete_states() override;
    void enter_continuous_time_mode() override {}
    bool completed_integrator_step(bool* terminate) override;

    // The variables the function sees and writes, in the order of its spans.
    const std::vector<const fmi_loader::ScalarVariable*>& inputs() const { return input_variables_; }
    const std::vector<const fmi_loader::ScalarVariable*>& outputs() const { return output_variables_; }

private:
    std::size_t slot(fmi2ValueReference vr) const;
    double next_sample_time() const { return start_time_ + static_cast<double>(next_sample_) * period_; }
    void sample();

    const fmi_loader::ModelDescription& description_;
    std::string name_;
    double period_;
    StepFunction step_;
    std::map<fmi2ValueReference, std::size_t> slots_;  // non-String variables -> index into values_
    std::map<fmi2ValueReference, std::string> strings_;
    std::vector<double> values_;
    std::vector<const fmi_loader::ScalarVariable*> input_variables_, output_variables_;
    std::vector<std::size_t> input_slots_, output_slots_;
    std::vector<double> in_, out_;  // the spans handed to the function (no allocation per sample)
    double start_time_ = 0.0, time_ = 0.0;
    long next_sample_ = 0;
    bool current_inputs_ = false;
    std::optional<double> last_sample_time_;  // the instant of the last call
};

}  // namespace cosim
