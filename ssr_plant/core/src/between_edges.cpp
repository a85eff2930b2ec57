// The exact step of the switching plant between events: see advance_between_edges in plant.hpp.
#include <algorithm>
#include <cmath>

#include "plant_internals.hpp"
#include "ssr_plant/plant.hpp"

namespace ssr_plant {
namespace {

// Local error per step, as a fraction of the host's relative tolerance times the bus voltage.
constexpr double error_fraction = 0.1;

// φ1(z) = (e^z − 1)/z and φ2(z) = (e^z − 1 − z)/z², by their series where the quotients lose digits.
double phi1(double z) {
    if (std::abs(z) < 1e-5) return 1.0 + z * (0.5 + z / 6.0);
    return std::expm1(z) / z;
}
double phi2(double z) {
    if (std::abs(z) < 0.05)
        return 0.5 + z * (1.0 / 6.0 + z * (1.0 / 24.0 + z * (1.0 / 120.0 + z * (1.0 / 720.0 + z / 5040.0))));
    return (std::expm1(z) - z) / (z * z);
}

double phi3(double z) {  // (e^z − 1 − z − z²/2)/z³
    if (std::abs(z) < 0.1)
        return 1.0 / 6.0 + z * (1.0 / 24.0 + z * (1.0 / 120.0 + z * (1.0 / 720.0 + z * (1.0 / 5040.0 + z / 40320.0))));
    return (std::expm1(z) - z - 0.5 * z * z) / (z * z * z);
}

// The linear equation of one step: dv/dt = f0 + a (v − v0) + b (t − t0).
struct Linear {
    double f0 = 0.0, a = 0.0, b = 0.0;
    double dv(double tau) const {  // v(t0 + τ) − v0, exact
        return tau * phi1(a * tau) * f0 + tau * tau * phi2(a * tau) * b;
    }
};

// Slopes of the bus right-hand side at the balance `b0` (state x, illumination l0) in v and, from the
// photocurrents of l0 and l1 (h later), in t. A panel delivering I through R_s' = R_s + R_or at the diode
// voltage x_d = V + I R_s' has, from eq. 2 differentiated, dI/dV = −g / (1 + R_s' g) and dI/dI_ph =
// 1 / (1 + R_s' g), g = I_D e^{x_d/a} / a + 1/R_sh; a reverse-biased (clipped) panel has neither.
Linear linearize(const Model& m, const Illumination& l0, const Illumination& l1, const DiscreteState& d, const State& x,
                 const detail::BusBalance& b0, double h) {
    const auto& p = m.parameters;
    const double v = x[state_v_bus];
    double di_dv = 0.0, di_dt = 0.0;
    for (std::size_t k = 0; k < face_count; ++k) {
        const double open = 1.0 - b0.sigma_face[k];
        if (open <= 0.0 || !(b0.i_pv[k] > 0.0)) continue;
        const DiodeModel& dm = l0.diode[k];
        const double rs = dm.series_resistance + p.or_diode_resistance;
        const double xd = v + p.or_diode_forward_voltage + b0.i_pv[k] * rs;
        const double g = dm.saturation_current / dm.ideality_voltage * std::exp(xd / dm.ideality_voltage) +
                         1.0 / dm.shunt_resistance;
        di_dv += open * -g / (1.0 + rs * g);
        if (h > 0.0) di_dt += open * (l1.photocurrent[k] - l0.photocurrent[k]) / h / (1.0 + rs * g);
    }
    // The battery network is piecewise linear in v: its slope by a central difference (no panel solve).
    constexpr double dv = 1e-6;
    const double soc = x[state_soc];
    const double di_batt = (battery_operating_point(p.battery, soc, v + dv, d.charge_connected).current -
                            battery_operating_point(p.battery, soc, v - dv, d.charge_connected).current) /
                           (2.0 * dv);
    const double c = p.bus_capacitance;
    return {b0.dx[state_v_bus], (di_dv - 1.0 / p.load_resistance - di_batt) / c, di_dt / c};
}

// The earliest zero in (0, h] of an indicator that was > 0 at the step's start and is ≤ 0 at its end,
// located on the step's solution (v exact for the linear equation, soc linear); Illinois' rule.
State dense(const State& x0, const State& x1, const Linear& lin, double correction, double h, double tau) {
    const double s = tau / h;
    return {x0[state_v_bus] + lin.dv(tau) + correction * s * s * s,
            x0[state_soc] + s * (x1[state_soc] - x0[state_soc])};
}

double locate_zero(const Model& m, const Inputs& u, const DiscreteState& d, double t0, const State& x0, const State& x1,
                   const Linear& lin, double correction, double h, std::size_t i, double z0, double z1) {
    auto z = [&](double tau) {
        const State x = dense(x0, x1, lin, correction, h, tau);
        return event_indicators(m, u, d, t0 + tau, x)[i];
    };
    double lo = 0.0, hi = h, z_lo = z0, z_hi = z1;
    int side = 0;
    const double tolerance = 1e-15 * std::max(1.0, std::abs(t0)) + 1e-18;
    for (int it = 0; it < 200 && hi - lo > tolerance; ++it) {
        double tau = lo + (hi - lo) * z_lo / (z_lo - z_hi);
        if (!(tau > lo && tau < hi)) tau = 0.5 * (lo + hi);
        const double zt = z(tau);
        if (zt > 0.0) {
            lo = tau;
            z_lo = zt;
            if (side == -1) z_hi *= 0.5;
            side = -1;
        } else {
            hi = tau;
            z_hi = zt;
            if (side == 1) z_lo *= 0.5;
            side = 1;
        }
    }
    return hi;  // the indicator is ≤ 0 there: the event update finds it due
}

}  // namespace

std::optional<SpanResult> advance_between_edges(const Model& m, const InputsAt& inputs_at, const DiscreteState& d,
                                                double t0, const State& x0, double t_stop, double rtol) {
    if (m.parameters.fidelity != Fidelity::switching || !(rtol > 0.0)) return std::nullopt;
    SpanResult r{t0, x0, false, 0};
    if (!(t_stop > t0)) return r;
    Inputs u = inputs_at(t0);
    Illumination l = detail::panels(m, u, d.faults, t0);
    detail::BusBalance b = detail::bus_balance(m, l, d, x0, nullptr);
    Indicators z = event_indicators(m, u, d, t0, x0);
    double t = t0;
    State x = x0;
    double h = t_stop - t0;
    const double h_min = 1e-12 * std::max(1.0, std::abs(t_stop));
    // Steps of a few µs suffice at any PWM frequency this model accepts; a span needing more than this
    // many is left to the integrator.
    constexpr int max_attempts = 10000;
    for (int attempt = 0; t < t_stop; ++attempt) {
        if (attempt == max_attempts) return std::nullopt;
        const bool last = h >= t_stop - t;
        const double t1 = last ? t_stop : t + h;
        h = t1 - t;
        const Inputs u1 = inputs_at(t1);
        const Illumination l1 = detail::panels(m, u1, d.faults, t1);
        const Linear lin = linearize(m, l, l1, d, x, b, h);
        const double v1 = x[state_v_bus] + lin.dv(h);
        const double g0 = b.dx[state_soc];
        State x1 = {v1, x[state_soc] + h * g0};
        detail::BusBalance b1 = detail::bus_balance(m, l1, d, x1, nullptr);
        // The linearization's error: the true slope at the end differs from the linear one by `mismatch`;
        // the difference grows from 0 at the start as (τ/h)² (second order in Δv and Δt), so its effect on
        // v(t1) is ∫ e^{a(h−τ)} mismatch (τ/h)² dτ = 2 h φ3(ah) mismatch. It is added (the step is then of
        // third order) and its size is the error estimate.
        const double mismatch = b1.dx[state_v_bus] - (lin.f0 + lin.a * (v1 - x[state_v_bus]) + lin.b * h);
        const double correction = 2.0 * h * phi3(lin.a * h) * mismatch;
        const double err = std::abs(correction);
        const double tol = error_fraction * rtol * std::max(1.0, std::abs(x[state_v_bus]));
        if (!std::isfinite(err)) return std::nullopt;
        if (err > tol && h > h_min) {
            h *= std::max(0.2, 0.9 * std::cbrt(tol / err));  // the error grows as h³
            continue;
        }
        x1[state_v_bus] += correction;
        b1.dx[state_v_bus] += lin.a * correction;  // the slope at the corrected end, to first order (δ ≈ 1e-8 V)
        if (b1.dx[state_soc] != g0) {              // the battery carries current: the trapezoidal rule for soc
            x1[state_soc] = x[state_soc] + 0.5 * h * (g0 + b1.dx[state_soc]);
            b1 = detail::bus_balance(m, l1, d, x1, nullptr);
        }
        const Indicators z1 = event_indicators(m, u1, d, t1, x1);
        double t_event = t1;
        bool event = false;
        for (std::size_t i = 0; i < indicator_count; ++i) {
            if (!(z[i] > 0.0 && z1[i] <= 0.0)) continue;
            const double te = t + locate_zero(m, u1, d, t, x, x1, lin, correction, h, i, z[i], z1[i]);
            if (!event || te < t_event) t_event = te;
            event = true;
        }
        ++r.steps;
        if (event) {
            const double tau = t_event - t;
            r.t = t_event;
            r.x = dense(x, x1, lin, correction, h, tau);
            r.state_event = true;
            inputs_at(t_event);
            return r;
        }
        t = t1;
        x = x1;
        u = u1;
        l = l1;
        b = b1;
        z = z1;
        if (err > 0.0)
            h *= std::min(5.0, 0.9 * std::cbrt(tol / err));
        else
            h *= 5.0;
    }
    r.t = t_stop;
    r.x = x;
    return r;
}

}  // namespace ssr_plant
