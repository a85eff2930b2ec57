// Test-only fixed-step RK4 integrator with exact event handling, to exercise the plant's event protocol
// the way an FMI Model Exchange master does: steps end exactly on time events (next_time_event) and on
// uniform output points; a sign change of an event indicator inside a step is located by bisection of
// the step length (to 1e-12 s) and the step is cut there; event_update runs at every event instant.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>

#include "ssr_plant/plant.hpp"

namespace ssr_plant_test {

struct RunStats {
    long steps = 0;
    long time_events = 0;
    long state_events = 0;
    long discrete_changes = 0;
    long charge_switchings = 0;
};

using InputsAt = std::function<ssr_plant::Inputs(double)>;
// Called at the start, at every output point and after every event:
// (t, x, discrete state, is_output_point).
using Observer = std::function<void(double, const ssr_plant::State&, const ssr_plant::DiscreteState&, bool)>;

inline ssr_plant::State rk4(const ssr_plant::Model& m, const InputsAt& u, const ssr_plant::DiscreteState& d, double t,
                            const ssr_plant::State& x, double h) {
    using ssr_plant::State;
    auto add = [](const State& a, const State& k, double s) {
        State r;
        for (std::size_t i = 0; i < r.size(); ++i) r[i] = a[i] + s * k[i];
        return r;
    };
    const State k1 = ssr_plant::derivatives(m, u(t), d, t, x);
    const State k2 = ssr_plant::derivatives(m, u(t + h / 2), d, t + h / 2, add(x, k1, h / 2));
    const State k3 = ssr_plant::derivatives(m, u(t + h / 2), d, t + h / 2, add(x, k2, h / 2));
    const State k4 = ssr_plant::derivatives(m, u(t + h), d, t + h, add(x, k3, h));
    State r;
    for (std::size_t i = 0; i < r.size(); ++i) r[i] = x[i] + h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    return r;
}

inline bool crossed(const ssr_plant::Indicators& a, const ssr_plant::Indicators& b) {
    for (std::size_t i = 0; i < a.size(); ++i)
        if ((a[i] > 0) != (b[i] > 0)) return true;
    return false;
}

inline RunStats simulate(const ssr_plant::Model& m, const InputsAt& u, ssr_plant::State& x, double t0, double t1,
                         double h_max, double output_interval, const Observer& observe) {
    RunStats st;
    ssr_plant::DiscreteState d = ssr_plant::initialize(m, u(t0), t0, x);
    double t = t0;
    long out_index = 1;
    observe(t, x, d, true);
    auto apply_event = [&](bool time_event) {
        const auto r = ssr_plant::event_update(m, u(t), d, t, x);
        if (r.changed) ++st.discrete_changes;
        if (r.discrete.charge_connected != d.charge_connected) ++st.charge_switchings;
        (time_event ? st.time_events : st.state_events)++;
        d = r.discrete;
        // One call must settle the instant (idempotent).
        if (ssr_plant::event_update(m, u(t), d, t, x).changed) throw std::logic_error("event_update not idempotent");
        observe(t, x, d, false);
    };
    while (t < t1) {
        const double t_out = t0 + out_index * output_interval;
        const double t_event = ssr_plant::next_time_event(m, d);
        const double tn = std::min({t + h_max, t_event, t_out, t1});
        const double h = tn - t;
        ssr_plant::State xn = rk4(m, u, d, t, x, h);
        const auto z0 = ssr_plant::event_indicators(m, u(t), d, t, x);
        const auto z1 = ssr_plant::event_indicators(m, u(tn), d, tn, xn);
        ++st.steps;
        if (crossed(z0, z1)) {
            double lo = 0.0, hi = h;
            while (hi - lo > 1e-12) {
                const double mid = 0.5 * (lo + hi);
                const auto xm = rk4(m, u, d, t, x, mid);
                if (crossed(z0, ssr_plant::event_indicators(m, u(t + mid), d, t + mid, xm)))
                    hi = mid;
                else
                    lo = mid;
            }
            x = rk4(m, u, d, t, x, hi);
            t += hi;
            apply_event(false);
            continue;
        }
        x = xn;
        t = tn;
        if (t == t_out) {
            observe(t, x, d, true);
            ++out_index;
        }
        if (t >= t_event) apply_event(true);
    }
    return st;
}

}  // namespace ssr_plant_test
