// Statistics against values worked out by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "statistics.hpp"

using campaign::percentile_of;
using campaign::statistic;

// Definition 7 of Hyndman & Fan: h = (n - 1) p / 100, linear between order statistics. For {1, 2, 3, 4}:
// p50 -> h = 1.5 -> 2.5; p25 -> h = 0.75 -> 1.75; p95 -> h = 2.85 -> 3.85.
TEST(Statistics, PercentilesInterpolateBetweenOrderStatistics) {
    const std::vector<double> v = {4.0, 1.0, 3.0, 2.0};
    EXPECT_DOUBLE_EQ(statistic("p50", v), 2.5);
    EXPECT_DOUBLE_EQ(statistic("p25", v), 1.75);
    EXPECT_DOUBLE_EQ(statistic("p95", v), 3.85);
    EXPECT_DOUBLE_EQ(statistic("p0", v), 1.0);
    EXPECT_DOUBLE_EQ(statistic("p100", v), 4.0);
    EXPECT_DOUBLE_EQ(statistic("p50", {7.0}), 7.0);
}

// {3, 4}: mean 3.5, rms sqrt((9 + 16) / 2) = sqrt(12.5); final is the last sampled, not the largest.
TEST(Statistics, NamedStatistics) {
    const std::vector<double> v = {3.0, 4.0, 1.0};
    EXPECT_DOUBLE_EQ(statistic("mean", v), 8.0 / 3.0);
    EXPECT_DOUBLE_EQ(statistic("rms", {3.0, 4.0}), std::sqrt(12.5));
    EXPECT_EQ(statistic("min", v), 1.0);
    EXPECT_EQ(statistic("max", v), 4.0);
    EXPECT_EQ(statistic("final", v), 1.0);
    EXPECT_EQ(statistic("count", v), 3.0);
    EXPECT_EQ(statistic("count", {}), 0.0);
    EXPECT_TRUE(std::isnan(statistic("mean", {})));
    EXPECT_TRUE(std::isnan(statistic("p95", {})));
}

TEST(Statistics, PercentileNames) {
    EXPECT_EQ(percentile_of("p95"), 95.0);
    EXPECT_EQ(percentile_of("p99.9"), 99.9);
    EXPECT_EQ(percentile_of("p0"), 0.0);
    EXPECT_FALSE(percentile_of("p101"));
    EXPECT_FALSE(percentile_of("p"));
    EXPECT_FALSE(percentile_of("px"));
    EXPECT_FALSE(percentile_of("p9x"));
    EXPECT_FALSE(percentile_of("mean"));
}

// Phi(1) - Phi(-1) = erf(1/sqrt 2) = 0.682689492137086 (tables); one-sided: Phi(0) = 1/2.
TEST(Statistics, NormalMass) {
    EXPECT_NEAR(campaign::normal_mass(0.0, 1.0, -1.0, 1.0), 0.682689492137086, 1e-12);
    EXPECT_NEAR(campaign::normal_mass(5.0, 2.0, 3.0, 7.0), 0.682689492137086, 1e-12);
    EXPECT_NEAR(campaign::normal_mass(0.0, 1.0, -INFINITY, 0.0), 0.5, 1e-15);
    EXPECT_EQ(campaign::normal_mass(0.0, 1.0, -INFINITY, INFINITY), 1.0);
}

// Normalized errors (3 dof) {1, 4, 9, 16}: NEES/dof = 30 / 4 / 3 = 2.5; three of four at or below chi2(3)'s
// 99 % point 11.3449 (16 is above it): 75 %.
TEST(Statistics, NormalizedErrorPerDofAndChiSquareCoverage) {
    const std::vector<double> v = {1.0, 4.0, 9.0, 16.0};
    EXPECT_DOUBLE_EQ(statistic("per_dof", v), 2.5);
    EXPECT_DOUBLE_EQ(statistic("chi2_99", v), 75.0);
    EXPECT_DOUBLE_EQ(statistic("chi2_99", {11.34}), 100.0);
    EXPECT_DOUBLE_EQ(statistic("chi2_99", {11.35}), 0.0);
    EXPECT_TRUE(std::isnan(statistic("chi2_99", {})));
}
