// One instance of a loaded FMI 2.0 FMU, seen from the master: every FMI call checked, a status of
// fmi2Error or worse turned into a CosimError carrying the FMU's own last log message, and values
// addressed by name or by value reference. The FMI function names appear only here and in the loader.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fmi_loader/fmu.hpp"

namespace cosim {

class Fmi2Instance {
public:
    Fmi2Instance(fmi_loader::Fmu& fmu, fmi_loader::FmuKind kind, std::string instance_name, bool logging_on = false);
    ~Fmi2Instance();
    Fmi2Instance(const Fmi2Instance&) = delete;
    Fmi2Instance& operator=(const Fmi2Instance&) = delete;

    const fmi_loader::ModelDescription& description() const { return fmu_.description(); }
    const std::string& name() const { return name_; }

    void setup_experiment(double start_time, std::optional<double> stop_time, std::optional<double> tolerance);
    void enter_initialization_mode();
    void exit_initialization_mode();
    void terminate();

    // Sets a variable from text ("0.5", "true", "qmethod"), parsed by the variable's declared type.
    void set_from_text(std::string_view name, std::string_view text);
    double get_real(fmi2ValueReference vr);
    // The value of any variable as text (for tables and CSV).
    std::string get_as_text(const fmi_loader::ScalarVariable& v);

    void do_step(double t, double h);

    // Typed access by value reference (the master's hot path: no name look-ups).
    void set_real(fmi2ValueReference vr, double x);
    fmi2Integer get_integer(fmi2ValueReference vr);
    void set_integer(fmi2ValueReference vr, fmi2Integer x);
    bool get_boolean(fmi2ValueReference vr);
    void set_boolean(fmi2ValueReference vr, bool x);
    std::string get_string(fmi2ValueReference vr);
    void set_string(fmi2ValueReference vr, const std::string& x);

    // Model Exchange.
    void set_time(double t);
    void set_states(const double* x, std::size_t n);
    void get_states(double* x, std::size_t n);
    void get_derivatives(double* dx, std::size_t n);
    void get_nominals(double* nominal, std::size_t n);
    void get_event_indicators(double* z, std::size_t n);
    void enter_event_mode();
    fmi2EventInfo new_discrete_states();
    void enter_continuous_time_mode();
    // Returns true when the FMU asks for a step event.
    bool completed_integrator_step(bool* terminate);

    // Messages the FMU logged (status and text), newest last; the master prints warnings and errors.
    const std::vector<std::pair<fmi2Status, std::string>>& messages() const { return messages_; }
    void record(fmi2Status status, std::string message);

private:
    void check(fmi2Status status, const char* function);

    fmi_loader::Fmu& fmu_;
    const fmi_loader::Fmi2Library& lib_;
    std::string name_;
    fmi2CallbackFunctions callbacks_;
    fmi2Component component_ = nullptr;
    std::vector<std::pair<fmi2Status, std::string>> messages_;
};

}  // namespace cosim
