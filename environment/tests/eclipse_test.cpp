#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "environment/circular_orbit.hpp"
#include "environment/constants.hpp"
#include "environment/eclipse.hpp"

namespace env = environment;

TEST(EnvironmentCoreEclipse, LitUmbraAndSmoothPenumbra) {
    const Eigen::Vector3d sun = env::kAstronomicalUnit * Eigen::Vector3d::UnitX();
    const double r = 6948137.0;
    EXPECT_DOUBLE_EQ(env::sunlight_fraction(Eigen::Vector3d(r, 0, 0), sun), 1.0);
    EXPECT_DOUBLE_EQ(env::sunlight_fraction(Eigen::Vector3d(0, r, 0), sun), 1.0);
    EXPECT_DOUBLE_EQ(env::sunlight_fraction(Eigen::Vector3d(-r, 0, 0), sun), 0.0);
    // Sweep the satellite across the shadow boundary behind the Earth: nu goes monotonically from 0 to 1
    // through intermediate values (the penumbra), with no jump larger than the step warrants.
    double previous = 0.0;
    int partial = 0;
    for (double y = 6.30e6; y <= 6.45e6; y += 500.0) {
        const double x = -std::sqrt(r * r - y * y);
        const double nu = env::sunlight_fraction(Eigen::Vector3d(x, y, 0), sun);
        EXPECT_GE(nu, previous - 1e-15);
        EXPECT_LT(nu - previous, 0.05);
        if (nu > 0.0 && nu < 1.0) ++partial;
        previous = nu;
    }
    EXPECT_DOUBLE_EQ(previous, 1.0);
    EXPECT_GT(partial, 10);
}

TEST(EnvironmentCoreEclipse, OrbitEclipseFractionMatchesBetaAngleFormula) {
    // Closed form for a circular orbit and a cylindrical shadow (e.g. Wertz, Space Mission Analysis and
    // Design, eclipse fraction): f = (1/pi) acos( sqrt(h^2 + 2 R h) / ((R + h) cos beta) ), |beta| < beta*.
    // The conical model's umbra + half its penumbra equals the cylinder to within the penumbra's asymmetry,
    // so the integrated shadow fraction (1 - nu) must agree to a few seconds per orbit.
    const double R = env::kEarthRadius, h = 570.0e3;
    for (double beta_deg : {0.0, 20.0, 45.0, 60.0, 70.0}) {
        env::OrbitParams p;
        p.inclination = 64.9 * env::kDegToRad;
        const env::CircularOrbit orbit(p);
        // Put the sun at angle beta above the orbit plane (fixed over the orbit).
        const Eigen::Vector3d nrm = orbit.orbit_normal();
        const Eigen::Vector3d in_plane = orbit.position_eci(0.0).normalized();
        const double beta = beta_deg * env::kDegToRad;
        const Eigen::Vector3d sun = env::kAstronomicalUnit * (std::cos(beta) * in_plane + std::sin(beta) * nrm);
        const int steps = 200000;
        const double dt = orbit.period() / steps;
        double shadow = 0.0;
        for (int k = 0; k < steps; ++k) shadow += 1.0 - env::sunlight_fraction(orbit.position_eci((k + 0.5) * dt), sun);
        const double f_numeric = shadow / steps;
        const double arg = std::sqrt(h * h + 2.0 * R * h) / ((R + h) * std::cos(beta));
        const double f_closed = arg >= 1.0 ? 0.0 : std::acos(arg) / env::kPi;
        EXPECT_NEAR(f_numeric, f_closed, 5.0 / orbit.period()) << "beta = " << beta_deg << " deg";
        std::printf("beta %4.0f deg: eclipse fraction conical %.6f, closed form %.6f (diff %.2f s/orbit)\n", beta_deg,
                    f_numeric, f_closed, (f_numeric - f_closed) * orbit.period());
    }
}
