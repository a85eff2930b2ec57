// One instance of a loaded FMI 3.0 FMU, seen from the master through the same ComponentInstance as an
// FMI 2.0 one. The master sees the FMU's scalars (fmi_loader::scalar_view: an array is one variable per
// element, "x[2]"), typed as FMI 2.0 kinds: Float32/64 as Real, the eight integer types and
// Enumerations as Integer (a value outside the Integer range is an error naming it), Boolean, String,
// and Binary as String holding hexadecimal text. The FMI 3.0 mode machine is kept inside:
// Model Exchange maps one to one (fmi3UpdateDiscreteStates for fmi2NewDiscreteStates); Co-Simulation
// with event mode (when the FMU has it and `event_mode` is asked) handles the events fmi3DoStep reports
// and the changes of discrete inputs in Event Mode before the next step.
// Refused, each by name: Scheduled Execution, clocks, arrays of String or Binary.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "engine/component_instance.hpp"
#include "fmi_loader/fmu.hpp"
#include "fmi_loader/scalar_view.hpp"

namespace cosim {

// Throws CosimError naming the first FMI 3.0 feature of `md` that cosim does not run (Scheduled
// Execution only, clocks, String or Binary arrays).
void refuse_unsupported_fmi3(const fmi_loader::ModelDescription& md, const std::string& component);

class Fmi3Instance final : public ComponentInstance {
public:
    Fmi3Instance(fmi_loader::Fmu& fmu, fmi_loader::FmuKind kind, std::string instance_name, bool event_mode = true,
                 bool logging_on = false);
    ~Fmi3Instance() override;
    Fmi3Instance(const Fmi3Instance&) = delete;
    Fmi3Instance& operator=(const Fmi3Instance&) = delete;

    // The scalar view: one variable per array element, value reference = its position.
    const fmi_loader::ModelDescription& description() const override { return view_.description; }
    const std::string& name() const override { return name_; }
    bool uses_event_mode() const noexcept { return event_mode_; }

    void setup_experiment(double start_time, std::optional<double> stop_time, std::optional<double> tolerance) override;
    void enter_initialization_mode() override;
    void exit_initialization_mode() override;
    void terminate() override;

    double get_real(fmi2ValueReference vr) override;
    void set_real(fmi2ValueReference vr, double x) override;
    void get_reals(std::span<const fmi2ValueReference> vr, std::span<double> x) override;
    void set_reals(std::span<const fmi2ValueReference> vr, std::span<const double> x) override;
    fmi2Integer get_integer(fmi2ValueReference vr) override;
    void set_integer(fmi2ValueReference vr, fmi2Integer x) override;
    bool get_boolean(fmi2ValueReference vr) override;
    void set_boolean(fmi2ValueReference vr, bool x) override;
    std::string get_string(fmi2ValueReference vr) override;
    void set_string(fmi2ValueReference vr, const std::string& x) override;

    void do_step(double t, double h) override;
    bool terminate_requested() const override { return terminate_requested_; }
    void set_real_input_derivatives(std::span<const fmi2ValueReference> vr, std::span<const double> dx) override;

    void set_time(double t) override;
    void set_states(const double* x, std::size_t n) override;
    void get_states(double* x, std::size_t n) override;
    void get_derivatives(double* dx, std::size_t n) override;
    void get_nominals(double* nominal, std::size_t n) override;
    void get_event_indicators(double* z, std::size_t n) override;
    void enter_event_mode() override;
    fmi2EventInfo new_discrete_states() override;
    void enter_continuous_time_mode() override;
    bool completed_integrator_step(bool* terminate) override;

    // FMU state (canGetAndSetFMUState): a snapshot the instance can return to; null when the FMU
    // cannot (an error names the capability).
    using State = void*;
    State get_state();
    void set_state(State s);
    void free_state(State s);
    // The snapshot serialized (canSerializeFMUState) and read back into a new snapshot.
    std::vector<std::uint8_t> serialize(State s);
    State deserialize(const std::vector<std::uint8_t>& bytes);

    const std::vector<std::pair<int, std::string>>& messages() const { return messages_; }
    void record(int status, std::string message);

private:
    void check(int status, const char* function);
    const fmi_loader::ScalarElement& element(fmi2ValueReference vr) const;
    // Every value of the FMI 3.0 variable behind `e`, as doubles (into `out`) or as 64-bit integers.
    void read_floats(const fmi_loader::ScalarElement& e, std::vector<double>& out);
    std::vector<std::int64_t> read_integers(const fmi_loader::ScalarElement& e);
    void write_floats(const fmi_loader::ScalarElement& e, const std::vector<double>& values);
    void write_integers(const fmi_loader::ScalarElement& e, const std::vector<std::int64_t>& values);
    // The values last written to an array variable (an element is set by writing the whole array;
    // the first write starts from the values the FMU holds).
    std::vector<double>& float_array(const fmi_loader::ScalarElement& e);
    std::vector<std::int64_t>& int_array(const fmi_loader::ScalarElement& e);
    // A set of a discrete input in Co-Simulation step mode with event mode used waits for the next
    // Event Mode (FMI 3.0.2 section 4.2.4: discrete inputs change in Event Mode only).
    bool must_defer(fmi2ValueReference vr) const;
    void set_or_defer(fmi2ValueReference vr, std::function<void()> set);
    void write_real(const fmi_loader::ScalarElement& e, double x);
    void event_iteration();
    void string_arrays_refused(const fmi_loader::ScalarElement& e) const;

    fmi_loader::Fmu& fmu_;
    const fmi_loader::Fmi3Library& lib_;
    fmi_loader::ScalarView view_;
    std::string name_;
    bool co_simulation_ = false;
    bool event_mode_ = false;
    bool instantiated_ = true;  // before fmi3EnterInitializationMode: no get allowed
    bool in_step_mode_ = false;
    bool terminate_requested_ = false;
    void* instance_ = nullptr;
    double start_time_ = 0.0;
    std::optional<double> stop_time_, tolerance_;
    std::vector<std::uint32_t> scratch_vr_;
    std::vector<double> scratch_values_;
    std::vector<fmi3Float32> scratch_f32_;
    std::vector<std::vector<double>> float_arrays_;      // by variable index, once written
    std::vector<std::vector<std::int64_t>> int_arrays_;  // the same for integer arrays
    std::vector<std::function<void()>> deferred_;        // discrete input sets for the next Event Mode
    std::vector<std::pair<int, std::string>> messages_;
    std::size_t unreported_errors_ = 0;  // Error/Fatal messages held for the exception of the failing call
};

}  // namespace cosim
