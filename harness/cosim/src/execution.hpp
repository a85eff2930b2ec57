// Runs a loaded system from start to stop: every Model Exchange component integrated together by
// one CVODE instance (inputs propagated in dependency order at every right-hand side, all event
// indicators as root functions, time events from every component, step events, and the event
// iteration before each restart), Co-Simulation components stepped at communication points, and
// observers called at output points. Times are counted in steps from the start, so they never drift.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "observer.hpp"
#include "system.hpp"

namespace cosim {

struct ExecutionOptions {
    double start_time = 0.0;
    double stop_time = 1.0;
    double output_interval = 0.01;
    std::optional<double> communication_step;  // Co-Simulation step; default: the output interval
    double relative_tolerance = 1e-6;
    bool realtime = false;   // pace simulated time to the wall clock
    bool event_rows = false; // also sample just before and just after each event
    std::function<void(double fraction)> progress;  // called now and then with 0..1
};

struct ComponentStatistics {
    std::string name;
    long rhs_evaluations = 0;
    long events = 0;
    long steps = 0;  // Co-Simulation steps
    std::optional<LinkStatistics> link;  // hardware-bridged components
};

struct RunStatistics {
    double simulated_time = 0.0;
    double wall_time = 0.0;
    long integrator_steps = 0;
    long rhs_evaluations = 0;
    long time_events = 0, state_events = 0, step_events = 0, communication_points = 0;
    long late_realtime_points = 0;  // output points the wall clock had already passed (--realtime)
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
