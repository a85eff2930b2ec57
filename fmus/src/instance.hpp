// One FMU instance: the FMI 2.0 mode machine, the host's callbacks and logging, value access by value
// reference, and the Model Exchange / Co-Simulation operations, in C++ with exceptions. The C entry
// points (fmi2_api.cpp) only check the handle and call these through one guard.
#pragma once

#include <memory>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "call_rules.hpp"
#include "fmi2/fmi2FunctionTypes.h"
#include "fmu/cs_solver.hpp"
#include "fmu/model_runner.hpp"

namespace fmu {

// The log categories this FMU declares in its model description, in that order.
inline constexpr const char* log_categories[] = {
    "logEvents", "logStatusWarning", "logStatusDiscard", "logStatusError", "logStatusFatal", "logStatistics", "logAll"};
inline constexpr const char* log_category_descriptions[] = {"Events: time and state events, discrete updates",
                                                            "Messages with status Warning (fmi2Warning, fmi3Warning)",
                                                            "Messages with status Discard (fmi2Discard, fmi3Discard)",
                                                            "Messages with status Error (fmi2Error, fmi3Error)",
                                                            "Messages with status Fatal (fmi2Fatal, fmi3Fatal)",
                                                            "Integrator statistics of Co-Simulation runs",
                                                            "Every call of the FMI functions"};

enum class Kind { model_exchange, co_simulation };

// A saved FMU state: the block's bytes plus the runtime's own state.
struct Snapshot {
    std::unique_ptr<Model> model;
    double time = 0.0;
    std::optional<Mode> mode;  // the mode it was taken in; none when it came from bytes
    double last_successful_time = 0.0;
    bool terminate_requested = false;
};

class Instance {
public:
    Instance(std::string name, Kind kind, const fmi2CallbackFunctions& callbacks, bool logging_on,
             std::unique_ptr<Model> model, std::string guid);
    ~Instance();

    // Logging through the host's callback. Errors and warnings are always passed on; the other
    // categories only when enabled with fmi2SetDebugLogging or loggingOn.
    void log(fmi2Status status, const char* category, const std::string& message) const;
    void log_call(std::string_view function) const;  // logAll
    // Whether log_call says anything: asked first, so that a call's name is not even looked up otherwise.
    bool logs_calls() const { return logger_ && category_enabled_.back(); }  // logAll: the last category
    void set_debug_logging(bool on, std::span<const fmi2String> categories);

    // Throws fmu::Error naming the mode when `call` is not allowed now.
    void require(Call call) const;
    void require_kind(Kind kind, Call call) const;
    Mode mode() const { return mode_; }
    void enter_error_mode() { mode_ = Mode::error; }

    void setup_experiment(bool tolerance_defined, double tolerance, double start_time, bool stop_defined,
                          double stop_time);
    void enter_initialization_mode();
    void exit_initialization_mode();
    void terminate();
    void reset();

    void get_real(std::span<const fmi2ValueReference> vr, fmi2Real* values);
    void get_integer(std::span<const fmi2ValueReference> vr, fmi2Integer* values);
    void get_boolean(std::span<const fmi2ValueReference> vr, fmi2Boolean* values);
    void get_string(std::span<const fmi2ValueReference> vr, fmi2String* values);
    void set_real(std::span<const fmi2ValueReference> vr, const fmi2Real* values);
    void set_integer(std::span<const fmi2ValueReference> vr, const fmi2Integer* values);
    void set_boolean(std::span<const fmi2ValueReference> vr, const fmi2Boolean* values);
    void set_string(std::span<const fmi2ValueReference> vr, const fmi2String* values);

    Snapshot* get_state(Snapshot* reuse);
    void set_state(const Snapshot* state);
    void free_state(Snapshot* state);
    std::vector<fmi2Byte> serialize(const Snapshot* state) const;
    Snapshot* deserialize(std::span<const fmi2Byte> bytes);
    std::size_t serialized_size(const Snapshot* state) const;

    // Model Exchange
    void enter_event_mode();
    void new_discrete_states(fmi2EventInfo& info);
    void enter_continuous_time_mode();
    void completed_integrator_step(fmi2Boolean* enter_event_mode, fmi2Boolean* terminate);
    void set_time(double t);
    void set_continuous_states(std::span<const double> x);
    void get_derivatives(std::span<double> dx);
    void get_event_indicators(std::span<double> z);
    void get_continuous_states(std::span<double> x);
    void get_nominals(std::span<double> nominal);

    // Co-Simulation; returns fmi2Discard when the block asked to terminate during the step. The FMI 3.0
    // layer leaves events to its host (event mode): `event_pending` tells whether the step stopped at one.
    fmi2Status do_step(double current_time, double step_size,
                       CsSolver::HostEvents host_events = CsSolver::HostEvents::none, bool* event_pending = nullptr,
                       const std::function<bool(double)>& host_wants = {});
    // canInterpolateInputs: first derivatives of continuous Real inputs, applied over the next steps.
    void set_real_input_derivatives(std::span<const fmi2ValueReference> vr, const fmi2Integer* order,
                                    const fmi2Real* values);
    fmi2Status get_status(fmi2StatusKind kind, fmi2Status* value) const;
    fmi2Status get_real_status(fmi2StatusKind kind, fmi2Real* value) const;
    fmi2Status get_boolean_status(fmi2StatusKind kind, fmi2Boolean* value) const;

    const std::string& name() const { return name_; }
    double time() const { return runner_.time(); }

private:
    // What the getters and setters need of a variable on their fast path, by value reference, in a few bytes
    // (a Variable is several hundred: its names, unit and limits are for the checks' messages).
    struct Access {
        std::size_t offset = 0;
        ValueType type = ValueType::Real;
        bool continuous_input = false;  // a Real input of continuous variability: settable in every mode after
                                        // initialization (continuous-time, event, step-complete)
        double min = 0.0, max = 0.0;    // its limits, -inf and +inf when it has none
    };
    static std::vector<Access> access_of(std::span<const Variable> vars);
    // Continuous Real inputs with finite values inside their limits, after initialization: written without the
    // general checks (which they would pass). False, with nothing written, for anything else.
    bool set_continuous_inputs(std::span<const fmi2ValueReference> vr, const fmi2Real* values);

    const Variable& variable(fmi2ValueReference vr, ValueType type) const;
    const Variable& variable(std::span<const Variable> vars, fmi2ValueReference vr, ValueType type) const;
    void check_settable(const Variable& v) const;
    void check_count(std::size_t given, std::size_t expected, const char* what) const;
    template <class T, class Check, class Write>
    void set_values(std::span<const fmi2ValueReference> vr, const T* values, ValueType type, Check&& check,
                    Write&& write);
    void require_owned(const Snapshot* state) const;
    bool category_on(const char* category) const;
    CsSolver& cs_solver();

    std::string name_;
    std::string guid_;
    std::vector<std::byte> defaults_;  // the block's bytes as constructed: the parameters' defaults
    Kind kind_;
    fmi2CallbackLogger logger_;
    fmi2ComponentEnvironment environment_;
    std::vector<bool> category_enabled_;
    Mode mode_ = Mode::instantiated;
    ModelRunner runner_;
    std::vector<Access> access_;  // by value reference
    // Built at the exit of initialization, dropped by a reset, and built again on the first step after a
    // restore that brought a solverless instance (reset, or never initialized) back to step-complete.
    std::unique_ptr<CsSolver> cs_solver_;
    double start_time_ = 0.0;
    double tolerance_;
    double last_successful_time_ = 0.0;
    bool terminate_requested_ = false;
    std::set<const Snapshot*> snapshots_;  // states this instance handed out and has not freed
};

}  // namespace fmu
