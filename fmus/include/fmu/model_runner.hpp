// Drives one block: its clock, lazy evaluation, continuous states, event indicators and event
// iteration. Shared by the Model Exchange entry points (the host integrates) and the Co-Simulation
// solver (we integrate), so both see the same equations in the same order. Plain C++, no FMI types.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "fmu/model.hpp"

namespace fmu {

class ModelRunner {
public:
    explicit ModelRunner(std::unique_ptr<Model> model);

    Model& model() { return *model_; }
    const Model& model() const { return *model_; }
    const TableBase& table() const { return model_->table(); }

    double time() const { return time_; }
    // Always marks the outputs stale: the block's own step between events (advance_between_events) writes its
    // states itself and calls this for each trial time, which may repeat.
    void set_time(double t);
    // The host's fmi2SetTime: the time the runner already has, bit for bit, changes nothing (a Model Exchange
    // host sets again the instant it just checked its indicators at); anything else is set_time(t).
    void set_time_from_host(double t);

    // Any change of time, states, inputs or parameters makes the outputs stale; they are
    // recomputed on the next read. In initialization mode a read first re-runs initialize().
    void mark_changed() { stale_ = derivatives_stale_ = true; }
    // A parameter changed: the block's configure() runs before its next equation.
    void parameters_changed() {
        configured_ = false;
        mark_changed();
    }
    // configure() now if a parameter changed since it last ran (so that its error surfaces here).
    void ensure_configured();

    // The one initialization path, used by the FMU, the board emulator and the tests' driver
    // (fmu/testing/block_driver.hpp), so that none of them can take a path the others do not:
    // enter_initialization(), then sets and reads (each read re-runs initialize()), then
    // exit_initialization(): validate(), configure(), initialize() and the equations with the final
    // values. A Co-Simulation host then settles the discrete state at the start time with
    // event_iteration(); a Model Exchange host does that in event mode.
    void enter_initialization() { set_initializing(true); }
    void exit_initialization();
    bool initializing() const { return initializing_; }
    // Back to the block's defaults, as instantiated (fmi2Reset).
    void reset(double start_time);

    void ensure_evaluated();
    // Derivatives and indicators current (evaluate_derivatives; outputs may still be stale).
    void ensure_derivatives();

    std::size_t state_count() const { return table().states().size(); }
    std::size_t indicator_count() const { return indicator_count_; }
    void get_states(std::span<double> x) const;
    // Marks the outputs stale only when a state differs, bit for bit, from the one the block holds.
    void set_states(std::span<const double> x);
    void get_derivatives(std::span<double> dx);
    void get_nominals(std::span<double> nominal) const;
    void get_indicators(std::span<double> z);

    // True when the block's next time event is due at the current time (within rounding). Both
    // configure the block first: its events may come from what configure() derives.
    bool time_event_due();
    double next_time_event() {
        ensure_configured();
        return model_->next_time_event();
    }
    // The block's own step between events toward t_stop (Model::advance_between_events), if it has one;
    // std::nullopt leaves time and states as they were.
    std::optional<SpanReached> advance_between_events(double t_stop, double relative_tolerance);
    // One round of discrete updates at the current time.
    EventUpdate update_discrete();
    // Rounds until the block needs no more; throws if it never settles. `states_changed` and
    // `terminate` are or-ed over the rounds.
    EventUpdate event_iteration();

    // Replace the whole block state with a copy (FMU state restore); time travels with it. Input
    // slopes are host-side knowledge, not block state: a restore drops them.
    void restore(const Model& saved, double time);

    // Co-Simulation inputs interpolated over a step (canInterpolateInputs): the Real input `variable` (an
    // index into the table) follows u(t) = u(t0) + slope * (t - t0) whenever the time is set, t0 being
    // the time the slope or the input's value was last set (setting the value keeps the slope, so a
    // host may set values and derivatives in either order). The host gives slopes for one step:
    // clear_input_slopes() after it.
    void set_input_slope(std::size_t variable, double slope);
    void input_value_set(std::size_t variable) {
        if (!input_slopes_.empty()) rebase_input_slope(variable);  // a Model Exchange host gives none
    }
    void clear_input_slopes() { input_slopes_.clear(); }

private:
    std::unique_ptr<Model> model_;
    double time_ = 0.0;
    bool stale_ = true;              // outputs
    bool derivatives_stale_ = true;  // derivatives and what the indicators use
    bool initializing_ = false;
    bool configured_ = false;  // configure() ran since the last parameter change, restore or reset
    std::size_t indicator_count_ = 0;

    struct InputSlope {
        std::size_t variable;
        double base_time, base_value, slope;
    };
    std::vector<InputSlope> input_slopes_;  // few (a block's Real inputs), searched linearly
    void apply_input_slopes();
    void rebase_input_slope(std::size_t variable);
    void set_initializing(bool on) {
        initializing_ = on;
        mark_changed();
    }
};

}  // namespace fmu
