// Co-Simulation inside the FMU: advances a block over a communication step with SUNDIALS CVODE,
// stopping exactly at the block's time events and locating its state events with CVODE's root
// finding, running the event iteration at each, and restarting the integrator after every
// discontinuity. Plain C++.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "fmu/model_runner.hpp"
#include "integrator/cvode_integrator.hpp"

namespace fmu {

struct SolverStatistics {
    std::int64_t steps = 0;
    std::int64_t rhs_evaluations = 0;
    std::int64_t time_events = 0;
    std::int64_t state_events = 0;
    std::int64_t restarts = 0;
    std::int64_t block_spans = 0;  // spans between events the block advanced itself (no integrator)
};

class CsSolver {
public:
    CsSolver(ModelRunner& runner, double relative_tolerance);

    enum class Outcome { reached, terminated, event_pending };
    // Which events advance leaves to the host (FMI 3.0 Co-Simulation with event mode): none (FMI 2.0,
    // and 3.0 without event mode), those due at t_end, or also those inside the step (early return).
    // A left event stops the step at its time with the discrete update not run: event_pending.
    // `ask`: those at t_end, and each one inside the step for which `host_wants(t)` says so (FMI 3.0's
    // intermediate update, the host requesting an early return); the others are handled inside.
    enum class HostEvents { none, at_end, all, ask };
    // Integrate from the runner's current time to t_end, handling every event on the way and any
    // event due exactly at t_end that is not the host's. Throws fmu::Error when the integrator fails.
    Outcome advance(double t_end, HostEvents host_events = HostEvents::none,
                    const std::function<bool(double)>& host_wants = {});
    // States were changed from outside (FMU state restored, inputs changed): restart at next advance.
    void invalidate() { restart_needed_ = true; }

    SolverStatistics statistics() const;

private:
    bool integrate_to(double t_stop);           // true when a state event stopped it
    bool locate_without_states(double t_stop);  // no states: bisection on the indicators

    ModelRunner& runner_;
    double relative_tolerance_;
    std::unique_ptr<integrator::CvodeIntegrator> cvode_;
    std::vector<double> x_;
    bool restart_needed_ = true;
    SolverStatistics stats_;
};

}  // namespace fmu
