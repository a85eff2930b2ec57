// Times far from the start (issue 14 case 1): PWM periods a host stepped over are skipped at once, and
// a time beyond the period count's limit (1e11 periods) is refused instead of walking edges.
#include <gtest/gtest.h>

#include <stdexcept>

#include "ssr_plant/plant.hpp"

namespace {

using namespace ssr_plant;

constexpr double T = 1.0 / 5000.0;  // seed PWM period

TEST(SsrCorePlantFarTime, SteppedOverPeriodsAreSkippedAtOnce) {
    Parameters p;
    p.modulation = Modulation::regular;  // the off edge is a time event at duty · T
    const Model m = make_model(p);
    Inputs u;
    u.sun_body = {1, 0, 0};
    u.irradiance = 1367.0;
    State x{15.001, 0.9};                               // just above the set point: a duty inside (0, 1)
    const double duty = initialize(m, u, 0.0, x).duty;  // the controller's law is tested elsewhere
    ASSERT_GT(duty, 0.0);
    ASSERT_LT(duty, 1.0);
    DiscreteState d = initialize(m, u, 0.0, x);
    // Jump to 1e7 periods + a hair: period 1e7 is in progress, its off edge (duty · T in) is next.
    const double t = (1e7 + 1e-3) * T;
    d = event_update(m, u, d, t, x).discrete;
    EXPECT_EQ(d.period_index, 10000000);
    EXPECT_GT(next_time_event(m, d), t);
    EXPECT_NEAR(next_time_event(m, d), (1e7 + duty) * T, 1e-9);
    // Latched modulation: no off-edge time event, the next period start is next.
    const Model latched = make_model(Parameters{});
    DiscreteState dl = initialize(latched, u, 0.0, x);
    dl = event_update(latched, u, dl, t, x).discrete;
    EXPECT_EQ(dl.period_index, 10000000);
    EXPECT_NEAR(next_time_event(latched, dl), (1e7 + 1) * T, 1e-9);
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
