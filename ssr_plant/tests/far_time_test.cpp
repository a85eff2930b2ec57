// Times far from the start (issue 14 case 1): PWM periods a host stepped over are skipped at once, and
// a time beyond the period count's limit (1e11 periods) is refused instead of walking edges.
#include <gtest/gtest.h>

#include <stdexcept>

#include "ssr_plant/plant.hpp"

namespace {

using namespace ssr_plant;

constexpr double T = 1.0 / 5000.0;  // seed PWM period

TEST(SsrCorePlantFarTime, SteppedOverPeriodsAreSkippedAtOnce) {
    // The regular modulator: both edges are time events, the off edge at D T into the period.
    Parameters p;
    p.modulation = Modulation::regular;
    p.controller_gain = 3.0;  // 1/V
    const Model m = make_model(p);
    Inputs u;
    u.sun_body = {1, 0, 0};
    u.irradiance = 1367.0;
    State x{15.2, 0.9};  // D = 0.6 (hand: 3 /V · 0.2 V)
    DiscreteState d = initialize(m, u, 0.0, x);
    // Jump to 1e7 periods + 0.1 T: by hand, period 1e7 is in progress, its off edge (0.6 T in) is next.
    const double t = (1e7 + 0.1) * T;
    d = event_update(m, u, d, t, x).discrete;
    EXPECT_EQ(d.period_index, 10000000);
    EXPECT_GT(next_time_event(m, d), t);
    EXPECT_NEAR(next_time_event(m, d), (1e7 + 0.6) * T, 1e-9);
}

TEST(SsrCorePlantFarTime, TimeBeyondTheCountIsRefused) {
    const Model m = make_model(Parameters{});
    Inputs u;
    u.sun_body = {1, 0, 0};
    u.irradiance = 1367.0;
    State x{15.2, 0.9};
    const DiscreteState d = initialize(m, u, 0.0, x);
    EXPECT_THROW(event_update(m, u, d, 1e18, x), std::invalid_argument);
}

}  // namespace
