// The step between PWM edges (advance_between_edges) against closed forms written here and an independent
// fine integration: the gate-on bus is a linear RC discharge (exact), the gate-off bus carries the panels'
// diode law (linearized per step, its error measured against RK4 on the core's right-hand side), and the
// latched modulator's trailing edge is the root of K (v(t) − v_ref) = (t − t_k)/T on the RC discharge.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "ssr_plant/plant.hpp"

namespace {

using namespace ssr_plant;

constexpr double T = 1.0 / 5000.0;  // seed PWM period
constexpr double R = 90.0, C = 1500e-6;

Inputs sun_on(double sx, double sy, double sz) {
    Inputs u;
    u.sun_body = {sx, sy, sz};
    u.irradiance = 1367.0;
    return u;
}

Model seed_model(Modulation modulation) {
    Parameters p;
    p.modulation = modulation;
    p.angular_response = AngularResponse::cosine;
    return make_model(p);
}

// The battery at soc 0.9 (lead-acid: 12.62 V rested) is behind its blocking diode at a 15 V bus, and the
// charge switch is open: the bus sees the panels and the load only.
constexpr double soc0 = 0.9;

TEST(SsrCoreBetweenEdges, GateOnIsTheExactRcDischarge) {
    const Model m = seed_model(Modulation::regular);
    const Inputs u = sun_on(0.3, 0.4, 0.866);
    DiscreteState d = initialize(m, u, 0.0, {15.05, soc0});  // D = 300 · 0.05 → 1: gate on all period
    ASSERT_TRUE(d.gate);
    ASSERT_FALSE(d.charge_connected);
    for (double v0 : {15.3, 15.05, 14.2}) {
        const auto r = advance_between_edges(
            m, [&](double) { return u; }, d, 0.0, {v0, soc0}, 1.6e-4, 1e-6);
        ASSERT_TRUE(r);
        EXPECT_FALSE(r->state_event);
        EXPECT_EQ(r->t, 1.6e-4);
        const double expected = v0 * std::exp(-1.6e-4 / (R * C));  // C dv/dt = −v/R
        EXPECT_NEAR(r->x[0], expected, 1e-13 * v0) << v0;
        EXPECT_EQ(r->x[1], soc0);  // no battery current, no charge change
    }
}

// RK4 with steps of 40 ns on the core's own right-hand side (derivatives()), inputs as given.
State fine_reference(const Model& m, const InputsAt& u, const DiscreteState& d, State x, double t0, double t1) {
    const int n = 4000;
    const double h = (t1 - t0) / n;
    for (int k = 0; k < n; ++k) {
        const double t = t0 + k * h;
        auto f = [&](double s, const State& y) { return derivatives(m, u(s), d, s, y); };
        const State k1 = f(t, x);
        const State k2 = f(t + h / 2, {x[0] + h / 2 * k1[0], x[1] + h / 2 * k1[1]});
        const State k3 = f(t + h / 2, {x[0] + h / 2 * k2[0], x[1] + h / 2 * k2[1]});
        const State k4 = f(t + h, {x[0] + h * k3[0], x[1] + h * k3[1]});
        for (int i = 0; i < 2; ++i) x[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    }
    return x;
}

// Gate off, three faces lit and the sun turning at the seed's 6.28 rad/s: the bus charges from the panels
// through the OR diodes, whose I–V curve is the only nonlinearity. The span (160 µs, one off-time) must
// agree with the fine integration to the step's error bound, 1e-3 · rtol · v per step (a few steps).
TEST(SsrCoreBetweenEdges, GateOffFollowsTheDiodeLawWithMovingSun) {
    const Model m = seed_model(Modulation::regular);
    auto u = [](double t) {
        const double a = 0.4 + 6.28 * t;
        return sun_on(0.5 * std::cos(a), 0.5 * std::sin(a), 0.707);
    };
    DiscreteState d = initialize(m, u(0.0), 0.0, {14.9, soc0});  // below the reference: D = 0, gate off
    ASSERT_FALSE(d.gate);
    for (double v0 : {14.9, 15.2, 17.0}) {  // 17 V: the panels near their maximum-power knee (Vmp 17.5 V)
        const auto r = advance_between_edges(m, u, d, 0.0, {v0, soc0}, 1.6e-4, 1e-6);
        ASSERT_TRUE(r);
        const State ref = fine_reference(m, u, d, {v0, soc0}, 0.0, 1.6e-4);
        std::printf("gate off from %.1f V: span %.12f V, RK4 %.12f V, difference %.2e V in %d steps\n", v0, r->x[0],
                    ref[0], r->x[0] - ref[0], r->steps);
        EXPECT_NEAR(r->x[0], ref[0], 2e-8) << v0;
        EXPECT_GT(r->x[0], v0);  // the panels charge the bus
    }
}

// latched_natural at the seed's 300 /V: the gate turns off where the live duty K (v − v_ref) meets the
// carrier t/T; on the RC discharge v(t) = v0 e^{−t/RC} that is the root of
// K (v0 e^{−t/RC} − v_ref) − t/T, found here by bisection.
TEST(SsrCoreBetweenEdges, ComparatorEdgeIsTheRootOnTheDischarge) {
    const Model m = seed_model(Modulation::latched_natural);
    const Inputs u = sun_on(0.3, 0.4, 0.866);
    const double v0 = 15.002;  // D = 0.6 at the period start
    const DiscreteState d = initialize(m, u, 0.0, {v0, soc0});
    ASSERT_TRUE(d.gate);
    const auto r = advance_between_edges(
        m, [&](double) { return u; }, d, 0.0, {v0, soc0}, T, 1e-6);
    ASSERT_TRUE(r);
    ASSERT_TRUE(r->state_event);
    auto g = [&](double t) { return 300.0 * (v0 * std::exp(-t / (R * C)) - 15.0) - t / T; };
    double lo = 0.0, hi = T;
    for (int k = 0; k < 200; ++k) {
        const double mid = 0.5 * (lo + hi);
        (g(mid) > 0 ? lo : hi) = mid;
    }
    EXPECT_NEAR(r->t, hi, 1e-15);
    EXPECT_NEAR(r->x[0], v0 * std::exp(-hi / (R * C)), 1e-12);
    // The event update finds the edge due there and turns the gate off.
    const EventResult e = event_update(m, u, d, r->t, r->x);
    EXPECT_FALSE(e.discrete.gate);
}

TEST(SsrCoreBetweenEdges, AveragedFidelityIsLeftToTheIntegrator) {
    Parameters p;
    p.fidelity = Fidelity::averaged;
    const Model m = make_model(p);
    const Inputs u = sun_on(0.0, 0.0, 1.0);
    const DiscreteState d = initialize(m, u, 0.0, {15.0, soc0});
    EXPECT_FALSE(advance_between_edges(
        m, [&](double) { return u; }, d, 0.0, {15.0, soc0}, 1e-3, 1e-6));
}

}  // namespace
