// orbit/orbit_classes.hpp against closed forms and published figures.
#include <gtest/gtest.h>

#include <cmath>

#include "orbit/calendar.hpp"
#include "orbit/element_age.hpp"
#include "orbit/orbit_classes.hpp"
#include "orbit/sgp4.hpp"

namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(OrbitClasses, SunSynchronousInclination) {
    // J2 alone: cos i = -2 ρ a^{7/2} / (3 J2 R² √μ), ρ the mean sun's rate.
    for (double altitude : {400.0, 550.0, 800.0}) {
        const double a = orbit::Wgs72::earth_radius_km + altitude;
        const double rho = orbit::kMeanSunRateDegPerDay * kPi / 180.0 / 86400.0;  // rad/s
        const double closed = std::acos(-2.0 * rho * std::pow(a, 3.5) /
                                        (3.0 * orbit::Wgs72::j2 * std::pow(orbit::Wgs72::earth_radius_km, 2) *
                                         std::sqrt(orbit::Wgs72::mu_km3_s2))) *
                              180.0 / kPi;
        // SGP4's J2², J4 terms and the Kozai/Brouwer mean motions move it by a few hundredths of a degree.
        EXPECT_NEAR(orbit::sun_synchronous_inclination_deg(altitude), closed, 0.05) << altitude;
    }
    EXPECT_NEAR(orbit::sun_synchronous_inclination_deg(550.0), 97.6, 0.05);
    // The node of the set made from it turns with the mean sun.
    const orbit::Tle sso = orbit::sun_synchronous_set(orbit::julian_date_at_midnight(2026, 6, 1), 550.0, 10.5, 0.0);
    EXPECT_NEAR(orbit::secular_rates(sso).raan_deg_per_day, orbit::kMeanSunRateDegPerDay, 1e-6);
}

TEST(OrbitClasses, AltitudeIsSgp4sMeanAxis) {
    for (double inclination : {20.0, 51.6, 97.6}) {
        const orbit::Tle t = orbit::circular_orbit_set(2461120.5, 420.0, inclination, 10.0, 20.0, 1e-4);
        orbit::Sgp4<double> sgp4;
        ASSERT_EQ(sgp4.initialize(t.mean_elements<double>()), orbit::Sgp4Status::ok);
        EXPECT_NEAR(sgp4.semi_major_axis_km(), orbit::Wgs72::earth_radius_km + 420.0, 1e-6) << inclination;
        // Kepler's period at that axis, to the J2 correction of the mean motion (~0.1 %).
        const double a = orbit::Wgs72::earth_radius_km + 420.0;
        EXPECT_NEAR(sgp4.period_minutes(), 2.0 * kPi * std::sqrt(a * a * a / orbit::Wgs72::mu_km3_s2) / 60.0, 0.1);
    }
    EXPECT_THROW(orbit::circular_orbit_set(2461120.5, 50.0, 51.6, 0.0, 0.0), std::invalid_argument);
}

TEST(OrbitClasses, LocalTimeOfTheNode) {
    // At the 2026 March equinox (20 March 14:46 UTC) the true sun's right ascension is 0; the mean sun's
    // differs by the equation of time, -7.4 min that day (the sundial slow): 360 - 1.85 deg.
    const double equinox = orbit::julian_date_at_midnight(2026, 3, 20) + (14.0 * 60.0 + 46.0) / 1440.0;
    EXPECT_NEAR(orbit::mean_sun_right_ascension_deg(equinox), 360.0 - 7.4 * 0.25, 0.1);
    // A 6 h (dawn) node then lies 90 deg west of the sun: the orbit plane is the terminator's.
    EXPECT_NEAR(orbit::raan_for_ltan_deg(6.0, equinox), 270.0 - 1.85, 0.1);
    EXPECT_NEAR(orbit::raan_for_ltan_deg(12.0, equinox), 358.15, 0.1);  // noon: towards the (mean) sun
    // Recovered from the node and the sun's right ascension, any time of day and date.
    for (double ltan : {0.0, 6.0, 10.5, 13.75, 22.0})
        for (double jd : {2461041.5, 2461200.25, 2461400.75})
            EXPECT_NEAR(orbit::ltan_hours(orbit::raan_for_ltan_deg(ltan, jd), jd), ltan, 1e-9);
    EXPECT_THROW(orbit::raan_for_ltan_deg(24.0, equinox), std::invalid_argument);
}

}  // namespace
