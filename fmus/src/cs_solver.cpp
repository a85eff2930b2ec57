#include "fmu/cs_solver.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "fmu/errors.hpp"
#include "integrator/indicator_bisection.hpp"

namespace fmu {

CsSolver::CsSolver(ModelRunner& runner, double relative_tolerance)
    : runner_(runner), relative_tolerance_(relative_tolerance), x_(runner.state_count()) {
    const std::size_t n = runner_.state_count();
    if (n == 0) return;  // nothing to integrate; events are located by bisection
    // Absolute tolerance of each state from its nominal magnitude: reltol × nominal.
    std::vector<double> abstol(n);
    runner_.get_nominals(abstol);
    for (auto& a : abstol) a *= relative_tolerance;
    auto rhs = [this](double t, std::span<const double> x, std::span<double> dx) {
        runner_.set_time(t);
        runner_.set_states(x);
        runner_.get_derivatives(dx);
    };
    auto roots = [this](double t, std::span<const double> x, std::span<double> g) {
        runner_.set_time(t);
        runner_.set_states(x);
        runner_.get_indicators(g);
    };
    cvode_ = std::make_unique<integrator::CvodeIntegrator>(n, runner_.indicator_count(), rhs, roots, relative_tolerance,
                                                           abstol);
}

SolverStatistics CsSolver::statistics() const {
    SolverStatistics s = stats_;
    if (cvode_) {
        s.steps = cvode_->steps();
        s.rhs_evaluations = cvode_->rhs_evaluations();
    }
    return s;
}

bool CsSolver::integrate_to(double t_stop) {
    if (restart_needed_) {
        runner_.get_states(x_);
        cvode_->restart(runner_.time(), x_);
        restart_needed_ = false;
        ++stats_.restarts;
    }
    double t = runner_.time();
    integrator::CvodeIntegrator::Stop stop;
    try {
        stop = cvode_->advance(t_stop, t, x_);
    } catch (...) {
        restart_needed_ = true;
        throw;
    }
    // The callbacks may have left trial values behind: set the point CVODE returned.
    runner_.set_time(t);
    runner_.set_states(x_);
    return stop == integrator::CvodeIntegrator::Stop::root;
}

bool CsSolver::locate_without_states(double t_stop) {
    const std::size_t m = runner_.indicator_count();
    const auto crossing = m == 0 ? std::nullopt
                                 : integrator::bisect_indicator_crossing(runner_.time(), t_stop, m,
                                                                         [this](double t, std::span<double> z) {
                                                                             runner_.set_time(t);
                                                                             runner_.get_indicators(z);
                                                                         });
    runner_.set_time(crossing.value_or(t_stop));
    return crossing.has_value();
}

CsSolver::Outcome CsSolver::advance(double t_end, HostEvents host_events,
                                    const std::function<bool(double)>& host_wants) {
    const double tiny = 1e-12 * std::max(1.0, std::abs(t_end));
    // Whether the event at the current time is the host's (see HostEvents).
    auto hosts = [&](bool at_end) {
        switch (host_events) {
            case HostEvents::none:
                return false;
            case HostEvents::at_end:
                return at_end;
            case HostEvents::all:
                return true;
            case HostEvents::ask:
                return at_end || host_wants(runner_.time());
        }
        return false;
    };
    for (;;) {
        if (runner_.time_event_due()) {
            if (hosts(runner_.time() >= t_end - tiny)) {
                restart_needed_ = true;  // the host's discrete update may make the right-hand side jump
                return Outcome::event_pending;
            }
            ++stats_.time_events;
            const EventUpdate r = runner_.event_iteration();
            restart_needed_ = true;  // any discrete change may make the right-hand side jump
            if (r.terminate) return Outcome::terminated;
            if (runner_.time_event_due())
                throw Error("the block did not move its time event past t = " + std::to_string(runner_.time()));
            continue;
        }
        if (runner_.time() >= t_end - tiny) {
            runner_.set_time(std::max(runner_.time(), t_end));
            return Outcome::reached;
        }
        const double t_stop = std::min(t_end, runner_.next_time_event());
        // A block that steps its own states between events (a linear circuit) needs no integrator there.
        bool state_event = false;
        if (const auto span = runner_.advance_between_events(t_stop, relative_tolerance_)) {
            restart_needed_ = true;  // the integrator's history no longer matches the states
            ++stats_.block_spans;
            state_event = span->state_event;
        } else {
            state_event = cvode_ ? integrate_to(t_stop) : locate_without_states(t_stop);
        }
        if (state_event) {
            ++stats_.state_events;
            if (hosts(false)) {
                restart_needed_ = true;
                return Outcome::event_pending;
            }
            const EventUpdate r = runner_.event_iteration();
            restart_needed_ = true;
            if (r.terminate) return Outcome::terminated;
        }
    }
}

}  // namespace fmu
