// The seed scenario (paper 000 §4, 001 §4): spinning box, s = (sin φ sin θ, cos φ sin θ, cos θ),
// φ̇ = 1.26 rad/s, θ̇ = 6.28 rad/s, 1367 W/m², PWM 5 kHz, 1500 µF, P gain 300, 15 V, 90 Ω, 12 V battery.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "earlier_reading.hpp"
#include "ssr_plant/plant.hpp"
#include "test_integrator.hpp"

namespace {

using namespace ssr_plant;

struct ScenarioResult {
    double v_min = 1e9, v_max = -1e9, v_mean = 0.0;
    double max_period_ripple = 0.0;  // largest peak-to-peak within one PWM period
    std::array<double, 3> err_rms{}, err_max{};
    double duty_min = 1.0, duty_max = 0.0;
    ssr_plant_test::RunStats stats;
};

std::array<double, 3> sun(double t) {
    const double phi = 1.26 * t, theta = 6.28 * t;
    return {std::sin(phi) * std::sin(theta), std::cos(phi) * std::sin(theta), std::cos(theta)};
}

ScenarioResult run(Fidelity f, AngularResponse law, double soc0, double t_end = 0.5) {
    Parameters p = earlier_reading();
    p.fidelity = f;
    p.angular_response = law;
    const Model m = make_model(p);
    auto u = [](double t) {
        Inputs in;
        in.sun_body = sun(t);
        in.irradiance = 1367.0;
        return in;
    };
    // i_sc0: the true short-circuit current of one panel at normal incidence (eq. 5 denominators).
    const double i_sc0 = outputs(
                             m,
                             [] {
                                 Inputs in;
                                 in.sun_body = {1, 0, 0};
                                 return in;
                             }(),
                             DiscreteState{}, 0.0, State{15.0, 0.9})
                             .i_sc[0];
    const double T = 1.0 / p.pwm_frequency;
    const double settle = 0.05;  // start-up transient excluded
    ScenarioResult r;
    long n = 0;
    std::array<double, 3> sq{};
    long period = -1;
    double pmin = 1e9, pmax = -1e9;
    State x{15.0, soc0};
    r.stats = ssr_plant_test::simulate(m, u, x, 0.0, t_end, 20e-6, 50e-6,
                                       [&](double t, const State& xs, const DiscreteState& d, bool is_output) {
                                           if (t < settle) return;
                                           const double v = xs[state_v_bus];
                                           r.v_min = std::min(r.v_min, v);
                                           r.v_max = std::max(r.v_max, v);
                                           const long k = static_cast<long>(std::floor((t + 1e-12) / T));
                                           if (k != period) {
                                               if (period >= 0)
                                                   r.max_period_ripple = std::max(r.max_period_ripple, pmax - pmin);
                                               period = k;
                                               pmin = pmax = v;
                                           }
                                           pmin = std::min(pmin, v);
                                           pmax = std::max(pmax, v);
                                           if (!is_output) return;  // statistics on the uniform 50 µs grid only
                                           const auto y = outputs(m, u(t), d, t, xs);
                                           r.duty_min = std::min(r.duty_min, y.duty);
                                           r.duty_max = std::max(r.duty_max, y.duty);
                                           const auto s = sun(t);
                                           for (int a = 0; a < 3; ++a) {
                                               const double e = y.i_sh[a] / i_sc0 - s[a];
                                               sq[a] += e * e;
                                               r.err_max[a] = std::max(r.err_max[a], std::abs(e));
                                           }
                                           r.v_mean += v;
                                           ++n;
                                       });
    r.v_mean /= static_cast<double>(n);
    for (int a = 0; a < 3; ++a) r.err_rms[a] = std::sqrt(sq[a] / static_cast<double>(n));
    return r;
}

void print(const char* name, const ScenarioResult& r) {
    std::cout << "[" << name << "] v_bus mean " << r.v_mean << " V, min " << r.v_min << ", max " << r.v_max << " (p-p "
              << r.v_max - r.v_min << "), max ripple within one PWM period " << r.max_period_ripple << " V; duty "
              << r.duty_min << ".." << r.duty_max << "; i_sh/i_sc0 − s: RMS (" << r.err_rms[0] << ", " << r.err_rms[1]
              << ", " << r.err_rms[2] << "), max (" << r.err_max[0] << ", " << r.err_max[1] << ", " << r.err_max[2]
              << "); steps " << r.stats.steps << ", time events " << r.stats.time_events << "\n";
}

// Hand bounds used below (seed values, defaults of parameters.hpp):
// - the P controller holds 0 < D < 1, so the bus sits in [15, 15 + 100/300] = [15, 15.333] V apart
//   from the ripple; one PWM period can move the bus by at most Σ I_sc · T / C ≤ √3 · 0.848 A ·
//   200 µs / 1500 µF = 0.196 V (all lit panels delivering for a whole period).
// - the S/H error: the sun vector moves at most |ds/dt| ≤ √(φ̇² + θ̇²) = 6.41 /s, held at most one
//   period (200 µs) → 1.3e-3; the shunt switch's 0.05 Ω adds a bias of order R/R_sh ≈ 1e-4.
TEST(SsrCoreScenario, SwitchingHoldsBusAndTracksSunWithCosineLaw) {
    const auto r = run(Fidelity::switching, AngularResponse::cosine, 0.9);
    print("switching, cosine, battery standby", r);
    EXPECT_GT(r.v_min, 15.0 - 0.196);
    EXPECT_LT(r.v_max, 15.0 + 1.0 / 3.0 + 0.196);
    EXPECT_LT(r.max_period_ripple, 0.196);
    EXPECT_GT(r.duty_min, 0.0);
    EXPECT_LT(r.duty_max, 1.0);
    for (int a = 0; a < 3; ++a) EXPECT_LT(r.err_max[a], 1.3e-3 + 1e-3) << a;
}

TEST(SsrCoreScenario, AveragedHoldsBusAndTracksSunWithCosineLaw) {
    const auto r = run(Fidelity::averaged, AngularResponse::cosine, 0.9);
    print("averaged, cosine, battery standby", r);
    EXPECT_GT(r.v_min, 15.0);
    EXPECT_LT(r.v_max, 15.0 + 1.0 / 3.0);
    EXPECT_EQ(r.stats.time_events, 0);
    for (int a = 0; a < 3; ++a) EXPECT_LT(r.err_max[a], 1e-3) << a;  // only the switch-resistance bias
}

TEST(SsrCoreScenario, ChargingBatteryAndKellyResponse) {
    // Battery connected for charging (soc below the 0.80 threshold) and the Kelly cosine: the bus is
    // still regulated. The Kelly law makes i_sh/i_sc0 read low against s: per face the deficit
    // cos β − f(β) is at most cos 80° = 0.174 (from 80° on f ∈ [0, 0.1]; below, the table's largest
    // deficit is 0.074 at 80°), and it must show (RMS well above the cosine run's 1e-3 bound).
    for (Fidelity f : {Fidelity::switching, Fidelity::averaged}) {
        const auto r = run(f, AngularResponse::kelly, 0.7);
        print(f == Fidelity::switching ? "switching, kelly, charging" : "averaged, kelly, charging", r);
        EXPECT_GT(r.v_min, 15.0 - 0.196);
        EXPECT_LT(r.v_max, 15.0 + 1.0 / 3.0 + 0.196);
        for (int a = 0; a < 3; ++a) {
            EXPECT_LT(r.err_max[a], 0.174) << a;
            EXPECT_GT(r.err_rms[a], 0.01) << a;
        }
    }
}

}  // namespace
