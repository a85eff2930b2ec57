// One instance of a loaded FMI 2.0 FMU, seen from the master: every FMI call checked, a status of
// fmi2Error or worse turned into a CosimError carrying the FMU's own last log message, and values
// addressed by name or by value reference. The FMI function names appear only here and in the loader.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/component_instance.hpp"
#include "fmi_loader/fmu.hpp"

namespace cosim {

class Fmi2Instance final : public ComponentInstance {
public:
    Fmi2Instance(fmi_loader::Fmu& fmu, fmi_loader::FmuKind kind, std::string instance_name, bool logging_on = false);
    ~Fmi2Instance() override;
    Fmi2Instance(const Fmi2Instance&) = delete;
    Fmi2Instance& operator=(const Fmi2Instance&) = delete;

    const fmi_loader::ModelDescription& description() const override { return fmu_.description(); }
    const std::string& name() const override { return name_; }

    void setup_experiment(double start_time, std::optional<double> stop_time, std::optional<double> tolerance) override;
    void enter_initialization_mode() override;
    void exit_initialization_mode() override;
    void terminate() override;

    double get_real(fmi2ValueReference vr) override;

    void do_step(double t, double h) override;
    void set_real_input_derivatives(std::span<const fmi2ValueReference> vr, std::span<const double> dx) override;
    void get_reals(std::span<const fmi2ValueReference> vr, std::span<double> x) override;
    void set_reals(std::span<const fmi2ValueReference> vr, std::span<const double> x) override;

    // Typed access by value reference (the master's hot path: no name look-ups).
    void set_real(fmi2ValueReference vr, double x) override;
    fmi2Integer get_integer(fmi2ValueReference vr) override;
    void set_integer(fmi2ValueReference vr, fmi2Integer x) override;
    bool get_boolean(fmi2ValueReference vr) override;
    void set_boolean(fmi2ValueReference vr, bool x) override;
    std::string get_string(fmi2ValueReference vr) override;
    void set_string(fmi2ValueReference vr, const std::string& x) override;

    // Model Exchange.
    void set_time(double t) override;
    void set_states(const double* x, std::size_t n) override;
    void get_states(double* x, std::size_t n) override;
    void get_derivatives(double* dx, std::size_t n) override;
    void get_nominals(double* nominal, std::size_t n) override;
    void get_event_indicators(double* z, std::size_t n) override;
    void enter_event_mode() override;
    fmi2EventInfo new_discrete_states() override;
    void enter_continuous_time_mode() override;
    // Returns true when the FMU asks for a step event.
    bool completed_integrator_step(bool* terminate) override;

    // FMI 2.0: outputs are functions of the time, states, inputs, parameters and discrete states, which only
    // the calls that count here change (each setter, event and step; getters do not).
    std::optional<std::uint64_t> values_version() const override { return version_; }

    // Messages the FMU logged (status and text), newest last; the master prints warnings and errors.
    const std::vector<std::pair<fmi2Status, std::string>>& messages() const { return messages_; }
    void record(fmi2Status status, std::string message);

private:
    void check(fmi2Status status, const char* function);
    // A call that may change values: a new version, and the time and states last given are no longer known
    // to be the FMU's (an event may move its states).
    void changed() {
        ++version_;
        ++other_changes_;
    }

    fmi_loader::Fmu& fmu_;
    const fmi_loader::Fmi2Library& lib_;
    std::string name_;
    fmi2CallbackFunctions callbacks_;
    fmi2Component component_ = nullptr;
    std::vector<fmi2Integer> first_order_;  // the orders argument of fmi2SetRealInputDerivatives: all 1
    std::vector<std::pair<fmi2Status, std::string>> messages_;
    std::size_t unreported_errors_ = 0;  // Error/Fatal messages held for the exception of the failing call
    std::uint64_t version_ = 0;          // values_version()
    std::uint64_t other_changes_ = 0;    // calls other than fmi2SetTime and fmi2SetContinuousStates
    // The time and states last given, and other_changes_ then: the same bits again, with nothing else
    // called in between, are not given again (a Model Exchange master sets both at the instant where its
    // integrator just checked the event indicators).
    std::optional<double> time_given_;
    std::uint64_t time_given_after_ = 0;
    std::vector<double> states_given_;
    bool states_known_ = false;
    std::uint64_t states_given_after_ = 0;
};

}  // namespace cosim
