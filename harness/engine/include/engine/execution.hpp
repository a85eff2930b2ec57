// Runs a loaded system from start to stop: every Model Exchange component integrated together by
// one CVODE instance, Co-Simulation components stepped at their own communication points, observers
// called at output points. Times are counted in steps from the start, so they never drift.
//
// What makes it fast (and what --reference turns off, to compare against):
// - Only the components with something to do enter event mode: a time, state or step event of
//   their own, or an input that changed at the instant and matters (a discrete input, or any input
//   of a component with states or event indicators). The others keep integrating.
// - CVODE is restarted only when something it integrates jumped: a component said its states
//   changed, or the derivatives or event indicators differ after the event from before it. Samplers
//   (the on-board computer) and pulses that flip a sensor's output but not its dynamics cost no restart.
// - Only output points and the time events of components with states or indicators stop the
//   integrator exactly; the other instants (samples of stateless components, communication points)
//   take CVODE's interpolated solution and let it go on with its step.
// - Between events, inputs are copied only into the components whose derivatives or indicators can
//   see them (the "continuous consumers"), in batches, with no allocation.
// (A Jacobian built component by component, each block from that component's own derivatives, was
// tried: with restarts this rare it saved nothing, and its missing coupling blocks made CVODE's Newton
// iteration fail at a kink of the averaged plant's duty in one orbit run. CVODE builds its own.)
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "engine/observer.hpp"
#include "engine/system.hpp"

namespace cosim {

struct ExecutionOptions {
    double start_time = 0.0;
    double stop_time = 1.0;
    double output_interval = 0.01;
    double relative_tolerance = 1e-6;
    std::optional<double> max_step;  // the longest step of the Model Exchange integrator (default: the .ssd's)
    bool realtime = false;           // pace simulated time to the wall clock
    double realtime_tolerance =
        1e-3;                 // s: how far behind its wall time an output point may be before it counts as late
    bool event_rows = false;  // also sample just before and just after each event
    // Today's reference execution (before the speed work): every Model Exchange component goes
    // through every event, CVODE restarts after each, and every output point is a stop time.
    bool reference = false;
    std::function<void(double fraction)> progress;  // called now and then with 0..1
};

struct ComponentStatistics {
    std::string name;
    long rhs_evaluations = 0;
    long events = 0;                     // Model Exchange: times it went through event mode
    long steps = 0;                      // Co-Simulation steps
    std::optional<LinkStatistics> link;  // hardware-bridged components
};

struct RunStatistics {
    double simulated_time = 0.0;
    double wall_time = 0.0;
    long integrator_steps = 0;
    long rhs_evaluations = 0;
    long restarts = 0;  // CVODE restarts (after initialization and after events that changed something continuous)
    long failure_restarts = 0;  // CVODE restarted where its steps failed repeatedly (CvodeIntegrator::advance)
    long time_events = 0, state_events = 0, step_events = 0, communication_points = 0;
    long late_realtime_points = 0;  // output points reached more than the tolerance after their wall time (--realtime)
    double realtime_max_behind = 0.0;  // s: the most any output point was behind its wall time (--realtime)
    double realtime_tolerance = 0.0;   // s: the lateness allowed (ExecutionOptions)
    bool terminated_early = false;
    std::vector<ComponentStatistics> components;
};

class Execution {
public:
    Execution(System& system, ExecutionOptions options);
    RunStatistics run(std::vector<Observer*> observers);

private:
    struct Impl;
    System& system_;
    ExecutionOptions options_;
};

}  // namespace cosim
