#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "environment/circular_orbit.hpp"
#include "environment/constants.hpp"
#include "environment/sun_ephemeris.hpp"
#include "environment/time_scales.hpp"

namespace env = environment;

TEST(EnvironmentCoreOrbit, CircularOrbitGeometry) {
    env::OrbitParams p;  // 570 km, 64.9 deg
    p.raan = 0.4;
    p.argument_of_latitude0 = 1.1;
    const env::CircularOrbit orbit(p);
    const double a = 6378137.0 + 570.0e3;
    // Kepler's third law by hand: T = 2 pi sqrt(a^3/mu) = 5763.86 s for a = 6948.137 km.
    EXPECT_NEAR(orbit.period(), 2.0 * env::kPi * std::sqrt(a * a * a / 3.986004418e14), 1e-9);
    EXPECT_NEAR(orbit.period(), 5763.86, 0.01);
    double max_z = 0.0;
    for (double t = 0.0; t < orbit.period(); t += 7.3) {
        const Eigen::Vector3d r = orbit.position_eci(t);
        const Eigen::Vector3d v = orbit.velocity_eci(t);
        EXPECT_NEAR(r.norm(), a, 1e-6);
        EXPECT_NEAR(v.norm(), std::sqrt(3.986004418e14 / a), 1e-9);
        EXPECT_NEAR(r.dot(v) / (r.norm() * v.norm()), 0.0, 1e-12);
        // velocity is the derivative of position (central difference)
        const Eigen::Vector3d v_fd = (orbit.position_eci(t + 0.01) - orbit.position_eci(t - 0.01)) / 0.02;
        EXPECT_LT((v_fd - v).norm(), 1e-4);
        max_z = std::max(max_z, r.z());
    }
    // Highest latitude reached equals the inclination.
    EXPECT_NEAR(max_z / a, std::sin(64.9 * env::kDegToRad), 1e-5);
    EXPECT_LT((orbit.position_eci(orbit.period()) - orbit.position_eci(0.0)).norm(), 1e-6);
    EXPECT_THROW(env::CircularOrbit(env::OrbitParams{-1.0, 0.0, 0.0, 0.0}), std::invalid_argument);
}

TEST(EnvironmentCoreSun, MatchesMeeusExample25a) {
    // Meeus, Astronomical Algorithms (2nd ed.), example 25.a: 1992 October 13.0 TD (JDE 2448908.5):
    // apparent right ascension 198.38083 deg, declination -7.78507 deg, distance R = 0.99766 AU.
    // The almanac formula's stated accuracy is 0.01 deg; the example's aberration and nutation are 0.006 deg.
    const env::SunPosition s = env::sun_almanac(2448908.5);
    EXPECT_NEAR(env::right_ascension(s.direction_eci) * env::kRadToDeg, 198.38083, 0.02);
    EXPECT_NEAR(env::declination(s.direction_eci) * env::kRadToDeg, -7.78507, 0.02);
    EXPECT_NEAR(s.distance / env::kAstronomicalUnit, 0.99766, 2e-4);
}

TEST(EnvironmentCoreSun, J2000SunIsTheAlmanacSunWithoutThePrecessionSince2000) {
    // Independent reference (a Python script, not this code): the almanac's ecliptic longitude of date minus
    // the IAU 1976 general precession in longitude 5029.0966" T, on the J2000 ecliptic (obliquity
    // 23.4392911 deg). That method neglects the motion of the ecliptic itself (0.47"/yr: 0.004 deg by 2026).
    // 2026-01-01 0h (JD 2461041.5): (0.177163610, -0.902968793, -0.391484884), 0.3632 deg from of-date;
    // 2026-07-01 0h (JD 2461222.5): (-0.153572079, 0.906598384, 0.393058504), 0.3702 deg from of-date.
    struct Case {
        double jd;
        Eigen::Vector3d j2000;
        double from_date_deg;
    };
    const Case cases[] = {{2461041.5, {0.177163610, -0.902968793, -0.391484884}, 0.3632},
                          {2461222.5, {-0.153572079, 0.906598384, 0.393058504}, 0.3702}};
    for (const Case& c : cases) {
        const Eigen::Vector3d j = env::sun_almanac_j2000(c.jd).direction_eci;
        const Eigen::Vector3d d = env::sun_almanac(c.jd).direction_eci;
        EXPECT_LT(std::acos(std::min(1.0, j.dot(c.j2000.normalized()))) * env::kRadToDeg, 0.005) << c.jd;
        EXPECT_NEAR(std::acos(std::min(1.0, j.dot(d))) * env::kRadToDeg, c.from_date_deg, 0.005) << c.jd;
        EXPECT_NEAR(j.norm(), 1.0, 1e-14);
        EXPECT_EQ(env::sun_almanac_j2000(c.jd).distance, env::sun_almanac(c.jd).distance);
    }
}

TEST(EnvironmentCoreSun, DeclinationAtEquinoxesAndSolstices2024) {
    // US Naval Observatory, "Earth's Seasons" 2024 (UTC): March equinox Mar 20 03:06, June solstice
    // Jun 20 20:51, September equinox Sep 22 12:44, December solstice Dec 21 09:20. Declination there:
    // 0 at the equinoxes, +/- the obliquity (23.436 deg in 2024) at the solstices. The sun's declination
    // moves 0.016 deg/h at the equinoxes, so minute-rounded times add < 0.001 deg.
    struct Case {
        env::UtcDate date;
        double declination_deg;
    };
    const Case cases[] = {{{2024, 3, 20, 3, 6, 0.0}, 0.0},
                          {{2024, 6, 20, 20, 51, 0.0}, 23.436},
                          {{2024, 9, 22, 12, 44, 0.0}, 0.0},
                          {{2024, 12, 21, 9, 20, 0.0}, -23.436}};
    for (const Case& c : cases) {
        const env::SunPosition s = env::sun_almanac(env::julian_date(c.date));
        EXPECT_NEAR(env::declination(s.direction_eci) * env::kRadToDeg, c.declination_deg, 0.02)
            << c.date.year << "-" << c.date.month << "-" << c.date.day;
    }
    // Perihelion 2024 Jan 3 (0.98331 AU), aphelion 2024 Jul 5 (1.01673 AU), USNO.
    EXPECT_NEAR(env::sun_almanac(env::julian_date({2024, 1, 3, 0, 39, 0.0})).distance / env::kAstronomicalUnit, 0.98331,
                2e-4);
    EXPECT_NEAR(env::sun_almanac(env::julian_date({2024, 7, 5, 5, 6, 0.0})).distance / env::kAstronomicalUnit, 1.01673,
                2e-4);
}

TEST(EnvironmentCoreSun, Seed002ModelByHand) {
    // Seed 002 eq. 21-23 evaluated by hand: T = 0 -> (1, 0, 0); T = 365/4 days -> lambda = 90 deg,
    // elevation = amplitude -> (0, cos A, sin A); T = 365/2 -> (-1, 0, 0).
    const double jd_eq = 2461120.0;
    const double amp = 23.439 * env::kDegToRad;
    auto s = [&](double days) { return env::sun_seed002(jd_eq + days, jd_eq, amp).direction_eci; };
    EXPECT_LT((s(0.0) - Eigen::Vector3d(1, 0, 0)).norm(), 1e-15);
    EXPECT_LT((s(365.0 / 4.0) - Eigen::Vector3d(0, std::cos(amp), std::sin(amp))).norm(), 1e-14);
    EXPECT_LT((s(365.0 / 2.0) - Eigen::Vector3d(-1, 0, 0)).norm(), 1e-14);
    // The printed amplitude 2 pi/180 rad gives a 2 deg maximum elevation.
    EXPECT_NEAR(env::declination(env::sun_seed002(jd_eq + 365.0 / 4.0, jd_eq, 2.0 * env::kPi / 180.0).direction_eci),
                2.0 * env::kDegToRad, 1e-14);
    // With the obliquity as amplitude it tracks the almanac sun only to a few degrees over a year. Budget
    // (hand): no eccentricity (equation of centre up to 1.9 deg; the September equinox comes 186 days, not
    // 182.5, after March's: 3.4 deg of azimuth) plus azimuth taken along the equator instead of the
    // ecliptic (right ascension minus longitude up to 2.5 deg): at most about 6.5 deg.
    const double jd_equinox_2026 = env::julian_date({2026, 3, 20, 14, 46, 0.0});  // USNO
    double worst = 0.0;
    for (double d = 0.0; d < 365.0; d += 1.0) {
        const Eigen::Vector3d a = env::sun_almanac(jd_equinox_2026 + d).direction_eci;
        const Eigen::Vector3d b = env::sun_seed002(jd_equinox_2026 + d, jd_equinox_2026, amp).direction_eci;
        worst = std::max(worst, std::acos(std::min(1.0, a.dot(b))) * env::kRadToDeg);
    }
    EXPECT_LT(worst, 6.5);
    std::printf("seed 002 sun model vs almanac over 2026: worst %.2f deg\n", worst);
}
