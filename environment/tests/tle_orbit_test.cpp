// The truth orbit from a TLE: the environment's epoch offset, units and frame around the orbit library
// (whose SGP4 and TEME -> J2000 are checked against python3-sgp4 and ERFA in orbit/tests), the orbit's
// geometry against hand figures, and decay refused with a clear error.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "environment/environment.hpp"
#include "environment/tle_orbit.hpp"
#include "orbit/frames.hpp"
#include "orbit/tle.hpp"

namespace environment {
namespace {

// The bundled synthetic set (environment/README.md): 64.9 deg, 570 km mean altitude, epoch 2026-03-20 00:00.
const char* kLine1 = "1 90001U          26079.00000000  .00002000  00000-0  15000-3 0  9995";
const char* kLine2 = "2 90001  64.9000   0.0000 0012000  90.0000 270.0000 14.98524078  1001";

TEST(EnvironmentCoreTleOrbit, TimeIsCountedFromTheEnvironmentsEpoch) {
    const orbit::Tle tle = orbit::parse_tle(kLine1, kLine2);
    // The set's epoch is day 79.0 of 2026, 2026-03-20 00:00 UTC; the environment starts one day and 90 s later.
    const UtcDate epoch{2026, 3, 21, 0, 1, 30.0};
    const double jd0 = julian_date(epoch);
    const TleOrbit o(tle, epoch);
    EXPECT_NEAR(o.minutes_from_tle_epoch(), 1441.5, 1e-12);
    orbit::Sgp4<double> sgp4;
    ASSERT_EQ(sgp4.initialize(tle.mean_elements<double>()), orbit::Sgp4Status::ok);
    for (double t : {0.0, 600.0, 5000.0}) {
        orbit::OrbitState<double> teme;
        ASSERT_EQ(sgp4.propagate(1441.5 + t / 60.0, teme), orbit::Sgp4Status::ok);
        const orbit::OrbitState<double> j2000 = orbit::teme_to_j2000(teme, orbit::julian_centuries(jd0 + t / 86400.0));
        const TleOrbit::State x = o.state_eci(t);
        EXPECT_LT((x.position - 1000.0 * j2000.position_km).norm(), 1e-6) << t;  // metres
        EXPECT_LT((x.velocity - 1000.0 * j2000.velocity_km_s).norm(), 1e-9) << t;
    }
}

TEST(EnvironmentCoreTleOrbit, GeometryOfTheBundledSet) {
    const orbit::Tle tle = orbit::parse_tle(kLine1, kLine2);
    const TleOrbit o(tle, UtcDate{2026, 3, 20, 0, 0, 0.0});
    // Period from SGP4's un-Kozai'd mean motion: the set's mean motion was chosen to match the circular
    // 570 km orbit's 2 pi sqrt(a^3 / mu) = 5763.86 s (hand calculation); the Kozai figure 1440 / 14.98524078
    // = 96.095 min = 5765.7 s differs by J2's correction at 64.9 deg.
    EXPECT_NEAR(o.period(), 5763.86, 6.0);
    double r_mean = 0.0;
    int n = 0;
    for (double t = 0.0; t < o.period(); t += 10.0, ++n) {
        const TleOrbit::State x = o.state_eci(t);
        r_mean += x.position.norm();
        // Angular momentum: the orbit plane's inclination to the J2000 equator is the set's 64.9 deg, moved
        // by at most the precession of the pole since 2000 (theta = 2004" per century: 0.15 deg by 2026).
        const Eigen::Vector3d h = x.position.cross(x.velocity).normalized();
        EXPECT_NEAR(std::acos(h.z()) * 180.0 / std::numbers::pi, 64.9, 0.16) << t;
        // Vis-viva for a near-circular orbit: |v| within 0.2 % of sqrt(mu / r).
        EXPECT_NEAR(x.velocity.norm(), std::sqrt(3.986004418e14 / x.position.norm()), 0.002 * x.velocity.norm());
    }
    r_mean /= n;
    // Mean altitude: the set's mean motion was chosen for 570 km; e = 0.0012 and J2's short-period terms
    // move the instantaneous radius by about +-15 km, their mean by far less.
    EXPECT_NEAR(r_mean - 6378137.0, 570e3, 5e3);
}

TEST(EnvironmentCoreTleOrbit, DecayIsRefusedNamingTheTime) {
    // 28872 of the verification set (Vallado et al. 2006) decays 55 min after its epoch.
    const orbit::Tle tle = orbit::parse_tle("1 28872U 05037B   05333.02012661  .25992681  00000-0  24476-3 0  1534",
                                            "2 28872  96.4736 157.9986 0303955 244.0492 110.6523 16.46015938 10708");
    const TleOrbit o(tle, UtcDate{2005, 11, 29, 0, 28, 58.94});  // day 333.02012661 of 2005
    EXPECT_NO_THROW(o.state_eci(50.0 * 60.0));
    try {
        o.state_eci(60.0 * 60.0);
        FAIL() << "a decayed orbit was propagated";
    } catch (const std::domain_error& e) {
        EXPECT_NE(std::string(e.what()).find("decayed"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("3600"), std::string::npos) << e.what();
    }
}

TEST(EnvironmentCoreTleOrbit, EnvironmentNeedsAnElementSetForTheTleOrbit) {
    EnvironmentParams p;
    p.orbit_model = OrbitModel::tle;  // no set given
    EXPECT_THROW(Environment{p}, std::invalid_argument);
    p.tle = orbit::parse_tle(kLine1, kLine2);
    const Environment env(p);
    EXPECT_NEAR(env.orbit_period(), 5763.86, 6.0);
}

}  // namespace
}  // namespace environment
