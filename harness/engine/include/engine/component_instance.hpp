// What the master asks of one component, whatever runs it: an FMU loaded in this process
// (Fmi2Instance) or a block on external hardware reached over a link (HardwareBridge). System and
// Execution see only this interface, so swapping a block for hardware changes nothing else.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "engine/setting.hpp"
#include "fmi2/fmi2FunctionTypes.h"
#include "fmi_loader/model_description.hpp"

namespace cosim {

// How the link to a hardware block fared over a run (latency of answered frames in seconds).
struct LinkStatistics {
    long exchanges = 0;  // request frames sent
    long answered = 0;   // answered in time with a valid reply
    long misses = 0;     // no valid reply before the timeout
    long late = 0;       // replies that arrived after their frame had been given up
    long malformed = 0;  // received frames rejected by the codec
    double latency_min = 0, latency_median = 0, latency_p95 = 0, latency_max = 0;
};

class ComponentInstance {
public:
    virtual ~ComponentInstance() = default;

    virtual const std::string& name() const = 0;

    virtual void setup_experiment(double start_time, std::optional<double> stop_time,
                                  std::optional<double> tolerance) = 0;
    virtual void enter_initialization_mode() = 0;
    virtual void exit_initialization_mode() = 0;
    virtual void terminate() = 0;

    // The model description the component answers to (its FMU's, also for a bridged block).
    virtual const fmi_loader::ModelDescription& description() const = 0;

    // A setting (--set, an .ssd binding, a campaign draw) typed by the variable it names; any value as
    // text (a Boolean as 1 or 0). Written once here for every kind of component, over the typed access.
    void apply(const Setting& s);
    std::string get_as_text(const fmi_loader::ScalarVariable& v);

    // Typed access by value reference.
    virtual double get_real(fmi2ValueReference vr) = 0;
    virtual void set_real(fmi2ValueReference vr, double x) = 0;
    virtual fmi2Integer get_integer(fmi2ValueReference vr) = 0;
    virtual void set_integer(fmi2ValueReference vr, fmi2Integer x) = 0;
    virtual bool get_boolean(fmi2ValueReference vr) = 0;
    virtual void set_boolean(fmi2ValueReference vr, bool x) = 0;
    virtual std::string get_string(fmi2ValueReference vr) = 0;
    virtual void set_string(fmi2ValueReference vr, const std::string& x) = 0;

    // Several Reals in one call (the master's hot path); one value per reference.
    virtual void get_reals(std::span<const fmi2ValueReference> vr, std::span<double> x) {
        for (std::size_t i = 0; i < vr.size(); ++i) x[i] = get_real(vr[i]);
    }
    virtual void set_reals(std::span<const fmi2ValueReference> vr, std::span<const double> x) {
        for (std::size_t i = 0; i < vr.size(); ++i) set_real(vr[i], x[i]);
    }

    // A count that moves with every call that may change what the component's getters return (a set, a time or
    // states that differ from the last ones given, an event, a step): equal counts, equal values. A master may
    // keep what it read while the count stays. std::nullopt: the component cannot tell (read every time).
    virtual std::optional<std::uint64_t> values_version() const { return std::nullopt; }

    // Co-Simulation.
    virtual void do_step(double t, double h) = 0;
    // Whether the component asked to end the run at its last step (FMI 3.0 terminateSimulation).
    virtual bool terminate_requested() const { return false; }
    // First time derivatives of continuous Real inputs for the next step (canInterpolateInputs).
    virtual void set_real_input_derivatives(std::span<const fmi2ValueReference> vr, std::span<const double> dx) = 0;

    // Model Exchange.
    virtual void set_time(double t) = 0;
    virtual void set_states(const double* x, std::size_t n) = 0;
    virtual void get_states(double* x, std::size_t n) = 0;
    virtual void get_derivatives(double* dx, std::size_t n) = 0;
    virtual void get_nominals(double* nominal, std::size_t n) = 0;
    virtual void get_event_indicators(double* z, std::size_t n) = 0;
    virtual void enter_event_mode() = 0;
    virtual fmi2EventInfo new_discrete_states() = 0;
    virtual void enter_continuous_time_mode() = 0;
    // Returns true when the component asks for a step event.
    virtual bool completed_integrator_step(bool* terminate) = 0;

    // --realtime: a component that talks to the outside world waits with this until the wall clock
    // reaches a simulated time before it acts. Components that only compute ignore it.
    virtual void set_pacer(std::function<void(double t)>) {}
    // Statistics of an external link, for components that have one.
    virtual std::optional<LinkStatistics> link_statistics() const { return std::nullopt; }
};

}  // namespace cosim
