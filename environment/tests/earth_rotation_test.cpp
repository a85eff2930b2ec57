#include <gtest/gtest.h>

#include <cmath>

#include "environment/constants.hpp"
#include "environment/earth_rotation.hpp"
#include "environment/time_scales.hpp"

namespace env = environment;

TEST(EnvironmentCoreEarthRotation, PrecessionAnglesMatchVallado) {
    // Vallado, Fundamentals of Astrodynamics and Applications, example 3-15: 2004 April 6, 07:51:28.386009
    // UTC, TT = UTC + 64.184 s, JD_TT = 2453101.828154745: zeta = 0.0273055, theta = 0.0237306,
    // z = 0.0273059 deg.
    const Eigen::Vector3d a = env::precession_angles(2453101.828154745) * env::kRadToDeg;
    EXPECT_NEAR(a.x(), 0.0273055, 2e-7);
    EXPECT_NEAR(a.y(), 0.0273059, 2e-7);
    EXPECT_NEAR(a.z(), 0.0237306, 2e-7);
}

TEST(EnvironmentCoreEarthRotation, AtJ2000OnlyGmstRemains) {
    // At J2000.0 precession is zero and GMST = 280.46061837 deg (IAU 1982, the constant term of the
    // GMST series in degrees), so the ECI direction at right ascension GMST is the Greenwich meridian.
    const double g = 280.46061837 * env::kDegToRad;
    const Eigen::Vector3d greenwich =
        env::ecef_from_eci(env::kJulianDateJ2000) * Eigen::Vector3d(std::cos(g), std::sin(g), 0.0);
    EXPECT_LT((greenwich - Eigen::Vector3d::UnitX()).norm(), 1e-9);
}

TEST(EnvironmentCoreEarthRotation, RotationIsProperAndPrecessesThePole) {
    const double jd = env::julian_date({2026, 3, 20, 0, 0, 0.0});
    const Eigen::Matrix3d m = env::ecef_from_eci(jd);
    EXPECT_LT((m * m.transpose() - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-14);
    EXPECT_NEAR(m.determinant(), 1.0, 1e-14);
    // The mean pole of date moves from the J2000 pole by theta ~ 2004.3" per century: 26.2 yr -> 0.146 deg.
    const Eigen::Vector3d pole_of_date_in_eci = env::precession_matrix(jd).transpose() * Eigen::Vector3d::UnitZ();
    const double t = (jd - env::kJulianDateJ2000) / 36525.0;
    EXPECT_NEAR(std::acos(pole_of_date_in_eci.z()) * env::kRadToDeg, 2004.3109 * t / 3600.0, 1e-5);
}
