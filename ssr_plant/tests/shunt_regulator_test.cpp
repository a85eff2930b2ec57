#include "ssr_plant/shunt_regulator.hpp"

#include <gtest/gtest.h>

namespace {

using namespace ssr_plant;

TEST(SsrCoreController, DutyIsProportionalPerVoltAndClamped) {
    const Parameters p{};  // gain 300 per volt, reference 15 V (seed)
    EXPECT_EQ(controller_duty(p, 15.0), 0.0);
    EXPECT_NEAR(controller_duty(p, 15.001), 0.30, 1e-9);  // 300 /V · 1 mV = 0.30
    EXPECT_NEAR(controller_duty(p, 15.0025), 0.75, 1e-9);
    EXPECT_EQ(controller_duty(p, 15.004), 1.0);  // clamped above (from 15 + 1/300 V = 15.0033 V)
    EXPECT_EQ(controller_duty(p, 12.0), 0.0);    // clamped below
}

TEST(SsrCoreHall, DifferentialCurrentsSubtractOppositeFaces) {
    // Faces +x, −x, +y, −y, +z, −z (eq. 5 numerators).
    const auto d = differential_currents({0.5, 0.125, 0.0, 0.25, 1.0, 0.0});
    EXPECT_DOUBLE_EQ(d[0], 0.375);
    EXPECT_DOUBLE_EQ(d[1], -0.25);
    EXPECT_DOUBLE_EQ(d[2], 1.0);
}

}  // namespace
