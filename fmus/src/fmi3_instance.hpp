// One FMI 3.0 instance: the FMI 3.0 mode machine, value access by FMI 3.0 value reference (whole
// arrays, the 3.0 types), Co-Simulation's event mode and early return, over the FMI 2.0 instance
// (instance.hpp), which keeps the block, the equations, the per-variable set rules, the FMU states and
// the Co-Simulation solver, so that both archives of a block run the same code. The C entry points
// (fmi3_api.cpp) only check the handle and call these through one guard.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "fmi3/fmi3FunctionTypes.h"
#include "fmi3_call_rules.hpp"
#include "fmu/fmi3_view.hpp"
#include "instance.hpp"

namespace fmu::fmi3 {

struct Options {
    bool event_mode_used = false;       // Co-Simulation: the host handles events in Event Mode
    bool early_return_allowed = false;  // Co-Simulation: a step may end early at an event
    // Co-Simulation: called at each event inside a step (with event mode and early return allowed);
    // the step ends there only if the host requests it. Null: the step ends at every event.
    fmi3IntermediateUpdateCallback intermediate_update = nullptr;
};

class Instance3 {
public:
    Instance3(std::string name, Kind kind, Options options, fmi3InstanceEnvironment environment,
              fmi3LogMessageCallback logger, bool logging_on, std::unique_ptr<Model> model, std::string token);

    void log(fmi3Status status, const char* category, const std::string& message) const;
    void log_call(std::string_view function) const { inner_.log_call(function); }
    bool logs_calls() const { return inner_.logs_calls(); }
    void set_debug_logging(bool on, std::span<const fmi3String> categories) {
        inner_.set_debug_logging(on, categories);
    }

    // Throws fmu::Error naming the mode when `call` is not allowed now.
    void require(Call call) const;
    void require_kind(Kind kind, Call call) const;
    void enter_error_mode();
    // Inside the intermediate-update callback of a step in progress (fmi3FreeInstance is refused there).
    bool in_intermediate_update() const { return in_callback_; }

    void enter_initialization_mode(bool tolerance_defined, double tolerance, double start_time, bool stop_defined,
                                   double stop_time);
    void exit_initialization_mode();
    void enter_event_mode();
    void terminate();
    void reset();

    void get_float64(std::span<const fmi3ValueReference> vr, std::span<fmi3Float64> values);
    void get_int32(std::span<const fmi3ValueReference> vr, std::span<fmi3Int32> values);
    void get_int64(std::span<const fmi3ValueReference> vr, std::span<fmi3Int64> values);
    void get_boolean(std::span<const fmi3ValueReference> vr, std::span<fmi3Boolean> values);
    void get_string(std::span<const fmi3ValueReference> vr, std::span<fmi3String> values);
    void set_float64(std::span<const fmi3ValueReference> vr, std::span<const fmi3Float64> values);
    void set_int32(std::span<const fmi3ValueReference> vr, std::span<const fmi3Int32> values);
    void set_int64(std::span<const fmi3ValueReference> vr, std::span<const fmi3Int64> values);
    void set_boolean(std::span<const fmi3ValueReference> vr, std::span<const fmi3Boolean> values);
    void set_string(std::span<const fmi3ValueReference> vr, std::span<const fmi3String> values);
    // A getter or setter of a type no variable here has (Float32, Int8, ..., Binary): names the type
    // the first value reference has.
    [[noreturn]] void refuse_type(const char* function, std::span<const fmi3ValueReference> vr) const;

    Snapshot* get_state(Snapshot* reuse);
    void set_state(const Snapshot* state);
    void free_state(Snapshot* state);
    std::vector<char> serialize(const Snapshot* state) const { return inner_.serialize(state); }
    std::size_t serialized_size(const Snapshot* state) const { return inner_.serialized_size(state); }
    Snapshot* deserialize(std::span<const fmi3Byte> bytes);

    // Model Exchange, and Co-Simulation's Event Mode
    struct DiscreteUpdate {
        bool again = false, terminate = false, states_changed = false, next_defined = false;
        double next_time = 0.0;
    };
    DiscreteUpdate update_discrete_states();
    void enter_continuous_time_mode();
    void enter_step_mode();
    void set_time(double t) { inner_.set_time(t); }
    Instance& inner() { return inner_; }
    std::size_t state_count() const;
    std::size_t event_indicator_count() const { return view_.event_indicator_count(); }

    struct StepResult {
        fmi3Status status = fmi3OK;
        bool event_handling_needed = false, terminate = false, early_return = false;
        double last_successful_time = 0.0;
    };
    StepResult do_step(double current_time, double step_size);

private:
    // The table's value references of the elements of `vr`'s variables, checked to be of `type`
    // (all first: a refused reference leaves nothing half-done), and their total count.
    std::span<const fmi3ValueReference> expand(std::span<const fmi3ValueReference> vr, ValueType type,
                                               std::size_t n_values, bool for_set);
    const Fmi3Variable& variable(fmi3ValueReference vr) const;

    std::string name_;
    Kind kind_;
    Options options_;
    fmi3InstanceEnvironment environment_;
    fmi3LogMessageCallback logger_;
    const TableBase& table_;  // the block's one table (static), taken before the model moves into inner_
    Fmi3View view_;
    Instance inner_;
    Mode mode_ = Mode::instantiated;
    bool in_callback_ = false;  // the intermediate-update callback is running (whatever mode a refusal left)
    std::map<const Snapshot*, Mode> snapshot_modes_;  // the FMI 3.0 mode each state was taken in
    std::vector<fmi3ValueReference> scratch_;         // expand()'s result, reused across calls
};

}  // namespace fmu::fmi3
