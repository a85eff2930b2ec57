// What the FMI runtime needs from a block, with no FMI types: its description, its variables as bytes
// located by the table, and its equations. Blocks do not implement this directly; they derive from
// fmu::Block (block.hpp), which implements the bookkeeping from the variable table.
#pragma once

#include <cstddef>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "fmu/table.hpp"
#include "fmu/version.hpp"
#include "time_rule/time_rule.hpp"

namespace fmu {

struct DefaultExperiment {
    double start_time = 0.0;
    double stop_time = 10.0;
    double tolerance = 1e-6;
    double step_size = 1e-3;  // the communication / output interval a host should use by default
};

// Block-level facts that go into the model description and the generated documentation.
struct ModelInfo {
    std::string model_identifier;  // folder, CMake target, .so and .fmu name: "magnetometer"
    std::string model_name;
    std::string description;         // one line, for the model description
    std::string documentation_html;  // the block's page in documentation/index.html (body fragment)
    std::string author = "pv_attitude_fmi contributors";
    std::string version = toolkit_version;  // a block of another project sets its own
    std::string license = "MIT";
    DefaultExperiment default_experiment;
};

// What an event update tells the runtime.
struct EventUpdate {
    bool again = false;           // another round of discrete updates is needed at this instant
    bool states_changed = false;  // continuous states were re-initialized (integrator must restart)
    bool terminate = false;       // the block asks the host to stop the simulation
};

inline constexpr double no_time_event = std::numeric_limits<double>::infinity();

// What a block's own step between events reports (Model::advance_between_events).
struct SpanReached {
    double time = 0.0;         // where the block stopped: t_stop, or the zero of an event indicator
    bool state_event = false;  // it stopped at an indicator's zero (the event iteration runs there)
};

// True when time t has reached event_time, allowing for the rounding of a host that computed t as a
// sum of steps. Blocks use it in event_update; the runtime uses it to decide that a time event is due.
// The rule is time_rule::reached (fmus/time_rule), the one the master and the blocks' cores use too.
using time_rule::reached;

class Model {
public:
    virtual ~Model() = default;

    virtual const ModelInfo& info() const = 0;
    virtual const TableBase& table() const = 0;
    virtual std::unique_ptr<Model> clone() const = 0;

    // The whole block state as bytes (a trivially copyable struct): get/set through the table's
    // offsets, FMU state save/restore and serialization are copies of these bytes.
    virtual std::span<std::byte> bytes() = 0;
    virtual std::span<const std::byte> bytes() const = 0;
    virtual void reset_to_defaults() = 0;

    // Equations. Called by the runtime only, in this contract:
    // - configure(): rebuild what the block derives from its parameters and keeps outside its data
    //   (a fitted model, a table, a workspace). The runtime calls it before the next equation after a
    //   parameter was set, a state restored (fmi2SetFMUstate) or the instance reset, and at exit of
    //   initialization after validate(); nothing else may rebuild or cache on parameters. Throw
    //   fmu::Error for parameters it cannot use.
    // - initialize(t): from parameters and start values, set the discrete state (first time events,
    //   switch positions). Called whenever a value is read in initialization mode and at its exit,
    //   so it must depend only on parameters, inputs and start values (calling it twice = once).
    // - evaluate(t): outputs, derivative fields and other locals from time, states, inputs,
    //   parameters and the discrete state. Must not change the discrete state.
    // - event_indicators(t, z): the block's zero-crossing functions (after evaluate or
    //   evaluate_derivatives: they may use only what the latter computes).
    // - event_update(t, time_event_due): the discrete changes at an event instant.
    // - next_time_event(): absolute time of the next time event, or no_time_event.
    // - validate(): cross-parameter checks at exit of initialization; throw fmu::Error with a
    //   message a user understands.
    virtual void configure() {}
    virtual void initialize(double t) = 0;
    virtual void evaluate(double t) = 0;
    // Only what derivatives and event indicators need, when a solver asks for nothing else (no
    // output is read between two of its calls). A block whose outputs cost more than its
    // derivatives overrides it; it must set the derivative fields exactly as evaluate() does.
    virtual void evaluate_derivatives(double t) { evaluate(t); }
    virtual std::size_t event_indicator_count() const = 0;
    virtual void event_indicators(double t, std::span<double> z) = 0;
    virtual EventUpdate event_update(double t, bool time_event_due) = 0;
    virtual double next_time_event() const = 0;
    virtual void validate() const = 0;
    // - check_state(): after a state came in as bytes (fmi2DeSerializeFMUstate), the invariants of
    //   the fields the table does not cover (finite numbers, bool bytes, indices in range, a live
    //   generator); throw fmu::Error. The table's own variables are checked by the runtime.
    virtual void check_state() const {}
    // - advance_between_events(t, t_stop, rtol, move_to): optional. A block whose states between two events
    //   follow a closed form (a linear circuit, say) advances them itself in Co-Simulation instead of the
    //   solver's integrator. From time t and the states in its data, toward t_stop (no time event of the
    //   block lies before t_stop): it sets the states at the time it reached and returns that time, t_stop
    //   or the first zero of one of its event indicators (with state_event set). `move_to(t)` moves the
    //   runtime's clock (and inputs the host interpolates) to t, so that the block's inputs are those of t;
    //   it ends at the time returned. Local error per step: at most rtol × 1e-3 of each state's nominal.
    //   std::nullopt: the block leaves the span to the integrator (its states untouched).
    virtual std::optional<SpanReached> advance_between_events(double /*t*/, double /*t_stop*/, double /*rtol*/,
                                                              const std::function<void(double)>& /*move_to*/) {
        return std::nullopt;
    }
};

// Every block defines this once (FMU_BLOCK in block.hpp); the runtime and the tools call it.
std::unique_ptr<Model> make_model();

}  // namespace fmu
