// A component whose block runs on external hardware (or its emulator). It keeps the block's
// modelDescription (ports, units and wiring as with the FMU) and acts as a Model Exchange component
// without states: at each sample instant t0 + k * sample_period it sends one request frame with its
// current inputs and applies the board's reply at that same instant. Between samples its outputs
// hold, as the sampled block's do. Wire format and policies: protocol/README.md.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "engine/component_instance.hpp"
#include "engine/system_description.hpp"
#include "protocol/link.hpp"

namespace cosim {

// The most sample periods the master counts from the start, as the blocks count theirs
// (fmu::max_instant_index): beyond it consecutive instants are closer than the 1e-12 relative tolerance
// of an instant, and a period that small would make the master count samples for ever.
inline constexpr double max_sample_index = 1e11;

class HardwareBridge final : public ComponentInstance {
public:
    HardwareBridge(const fmi_loader::ModelDescription& description, std::string name, BridgeDescription settings);
    ~HardwareBridge() override;

    const std::string& name() const override { return name_; }
    const fmi_loader::ModelDescription& description() const override { return description_; }

    void setup_experiment(double start_time, std::optional<double> stop_time, std::optional<double> tolerance) override;
    void enter_initialization_mode() override {}
    void exit_initialization_mode() override;
    void terminate() override;

    double get_real(fmi2ValueReference vr) override;
    void set_real(fmi2ValueReference vr, double x) override;
    fmi2Integer get_integer(fmi2ValueReference vr) override;
    void set_integer(fmi2ValueReference vr, fmi2Integer x) override;
    bool get_boolean(fmi2ValueReference vr) override;
    void set_boolean(fmi2ValueReference vr, bool x) override;
    std::string get_string(fmi2ValueReference vr) override;
    void set_string(fmi2ValueReference vr, const std::string& x) override;

    void do_step(double t, double h) override;
    void set_real_input_derivatives(std::span<const fmi2ValueReference> vr, std::span<const double> dx) override;

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

    void set_pacer(std::function<void(double t)> pacer) override { pacer_ = std::move(pacer); }
    std::optional<LinkStatistics> link_statistics() const override;

private:
    enum class Kind { real, integer, boolean, string };
    std::size_t slot(Kind kind, fmi2ValueReference vr) const;
    // The slot of a value set from this side: refused, naming the variable, unless the board receives it
    // (an input or a parameter; a String never crosses the link, an output or a local is never sent).
    std::size_t settable(Kind kind, fmi2ValueReference vr) const;
    double next_sample_time() const { return start_time_ + static_cast<double>(next_sample_) * period_; }
    void exchange();
    // The first sample instant the current time has not reached: bounded steps, never a count of
    // every instant skipped; CosimError past max_sample_index.
    void advance_sample_count();
    // One frame from the board before the deadline, or none; waits in slices so that a signal
    // (SIGINT, SIGTERM, SIGHUP) ends the wait within wait_slice, throwing Interrupted.
    std::optional<std::vector<std::uint8_t>> receive(bridge::Clock::time_point deadline);
    // Sends the block's parameter values (configure frames) and waits for the board to take each; throws
    // CosimError when it does not within the bridge's timeout_ms, or has other parameters.
    void configure_board();

    const fmi_loader::ModelDescription& description_;
    std::string name_;
    BridgeDescription settings_;
    std::map<std::pair<Kind, fmi2ValueReference>, std::size_t> slots_;  // -> index into values_
    std::vector<double> values_;           // every non-String variable, as the wire carries it (f64)
    std::vector<std::size_t> parameters_;  // indices into values_ of the parameters, value-reference order
    std::vector<std::string> strings_;     // String variables (stay on this side of the link)
    std::map<std::pair<Kind, fmi2ValueReference>, const fmi_loader::ScalarVariable*> variables_;  // for messages
    std::vector<std::size_t> inputs_, outputs_;  // value-reference order
    std::size_t period_slot_ = 0;
    double start_time_ = 0.0, time_ = 0.0, period_ = 0.0;
    std::optional<double> stop_time_;
    long next_sample_ = 0;
    std::unique_ptr<bridge::Link> link_;
    std::uint32_t sequence_ = 0;
    int consecutive_misses_ = 0;
    std::string last_error_;
    LinkStatistics stats_;
    std::vector<double> latencies_;
    std::function<void(double)> pacer_;
};

}  // namespace cosim
