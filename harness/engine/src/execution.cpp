#include "engine/execution.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <thread>

#include "engine/cosim_error.hpp"
#include "engine/interrupt.hpp"
#include "integrator/cvode_integrator.hpp"
#include "integrator/indicator_bisection.hpp"
#include "same_bits.hpp"
#include "time_rule/time_rule.hpp"

namespace cosim {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr int max_event_rounds = 100;

// The wall-clock time at which `elapsed` seconds of simulated time are due (--realtime).
std::chrono::steady_clock::time_point wall_due(std::chrono::steady_clock::time_point wall_start, double elapsed) {
    return wall_start +
           std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(elapsed));
}

}  // namespace

struct Execution::Impl {
    System& system;
    const ExecutionOptions& options;
    std::vector<Observer*> observers;
    std::vector<std::size_t> me, cs, consumers;  // component indices
    std::size_t n = 0, m = 0;
    std::vector<double> x;
    std::unique_ptr<integrator::CvodeIntegrator> cvode;
    bool restart = true;
    bool terminate = false;
    double t = 0.0;
    double last_sample = -infinity;
    RunStatistics stats;

    struct Stepping {  // a Co-Simulation component's communication grid
        double step = 0.0, last = 0.0;
        long k = 0;
    };
    std::vector<Stepping> stepping;  // per component (used for Co-Simulation ones)
    std::vector<char> in_event;      // per component: in event mode at this instant

    Impl(System& s, const ExecutionOptions& o, std::vector<Observer*> obs)
        : system(s), options(o), observers(std::move(obs)) {
        auto& comps = system.components();
        for (std::size_t i = 0; i < comps.size(); ++i) {
            auto& c = comps[i];
            if (c.interface == Interface::model_exchange) {
                me.push_back(i);
                n += c.state_count;
                m += c.indicator_count;
                if (c.continuous_consumer || options.reference) consumers.push_back(i);
            } else {
                cs.push_back(i);
            }
        }
        x.resize(n);
        stepping.resize(comps.size());
        in_event.assign(comps.size(), 0);
    }

    Component& comp(std::size_t i) { return system.components()[i]; }

    // Time and states into the given Model Exchange components, then the values they see.
    void set_continuous(const std::vector<std::size_t>& which, Pass pass, double time, std::span<const double> states) {
        for (auto i : which) {
            auto& c = comp(i);
            c.instance->set_time(time);
            if (c.state_count) c.instance->set_states(states.data() + c.state_offset, c.state_count);
        }
        system.propagate(pass);
    }
    // Between events: only the components whose derivatives or indicators are asked for.
    void set_integrating(double time, std::span<const double> states) {
        set_continuous(consumers, Pass::integrating, time, states);
    }
    // At an instant the master stops at: every component, every continuous input, so that any output can be read.
    void set_everywhere(double time, std::span<const double> states) {
        set_continuous(me, Pass::continuous, time, states);
    }

    void rhs(double time, std::span<const double> states, std::span<double> dx) {
        set_integrating(time, states);
        for (auto i : me) {
            auto& c = comp(i);
            if (!c.state_count) continue;
            c.instance->get_derivatives(dx.data() + c.state_offset, c.state_count);
            ++c.rhs_evaluations;
        }
    }

    void indicators(double time, std::span<const double> states, std::span<double> z) {
        set_integrating(time, states);
        for (auto i : me) {
            auto& c = comp(i);
            if (c.indicator_count) c.instance->get_event_indicators(z.data() + c.indicator_offset, c.indicator_count);
        }
    }

    // A component joins the instant's event mode when it has an event of its own or one of its
    // inputs changed in a way it must see: a discrete input, or any input of a component whose
    // derivatives or indicators use it.
    bool must_join(std::size_t i) {
        const auto& c = comp(i);
        if (c.interface != Interface::model_exchange || in_event[i]) return false;
        if (options.reference) return true;
        return system.discrete_input_changed(i) || (system.input_changed(i) && c.has_dynamics());
    }

    void join(std::size_t i) {
        comp(i).instance->enter_event_mode();
        ++comp(i).events;
        in_event[i] = 1;
    }

    // fmi2NewDiscreteStates for the components in event mode, with values re-propagated and the
    // components whose inputs changed drawn in, until nobody asks for another round. Returns true
    // when a component said its continuous states changed (CVODE must restart).
    bool event_iteration() {
        bool continuous_change = false;
        const auto join_for_discrete_input = [this](std::size_t i) {
            if (!in_event[i]) join(i);
        };
        system.clear_changes();
        system.propagate(Pass::event, join_for_discrete_input);
        for (auto i : me)
            if (must_join(i)) join(i);
        for (int round = 0; round < max_event_rounds; ++round) {
            bool again = false;
            for (auto i : me) {
                if (!in_event[i]) continue;
                auto& c = comp(i);
                const fmi2EventInfo info = c.instance->new_discrete_states();
                again = again || info.newDiscreteStatesNeeded;
                terminate = terminate || info.terminateSimulation;
                continuous_change = continuous_change || info.valuesOfContinuousStatesChanged;
                c.next_time_event = info.nextEventTimeDefined ? info.nextEventTime : infinity;
            }
            system.clear_changes();
            system.propagate(Pass::event, join_for_discrete_input);
            for (auto i : me) {
                if (in_event[i] && system.input_changed(i)) again = true;  // it must see its new inputs
                if (must_join(i)) {
                    join(i);
                    again = true;
                }
            }
            if (!again) {
                for (auto i : me) {
                    if (!in_event[i]) continue;
                    comp(i).instance->enter_continuous_time_mode();
                    in_event[i] = 0;
                }
                return continuous_change;
            }
        }
        throw CosimError("the event iteration at t = " + std::to_string(t) + " did not settle after " +
                         std::to_string(max_event_rounds) + " rounds");
    }

    // What CVODE integrates, at the current instant: the derivatives and indicators of every Model
    // Exchange component. An event that leaves both unchanged, bit for bit, changed nothing the
    // integrator sees here (a sampler's output that only feeds discrete inputs, a set/reset pulse
    // that flips a sensor's output but not its filter): CVODE goes on with its step size and order.
    // One that changes them restarts it: a switch of the PWM, a new input to a state's derivative.
    std::vector<double> seen_before, seen_after;
    void what_the_integrator_sees(std::vector<double>& out) {
        out.resize(n + m);
        for (auto i : me) {
            auto& c = comp(i);
            if (c.state_count) c.instance->get_derivatives(out.data() + c.state_offset, c.state_count);
            if (c.indicator_count)
                c.instance->get_event_indicators(out.data() + n + c.indicator_offset, c.indicator_count);
        }
    }
    bool integrator_sees_a_change() {
        what_the_integrator_sees(seen_after);
        // A system of components without states or indicators has empty vectors: nothing to see.
        return !seen_before.empty() && !same_bits(seen_before, seen_after);
    }

    // Hard instants stop CVODE exactly: time events of components whose right-hand side or
    // indicators jump there, and output points. Soft ones (samples of components without states,
    // communication points) are read off its interpolating polynomial, which is accurate for the
    // smooth signals samplers read but not for a stiff state between two long steps (the averaged
    // plant's bus, whose loop settles in microseconds, through a kink of its duty over a 30 s step):
    // what a user sees in the results comes from steps.
    double next_hard_time(double t_out) {
        double next = std::min(options.stop_time, t_out);
        for (auto i : me)
            if (comp(i).has_dynamics()) next = std::min(next, comp(i).next_time_event);
        return next;
    }

    double next_soft_time(double t_out) {
        double next = t_out;
        for (auto i : me)
            if (!comp(i).has_dynamics()) next = std::min(next, comp(i).next_time_event);
        for (auto i : cs) next = std::min(next, next_communication(i));
        return next;
    }

    double next_communication(std::size_t i) const {
        const auto& s = stepping[i];
        return std::min(options.start_time + static_cast<double>(s.k + 1) * s.step, options.stop_time);
    }

    void gather_states() {
        for (auto i : me) {
            auto& c = comp(i);
            if (c.state_count) c.instance->get_states(x.data() + c.state_offset, c.state_count);
        }
    }

    void sample() {
        for (auto* o : observers) o->sample(t, system);
        last_sample = t;
    }

    // No continuous states but event indicators: locate a sign change by bisection on time.
    bool bisect(double t_stop) {
        const auto crossing = integrator::bisect_indicator_crossing(
            t, t_stop, m, [this](double time, std::span<double> z) { indicators(time, x, z); });
        t = crossing.value_or(t_stop);
        return crossing.has_value();
    }

    // Integrate the Model Exchange part to t_out (interpolated) without passing t_hard, or to the
    // first state event; true on a state event.
    bool integrate(double t_out, double t_hard) {
        if (n > 0) {
            if (restart) {
                cvode->restart(t, x);
                restart = false;
                ++stats.restarts;
            }
            return cvode->advance(t_out, t_hard, t, x) == integrator::CvodeIntegrator::Stop::root;
        }
        if (m > 0) return bisect(std::min(t_out, t_hard));
        t = std::min(t_out, t_hard);
        return false;
    }

    // The components whose indicators crossed at the last state event.
    void mark_state_event_components() {
        if (n == 0) {  // bisection does not say which: every component with indicators looks
            for (auto i : me)
                if (comp(i).indicator_count && !in_event[i]) join(i);
            return;
        }
        const auto& info = cvode->root_info();
        for (auto i : me) {
            const auto& c = comp(i);
            for (std::size_t k = 0; k < c.indicator_count; ++k)
                if (info[c.indicator_offset + k] != 0 && !in_event[i]) join(i);
        }
    }

    void start_integrator() {
        if (n == 0) return;
        std::vector<double> abstol(n, 1.0);  // the states' nominal magnitudes times the relative tolerance
        for (auto i : me) {
            auto& c = comp(i);
            if (c.state_count) c.instance->get_nominals(abstol.data() + c.state_offset, c.state_count);
        }
        for (auto& a : abstol) a *= options.relative_tolerance;
        cvode = std::make_unique<integrator::CvodeIntegrator>(
            n, m, [this](double tt, std::span<const double> xx, std::span<double> dx) { rhs(tt, xx, dx); },
            [this](double tt, std::span<const double> xx, std::span<double> z) { indicators(tt, xx, z); },
            options.relative_tolerance, abstol);
        // A system's own limit (its .ssd) unless the run gives one.
        if (const auto h = options.max_step ? options.max_step : system.description().max_step) cvode->set_max_step(*h);
    }

    RunStatistics run() {
        const double start = options.start_time, stop = options.stop_time;
        const double h_out = options.output_interval;
        if (!(stop > start) || !(h_out > 0.0))
            throw CosimError("the stop time must exceed the start time, and the output interval be positive");
        for (auto i : cs) {
            stepping[i].step =
                comp(i).communication_step.value_or(h_out);  // without a step of its own: the output interval
            stepping[i].last = start;
            if (!(stepping[i].step > 0.0)) throw CosimError(comp(i).name + ": the communication step must be positive");
        }
        // The wall clock of --realtime starts when the run does, after initialization: a board's answer to
        // its configuration (QEMU booting the firmware takes most of a second) is not simulated time.
        const auto run_started = std::chrono::steady_clock::now();
        const auto wall_origin = std::make_shared<std::chrono::steady_clock::time_point>(run_started);
        stats.realtime_tolerance = options.realtime_tolerance;
        if (options.realtime) {
            // Components that talk to hardware act at their instants' wall time, not only at output points.
            for (auto& c : system.components())
                c.instance->set_pacer([wall_origin, start](double time) {
                    sleep_until_or_interrupted(wall_due(*wall_origin, time - start));
                });
        }

        system.initialize(start, stop);
        *wall_origin = std::chrono::steady_clock::now();
        const auto wall_start = *wall_origin;
        t = start;
        // Model Exchange components leave initialization in event mode: all of them settle here.
        for (auto i : me) in_event[i] = 1;
        event_iteration();
        gather_states();
        start_integrator();
        sample();

        long k_out = 0;
        const double tiny = time_rule::resolution(stop);
        while (!terminate && t < stop - tiny) {
            throw_if_interrupted();  // between integrator steps and events, not only at output points
            for (auto* o : observers) o->between_steps();
            const double t_out = std::min(start + static_cast<double>(k_out + 1) * h_out, stop);
            // The reference execution stops at every instant.
            const double t_soft = next_soft_time(t_out);
            const double t_hard = options.reference ? std::min(next_hard_time(t_out), t_soft) : next_hard_time(t_out);
            const bool state_event = integrate(std::min(t_soft, t_hard), t_hard);
            set_everywhere(t, x);

            bool step_event = false;
            for (auto i : me) {
                auto& c = comp(i);
                if (!c.completed_step_needed) continue;
                bool stop_requested = false;
                if (c.instance->completed_integrator_step(&stop_requested) && !in_event[i]) {
                    step_event = true;
                    join(i);
                }
                terminate = terminate || stop_requested;
            }
            bool time_event = false;
            for (auto i : me) {
                if (!time_rule::reached(t, comp(i).next_time_event)) continue;
                time_event = true;
                if (!in_event[i]) join(i);
            }
            if (state_event) mark_state_event_components();
            const bool any_event = state_event || time_event || step_event;

            if (options.event_rows && any_event && t != last_sample) sample();  // just before the event
            bool communicated = false;
            for (auto i : cs) {
                const double t_comm = next_communication(i);
                if (!time_rule::reached(t, t_comm)) continue;
                auto& s = stepping[i];
                system.step_co_simulation(i, t_comm, t_comm - s.last);
                terminate = terminate || comp(i).instance->terminate_requested();
                s.last = t_comm;
                ++s.k;
                ++comp(i).events;
                ++stats.communication_points;
                communicated = true;
            }

            if (any_event || communicated) {
                stats.state_events += state_event;
                stats.time_events += time_event;
                stats.step_events += step_event;
                if (!options.reference) what_the_integrator_sees(seen_before);
                const bool states_changed = event_iteration();
                if (options.reference || states_changed || integrator_sees_a_change()) {
                    gather_states();
                    restart = true;
                }
                if (options.event_rows && any_event) {
                    set_everywhere(t, x);
                    sample();
                }
            }
            if (time_rule::reached(t, t_out) || t >= stop - tiny) {
                while (time_rule::reached(t, start + static_cast<double>(k_out + 1) * h_out)) ++k_out;
                if (t != last_sample) sample();
                if (options.realtime) pace(wall_start, start);
                if (options.progress) options.progress((t - start) / (stop - start));
            }
        }
        stats.terminated_early = terminate && t < stop - tiny;
        for (auto& c : system.components()) c.instance->terminate();

        stats.simulated_time = t - start;
        stats.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - run_started).count();
        if (cvode) {
            stats.integrator_steps = cvode->steps();
            stats.rhs_evaluations = cvode->rhs_evaluations();
            stats.failure_restarts = cvode->failure_restarts();
        }
        for (const auto& c : system.components()) {
            ComponentStatistics cs_stats{c.name, c.rhs_evaluations, 0, 0, c.instance->link_statistics()};
            (c.interface == Interface::model_exchange ? cs_stats.events : cs_stats.steps) = c.events;
            stats.components.push_back(cs_stats);
        }
        return stats;
    }

    // Wait until the wall clock has caught up with simulated time; count the points already late.
    // A point reached after its wall time by more than the tolerance is late (an exchange with
    // hardware at an instant starts at that instant's wall time: its answer is always a little after).
    void pace(std::chrono::steady_clock::time_point wall_start, double start) {
        const auto due = wall_due(wall_start, t - start);
        const double behind = std::chrono::duration<double>(std::chrono::steady_clock::now() - due).count();
        stats.realtime_max_behind = std::max(stats.realtime_max_behind, behind);
        if (behind > options.realtime_tolerance) ++stats.late_realtime_points;
        if (behind < 0.0) sleep_until_or_interrupted(due);
    }
};

Execution::Execution(System& system, ExecutionOptions options) : system_(system), options_(std::move(options)) {}

RunStatistics Execution::run(std::vector<Observer*> observers) {
    Impl impl(system_, options_, std::move(observers));
    return impl.run();
}

}  // namespace cosim
