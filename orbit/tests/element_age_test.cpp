// orbit/element_age.hpp and element_plausibility.hpp: a set moved along SGP4's secular rates, against the
// study script that made the bundled system's on-board set (attitude_estimator/study/older_tle.py, run at
// test time where python3 is) and against closed forms; the plausibility rule.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "orbit/element_age.hpp"
#include "orbit/element_plausibility.hpp"
#include "orbit/tle.hpp"

namespace {

constexpr double kPi = 3.14159265358979323846;

// A line with its checksum in column 69 (the test's sets are written without one).
std::string with_checksum(std::string line68) {
    return line68 + std::to_string(orbit::tle_checksum(line68));
}

struct Set {
    std::string line1, line2;
    double hours;
};

const Set kSets[] = {
    // The bundled truth set (harness/systems/leo_orbit.ssd): 64.9 deg, 570 km, e = 0.0012.
    {with_checksum("1 90001U          26079.00000000  .00002000  00000-0  15000-3 0  999"),
     with_checksum("2 90001  64.9000   0.0000 0012000  90.0000 270.0000 14.98524078  100"), 24.0},
    // 00005 of the SGP4 verification file: e = 0.186, 34 deg.
    {with_checksum("1 00005U 58002B   00179.78495062  .00000023  00000-0  28098-4 0  475"),
     with_checksum("2 00005  34.2682 348.7242 1859667 331.7664  19.3264 10.82419157 4138"), 72.0},
    // An ISS-like set, 51.6 deg, 15.5 rev/day.
    {with_checksum("1 25544U 98067A   26150.50000000  .00016717  00000-0  30000-3 0  999"),
     with_checksum("2 25544  51.6400 200.1000 0005000  60.0000 300.0000 15.50000000 4000"), 5.5},
    // Sun-synchronous, 98.7 deg, 800 km.
    {with_checksum("1 28057U 03049A   26200.25000000  .00000040  00000-0  30000-4 0  999"),
     with_checksum("2 28057  98.7000  10.0000 0010000 120.0000 240.0000 14.28000000 1000"), 48.0},
};

std::string run(const std::string& command) {
    std::string out;
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
    if (!pipe) return out;
    char buffer[256];
    while (fgets(buffer, sizeof buffer, pipe.get())) out += buffer;
    return out;
}

double angle_difference(double a, double b) {
    const double d = std::fmod(std::abs(a - b), 360.0);
    return std::min(d, 360.0 - d);
}

TEST(OrbitElementAge, MatchesTheStudyScript) {
    const std::string python = PVATT_PYTHON3;
    if (python.empty()) GTEST_SKIP() << "python3 not found";
    for (const Set& s : kSets) {
        const std::string out = run(python + " " + PVATT_OLDER_TLE_SCRIPT + " '" + s.line1 + "' '" + s.line2 +
                                    "' --hours " + std::to_string(s.hours));
        const auto newline = out.find('\n');
        ASSERT_NE(newline, std::string::npos) << out;
        const orbit::Tle script = orbit::parse_tle(out.substr(0, newline), out.substr(newline + 1, 69));
        const orbit::Tle mine = orbit::older_set(orbit::parse_tle(s.line1, s.line2), s.hours * 3600.0);
        SCOPED_TRACE(s.line1);
        // The script prints the day to 1e-8 and the angles to 1e-4 deg: half of that is its rounding.
        EXPECT_NEAR(mine.epoch_jd_utc, script.epoch_jd_utc, 0.6e-8);
        EXPECT_EQ(mine.epoch_year, script.epoch_year);
        EXPECT_LE(angle_difference(mine.raan_deg, script.raan_deg), 0.6e-4);
        EXPECT_LE(angle_difference(mine.arg_perigee_deg, script.arg_perigee_deg), 0.6e-4);
        EXPECT_LE(angle_difference(mine.mean_anomaly_deg, script.mean_anomaly_deg), 0.6e-4);
        EXPECT_DOUBLE_EQ(mine.mean_motion_rev_per_day, script.mean_motion_rev_per_day);
        EXPECT_DOUBLE_EQ(mine.eccentricity, script.eccentricity);
        EXPECT_DOUBLE_EQ(mine.inclination_deg, script.inclination_deg);
        EXPECT_DOUBLE_EQ(mine.bstar_per_earth_radius, script.bstar_per_earth_radius);
        EXPECT_EQ(mine.catalog_number, script.catalog_number);
    }
}

TEST(OrbitElementAge, NodeRateIsJ2sClosedForm) {
    // Ω̇ = -3/2 n J2 (R/p)² cos i to first order in J2 (the J2², J4 terms are 1e-3 of it).
    for (const Set& s : kSets) {
        const orbit::Tle t = orbit::parse_tle(s.line1, s.line2);
        const double n = t.mean_motion_rev_per_day * 360.0;  // deg/day (Kozai; the difference is O(J2))
        const double xke = 60.0 / std::sqrt(std::pow(orbit::Wgs72::earth_radius_km, 3) / orbit::Wgs72::mu_km3_s2);
        const double a = std::pow(xke / (t.mean_motion_rev_per_day * 2.0 * kPi / 1440.0), 2.0 / 3.0);
        const double p = a * (1.0 - t.eccentricity * t.eccentricity);
        const double expected = -1.5 * n * orbit::Wgs72::j2 / (p * p) * std::cos(t.inclination_deg * kPi / 180.0);
        EXPECT_NEAR(orbit::secular_rates(t).raan_deg_per_day, expected, 0.01 * std::abs(expected)) << s.line1;
    }
}

TEST(OrbitElementAge, CrossesTheYearBoundary) {
    // 2026 day 1.25 made two days older: 2025 (not a leap year) day 364.25; and back again.
    const orbit::Tle t =
        orbit::parse_tle(with_checksum("1 90001U          26001.25000000  .00002000  00000-0  15000-3 0  999"),
                         with_checksum("2 90001  64.9000   0.0000 0012000  90.0000 270.0000 14.98524078  100"));
    const orbit::Tle older = orbit::older_set(t, 2.0 * 86400.0);
    EXPECT_EQ(older.epoch_year, 2025);
    EXPECT_NEAR(older.epoch_day, 364.25, 1e-9);
    EXPECT_NEAR(older.epoch_jd_utc, t.epoch_jd_utc - 2.0, 1e-9);
    const orbit::Tle back = orbit::reepoched(older, t.epoch_jd_utc);
    EXPECT_EQ(back.epoch_year, 2026);
    EXPECT_NEAR(back.epoch_day, 1.25, 1e-9);
    EXPECT_LE(angle_difference(back.raan_deg, t.raan_deg), 1e-9);
    EXPECT_LE(angle_difference(back.mean_anomaly_deg, t.mean_anomaly_deg), 1e-9);
    // Into a leap year's last day: 2025-01-01 back one day is 2024 day 366.
    const orbit::Tle leap = orbit::reepoched(t, orbit::julian_date_at_midnight(2024, 12, 31) + 0.5);
    EXPECT_EQ(leap.epoch_year, 2024);
    EXPECT_NEAR(leap.epoch_day, 366.5, 1e-9);
}

TEST(OrbitElementAge, NumbersRoundTripAndAreChecked) {
    const orbit::Tle t = orbit::parse_tle(kSets[0].line1, kSets[0].line2);
    const orbit::Tle n = orbit::checked_tle_from_elements(orbit::elements_of(t));
    EXPECT_EQ(n.epoch_year, t.epoch_year);
    EXPECT_NEAR(n.epoch_day, t.epoch_day, 1e-9);
    EXPECT_EQ(n.mean_motion_rev_per_day, t.mean_motion_rev_per_day);
    auto refused = [&](std::size_t k, double value, const char* says) {
        orbit::TleElements e = orbit::elements_of(t);
        e[k] = value;
        try {
            orbit::checked_tle_from_elements(e);
            ADD_FAILURE() << "element " << k + 1 << " = " << value << " accepted";
        } catch (const orbit::TleElementsError& error) {
            EXPECT_EQ(error.element(), static_cast<int>(k + 1));
            EXPECT_NE(std::string(error.what()).find(says), std::string::npos) << error.what();
        }
    };
    refused(0, 2400000.5, "1957-2056");
    refused(1, 0.0, "positive");
    refused(1, 2.0, "SDP4");
    refused(2, 1.0, "[0, 1)");
    refused(3, 181.0, "[0, 180]");
    refused(4, -1.0, "[0, 360]");
    refused(6, NAN, "finite");
}

TEST(OrbitElementPlausibility, OneRuleForTheDate) {
    const orbit::Tle t = orbit::parse_tle(kSets[0].line1, kSets[0].line2);  // 2026-03-20 00:00 UTC
    EXPECT_EQ(orbit::element_set_problem_at(t, t.epoch_jd_utc + 1.0, "the clock"), "");
    EXPECT_EQ(orbit::element_set_problem_at(t, t.epoch_jd_utc - 300.0, "the clock"), "");
    const std::string far = orbit::element_set_problem_at(t, orbit::julian_date_at_midnight(2076, 3, 20), "the clock");
    for (const char* part : {"2026-03-20 00:00:00.000 UTC", "2076-03-20 00:00:00.000 UTC", "the clock", "366 days",
                             "kMaxElementSetAgeDays"})
        EXPECT_NE(far.find(part), std::string::npos) << far;
    // Within the bound, a set SGP4 has decayed by then: 28872 decays 55 min after its epoch.
    const orbit::Tle decaying =
        orbit::parse_tle("1 28872U 05037B   05333.02012661  .25992681  00000-0  24476-3 0  1534",
                         "2 28872  96.4736 157.9986 0303955 244.0492 110.6523 16.46015938 10708");
    EXPECT_EQ(orbit::element_set_problem_at(decaying, decaying.epoch_jd_utc + 50.0 / 1440.0, "t = 0"), "");
    EXPECT_NE(orbit::element_set_problem_at(decaying, decaying.epoch_jd_utc + 1.0, "t = 0").find("decayed"),
              std::string::npos);
    EXPECT_EQ(orbit::format_utc(orbit::julian_date_at_midnight(2026, 12, 31) + (86400.0 - 0.0001) / 86400.0),
              "2027-01-01 00:00:00.000 UTC");
}

}  // namespace
