#include <gtest/gtest.h>

#include <stdexcept>

#include "environment/constants.hpp"
#include "environment/time_scales.hpp"

namespace env = environment;

TEST(EnvironmentCoreTime, JulianDateOfJ2000IsTheDefinition) {
    // J2000.0 = 2000-01-01 12:00 = JD 2451545.0 (IAU definition).
    EXPECT_DOUBLE_EQ(env::julian_date({2000, 1, 1, 12, 0, 0.0}), 2451545.0);
}

TEST(EnvironmentCoreTime, JulianDateMatchesMeeusExamples) {
    // Meeus, Astronomical Algorithms (2nd ed.), example 7.a: 1957 Oct 4.81 UT = JD 2436116.31
    // (0.81 d = 19:26:24).
    EXPECT_NEAR(env::julian_date({1957, 10, 4, 19, 26, 24.0}), 2436116.31, 1e-8);
    // Meeus ch. 7 table: 1987 Jan 27.0 = 2446822.5, 1988 Jun 19.5 = 2447332.0, 1600 Dec 31.0 = 2305812.5.
    EXPECT_DOUBLE_EQ(env::julian_date({1987, 1, 27, 0, 0, 0.0}), 2446822.5);
    EXPECT_DOUBLE_EQ(env::julian_date({1988, 6, 19, 12, 0, 0.0}), 2447332.0);
    EXPECT_DOUBLE_EQ(env::julian_date({1600, 12, 31, 0, 0, 0.0}), 2305812.5);
}

TEST(EnvironmentCoreTime, JulianDateRejectsImpossibleDates) {
    EXPECT_THROW(env::julian_date({2026, 13, 1, 0, 0, 0.0}), std::invalid_argument);
    EXPECT_THROW(env::julian_date({2026, 1, 1, 24, 0, 0.0}), std::invalid_argument);
}

TEST(EnvironmentCoreTime, GmstMatchesPublishedExamples) {
    // Meeus example 12.a: 1987 April 10, 0h UT -> GMST = 13h10m46.3668s = 197.693195 deg.
    const double g1 = env::gmst(env::julian_date({1987, 4, 10, 0, 0, 0.0})) * env::kRadToDeg;
    EXPECT_NEAR(g1, (13.0 + 10.0 / 60.0 + 46.3668 / 3600.0) * 15.0, 1e-5);
    // Vallado, Fundamentals of Astrodynamics, example 3-5: 1992 Aug 20, 12:14 UT1 -> 152.578788 deg.
    const double g2 = env::gmst(env::julian_date({1992, 8, 20, 12, 14, 0.0})) * env::kRadToDeg;
    EXPECT_NEAR(g2, 152.578788, 1e-5);
}

TEST(EnvironmentCoreTime, DecimalYearCountsTheCalendarYear) {
    // Hand calculation: 2025-07-02 12:00 is 182.5 days after 2025-01-01 00:00, 2025 has 365 days.
    EXPECT_NEAR(env::decimal_year(env::julian_date({2025, 7, 2, 12, 0, 0.0})), 2025.5, 1e-12);
    EXPECT_DOUBLE_EQ(env::decimal_year(env::julian_date({2026, 1, 1, 0, 0, 0.0})), 2026.0);
    // 2028 is a leap year: 2028-07-02 00:00 is 183 days in, 183/366 = 0.5.
    EXPECT_NEAR(env::decimal_year(env::julian_date({2028, 7, 2, 0, 0, 0.0})), 2028.5, 1e-12);
}
