#include "execution.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <thread>

#include "cosim_error.hpp"
#include "fmu/cvode_integrator.hpp"
#include "fmu/indicator_bisection.hpp"

namespace cosim {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr int max_event_rounds = 100;

bool reached(double t, double event_time) {
    return t >= event_time - 1e-12 * std::max(1.0, std::abs(event_time));
}

// The wall-clock time at which `elapsed` seconds of simulated time are due (--realtime).
std::chrono::steady_clock::time_point wall_due(std::chrono::steady_clock::time_point wall_start, double elapsed) {
    return wall_start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(elapsed));
}

}  // namespace

struct Execution::Impl {
    System& system;
    const ExecutionOptions& options;
    std::vector<Observer*> observers;
    std::vector<Component*> me, cs;
    std::size_t n = 0, m = 0;
    std::vector<double> x;
    std::unique_ptr<fmu::CvodeIntegrator> cvode;
    bool restart = true;
    bool terminate = false;
    double t = 0.0;
    double last_sample = -infinity;
    RunStatistics stats;

    Impl(System& s, const ExecutionOptions& o, std::vector<Observer*> obs) : system(s), options(o), observers(std::move(obs)) {
        for (auto& c : system.components()) (c.interface == Interface::model_exchange ? me : cs).push_back(&c);
        for (auto* c : me) {
            n += c->state_count;
            m += c->indicator_count;
        }
        x.resize(n);
    }

    // Time and states into every Model Exchange component, then the values that flow between them.
    void set_continuous(double time, std::span<const double> states) {
        for (auto* c : me) {
            c->instance->set_time(time);
            if (c->state_count) c->instance->set_states(states.data() + c->state_offset, c->state_count);
        }
        system.propagate(true);
    }

    void rhs(double time, std::span<const double> states, std::span<double> dx) {
        set_continuous(time, states);
        for (auto* c : me) {
            if (!c->state_count) continue;
            c->instance->get_derivatives(dx.data() + c->state_offset, c->state_count);
            ++c->rhs_evaluations;
        }
    }

    void indicators(double time, std::span<const double> states, std::span<double> z) {
        set_continuous(time, states);
        for (auto* c : me)
            if (c->indicator_count) c->instance->get_event_indicators(z.data() + c->indicator_offset, c->indicator_count);
    }

    // fmi2NewDiscreteStates for every component, with values re-propagated, until no component
    // asks for another round and no propagated value changes.
    void event_iteration(bool with_cs_sources) {
        system.propagate(false, with_cs_sources);
        for (int round = 0; round < max_event_rounds; ++round) {
            bool needed = false;
            for (auto* c : me) {
                const fmi2EventInfo info = c->instance->new_discrete_states();
                needed = needed || info.newDiscreteStatesNeeded;
                terminate = terminate || info.terminateSimulation;
                c->next_time_event = info.nextEventTimeDefined ? info.nextEventTime : infinity;
            }
            const bool changed = system.propagate(false, with_cs_sources);
            if (!needed && !changed) return;
        }
        throw CosimError("the event iteration at t = " + std::to_string(t) + " did not settle after " +
                         std::to_string(max_event_rounds) + " rounds");
    }

    double next_time_event() const {
        double next = infinity;
        for (auto* c : me) next = std::min(next, c->next_time_event);
        return next;
    }

    void gather_states() {
        for (auto* c : me)
            if (c->state_count) c->instance->get_states(x.data() + c->state_offset, c->state_count);
    }

    void sample() {
        for (auto* o : observers) o->sample(t, system);
        last_sample = t;
    }

    // No continuous states but event indicators: locate a sign change by bisection on time.
    bool bisect(double t_stop) {
        const auto crossing = fmu::bisect_indicator_crossing(
            t, t_stop, m, [this](double time, std::span<double> z) { indicators(time, x, z); });
        t = crossing.value_or(t_stop);
        return crossing.has_value();
    }

    // Integrate the Model Exchange part to t_target or the first state event; true on a state event.
    bool integrate(double t_target) {
        if (n > 0) {
            if (restart) {
                cvode->restart(t, x);
                restart = false;
            }
            return cvode->advance(t_target, t, x) == fmu::CvodeIntegrator::Stop::root;
        }
        if (m > 0) return bisect(t_target);
        t = t_target;
        return false;
    }

    void communicate(double step) {
        system.propagate_into(Interface::co_simulation);
        for (auto* c : cs) {
            c->instance->do_step(t, step);
            ++c->events;  // counts steps for CS components
        }
        ++stats.communication_points;
    }

    RunStatistics run() {
        const double start = options.start_time, stop = options.stop_time;
        const double h_out = options.output_interval;
        const double h_comm = options.communication_step.value_or(h_out);
        if (!(stop > start) || !(h_out > 0.0) || !(h_comm > 0.0))
            throw CosimError("the stop time must exceed the start time, and the intervals be positive");
        const auto wall_start = std::chrono::steady_clock::now();
        if (options.realtime) {
            // Components that talk to hardware act at their instants' wall time, not only at output points.
            for (auto& c : system.components())
                c.instance->set_pacer([wall_start, start](double time) { std::this_thread::sleep_until(wall_due(wall_start, time - start)); });
        }

        system.initialize(start, stop);
        t = start;
        event_iteration(true);  // Model Exchange components leave initialization in event mode
        for (auto* c : me) c->instance->enter_continuous_time_mode();
        gather_states();
        if (n > 0) {
            std::vector<double> abstol(n);
            for (auto* c : me)
                if (c->state_count) c->instance->get_nominals(abstol.data() + c->state_offset, c->state_count);
            for (auto& a : abstol) a *= options.relative_tolerance;
            cvode = std::make_unique<fmu::CvodeIntegrator>(
                n, m, [this](double tt, std::span<const double> xx, std::span<double> dx) { rhs(tt, xx, dx); },
                [this](double tt, std::span<const double> xx, std::span<double> z) { indicators(tt, xx, z); },
                options.relative_tolerance, abstol);
        }
        sample();
        if (!cs.empty()) communicate(std::min(h_comm, stop - t));  // outputs at start + h_comm, applied then

        long k_out = 0, k_comm = 0;
        const double tiny = 1e-12 * std::max(1.0, std::abs(stop));
        while (!terminate && t < stop - tiny) {
            const double t_out = start + static_cast<double>(k_out + 1) * h_out;
            const double t_comm = cs.empty() ? infinity : start + static_cast<double>(k_comm + 1) * h_comm;
            const double t_target = std::min({t_out, t_comm, next_time_event(), stop});
            const bool state_event = integrate(t_target);
            set_continuous(t, x);
            bool step_event = false;
            for (auto* c : me) {
                bool stop_requested = false;
                step_event = c->instance->completed_integrator_step(&stop_requested) || step_event;
                terminate = terminate || stop_requested;
            }
            const bool time_event = reached(t, next_time_event());
            const bool comm = !cs.empty() && reached(t, t_comm);
            if (state_event || time_event || step_event || comm) {
                if (options.event_rows && (state_event || time_event || step_event)) sample();
                for (auto* c : me) {
                    c->instance->enter_event_mode();
                    ++c->events;
                }
                stats.state_events += state_event;
                stats.time_events += time_event;
                stats.step_events += step_event;
                event_iteration(comm);
                if (comm) {
                    ++k_comm;
                    communicate(std::min(h_comm, stop - t));
                }
                for (auto* c : me) c->instance->enter_continuous_time_mode();
                gather_states();
                restart = true;
                if (options.event_rows && (state_event || time_event || step_event)) sample();
            }
            if (reached(t, t_out) || t >= stop - tiny) {
                while (reached(t, start + static_cast<double>(k_out + 1) * h_out)) ++k_out;
                if (t != last_sample) sample();
                if (options.realtime) pace(wall_start, start);
                if (options.progress) options.progress((t - start) / (stop - start));
            }
        }
        stats.terminated_early = terminate && t < stop - tiny;
        for (auto& c : system.components()) c.instance->terminate();

        stats.simulated_time = t - start;
        stats.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
        if (cvode) {
            stats.integrator_steps = cvode->steps();
            stats.rhs_evaluations = cvode->rhs_evaluations();
        }
        for (const auto& c : system.components()) {
            ComponentStatistics cs_stats{c.name, c.rhs_evaluations, 0, 0, c.instance->link_statistics()};
            (c.interface == Interface::model_exchange ? cs_stats.events : cs_stats.steps) = c.events;
            stats.components.push_back(cs_stats);
        }
        return stats;
    }

    // Wait until the wall clock has caught up with simulated time; count the points already late.
    void pace(std::chrono::steady_clock::time_point wall_start, double start) {
        const auto due = wall_due(wall_start, t - start);
        if (std::chrono::steady_clock::now() > due) {
            ++stats.late_realtime_points;
            return;
        }
        std::this_thread::sleep_until(due);
    }
};

Execution::Execution(System& system, ExecutionOptions options) : system_(system), options_(std::move(options)) {}

RunStatistics Execution::run(std::vector<Observer*> observers) {
    Impl impl(system_, options_, std::move(observers));
    return impl.run();
}

}  // namespace cosim
