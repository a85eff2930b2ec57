#include "ssr_plant/angular_response.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

using namespace ssr_plant;
constexpr double deg = std::numbers::pi / 180.0;

TEST(SsrCoreAngular, CosineLawIsEq1AndZeroBeyond90) {
    // Expected: cos β by the standard library (eq. 1), 0 for faces turned away.
    for (double b : {0.0, 10.0, 30.0, 45.0, 60.0, 89.0})
        EXPECT_NEAR(angular_response(AngularResponse::cosine, std::cos(b * deg)), std::cos(b * deg), 1e-15) << b;
    EXPECT_EQ(angular_response(AngularResponse::cosine, std::cos(90.0 * deg)), std::max(0.0, std::cos(90 * deg)));
    EXPECT_EQ(angular_response(AngularResponse::cosine, std::cos(120.0 * deg)), 0.0);
    EXPECT_EQ(angular_response(AngularResponse::cosine, -1.0), 0.0);
}

TEST(SsrCoreAngular, KellyMatchesPatelTableAtTabulatedAngles) {
    // Patel (1999) Kelly cosine table, seed 000 fig. 4 (values typed from the brief, not from the code).
    const double angles[] = {0, 30, 50, 60, 80, 85};
    const double values[] = {1.000, 0.866, 0.635, 0.450, 0.100, 0.000};
    for (int i = 0; i < 6; ++i) {
        EXPECT_NEAR(kelly_response(angles[i] * deg), values[i], 1e-4) << angles[i];
        EXPECT_NEAR(angular_response(AngularResponse::kelly, std::cos(angles[i] * deg)), values[i], 1e-4) << angles[i];
    }
    // Beyond 85° and behind the face: zero.
    for (double b : {85.0, 86.0, 89.9, 90.0, 100.0, 180.0})
        EXPECT_EQ(angular_response(AngularResponse::kelly, std::cos(b * deg)), 0.0) << b;
    // Below 30° it is the cosine itself (the table's 0° and 30° entries are cos 0°, cos 30°).
    for (double b : {1.0, 15.0, 29.0}) EXPECT_NEAR(kelly_response(b * deg), std::cos(b * deg), 1e-15);
}

TEST(SsrCoreAngular, KellyIsMonotoneBoundedAndSmooth) {
    double prev = 1.0;
    for (int i = 0; i <= 9000; ++i) {
        const double b = i * 0.01;
        const double f = kelly_response(b * deg);
        EXPECT_LE(f, prev + 1e-15) << b;  // non-increasing in β
        EXPECT_GE(f, 0.0);
        EXPECT_LE(f, 1.0);
        prev = f;
    }
    // C¹ at every knot (and at the joins with cos and with 0): one-sided difference quotients agree.
    const double h = 1e-5;
    for (double knot : {30.0, 50.0, 60.0, 80.0, 85.0}) {
        const double f0 = kelly_response(knot * deg);
        const double left = (f0 - kelly_response((knot - h) * deg)) / h;
        const double right = (kelly_response((knot + h) * deg) - f0) / h;
        EXPECT_NEAR(left, right, 1e-5) << knot;
        // Continuous: both sides approach the knot value.
        EXPECT_NEAR(kelly_response((knot - h) * deg), f0, 1e-6);
        EXPECT_NEAR(kelly_response((knot + h) * deg), f0, 1e-6);
    }
    // The Kelly response falls faster than the cosine at large angles (the point of fig. 4):
    // every tabulated value from 50° on is below cos β.
    for (double b : {50.0, 60.0, 80.0, 85.0}) EXPECT_LT(kelly_response(b * deg), std::cos(b * deg));
}

}  // namespace
