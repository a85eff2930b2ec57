// The derived signals (harness/systems/analysis/derived_signals.hpp) against hand derivations: rotations
// about one axis compose by adding angles, whatever the product convention.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "analysis/angle_error.hpp"
#include "analysis/derived_signals.hpp"

namespace {

constexpr double pi = std::numbers::pi;

// A rotation by `angle` about body axis k (0 x, 1 y, 2 z), scalar-last.
std::array<double, 4> about(int k, double angle) {
    std::array<double, 4> q{0.0, 0.0, 0.0, std::cos(angle / 2)};
    q[static_cast<std::size_t>(k)] = std::sin(angle / 2);
    return q;
}

TEST(DerivedSignals, AttitudeErrorIsTheRotationAboutEachBodyAxis) {
    for (int k = 0; k < 3; ++k) {
        // The estimate 0.3 rad about axis k, the truth 0.3 + 0.02 rad about it: 0.02 rad about k, nothing else.
        const auto d = analysis::attitude_error_vector(about(k, 0.32), about(k, 0.3));
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(d[static_cast<std::size_t>(j)], j == k ? 0.02 : 0.0, 1e-12) << k;
    }
    // q and -q are one attitude: the sign of the estimate changes nothing; 170 deg is 170 deg, not 190.
    auto minus = about(2, 0.3);
    for (auto& x : minus) x = -x;
    EXPECT_NEAR(analysis::attitude_error_vector(about(2, 0.32), minus)[2], 0.02, 1e-12);
    EXPECT_NEAR(analysis::attitude_error_vector(about(0, 170.0 * pi / 180.0), about(0, 0.0))[0], 170.0 * pi / 180.0,
                1e-12);
}

TEST(DerivedSignals, NormalizedErrorPerDegreeOfFreedom) {
    // P = diag(s^2): an error of s on each axis is 1 per dof.
    EXPECT_NEAR(analysis::normalized_error_per_dof({0.01, 0.01, 0.01}, {0.01, 0.0, 0.01, 0.0, 0.0, 0.01}), 1.0, 1e-12);
    // L = [[1,0,0],[1,1,0],[0,0,2]]: d = (1, 2, 2) gives z = (1, 1, 1), |z|^2 / 3 = 1; d = (0, 0, 6): z3 = 3, 3.
    EXPECT_NEAR(analysis::normalized_error_per_dof({1.0, 2.0, 2.0}, {1.0, 1.0, 1.0, 0.0, 0.0, 2.0}), 1.0, 1e-12);
    EXPECT_NEAR(analysis::normalized_error_per_dof({0.0, 0.0, 6.0}, {1.0, 1.0, 1.0, 0.0, 0.0, 2.0}), 3.0, 1e-12);
    EXPECT_TRUE(std::isnan(analysis::normalized_error_per_dof({1.0, 0.0, 0.0}, {0.0, 0.0, 1.0, 0.0, 0.0, 1.0})));
}

TEST(DerivedSignals, VectorAngleKeepsSmallAngles) {
    const double x[3] = {1.0, 0.0, 0.0}, y[3] = {0.0, 2.0, 0.0}, zero[3] = {0.0, 0.0, 0.0};
    const double near_x[3] = {1.0, std::tan(1e-6), 0.0};  // 1e-6 rad off x: acos(cos) would give 0
    EXPECT_NEAR(analysis::vector_angle_degrees(x, y), 90.0, 1e-12);
    EXPECT_NEAR(analysis::vector_angle_degrees(x, near_x), 1e-6 * 180.0 / pi, 1e-15);
    EXPECT_TRUE(std::isnan(analysis::vector_angle_degrees(zero, x)));
}

}  // namespace
