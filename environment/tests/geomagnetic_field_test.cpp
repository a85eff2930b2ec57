#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "environment/constants.hpp"
#include "environment/geomagnetic_field.hpp"
#include "ground/igrf_coefficients.hpp"

namespace env = environment;

namespace {
// North (X), east (Y), down (Z) components in nT at geocentric colatitude/longitude (deg), radius r (m).
Eigen::Vector3d xyz_nt(const Eigen::Vector3d& b_ecef_tesla, double colat_deg, double lon_deg) {
    const double t = colat_deg * env::kDegToRad, p = lon_deg * env::kDegToRad;
    const Eigen::Vector3d e_r(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
    const Eigen::Vector3d e_t(std::cos(t) * std::cos(p), std::cos(t) * std::sin(p), -std::sin(t));
    const Eigen::Vector3d e_p(-std::sin(p), std::cos(p), 0.0);
    const Eigen::Vector3d b = b_ecef_tesla * 1e9;
    return {-b.dot(e_t), b.dot(e_p), -b.dot(e_r)};
}
Eigen::Vector3d position(double colat_deg, double lon_deg, double r) {
    const double t = colat_deg * env::kDegToRad, p = lon_deg * env::kDegToRad;
    return r * Eigen::Vector3d(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
}
}  // namespace

TEST(EnvironmentCoreIgrf, CoefficientTableHasThePublishedValues) {
    // IGRF-14 (IAGA V-MOD 2024) as published in igrf14coeffs.txt: g10(2025) = -29350.0 nT, SV +12.6 nT/yr;
    // g11 = -1410.3, SV +10.0; h11 = 4545.5, SV -21.5.
    const env::GaussCoefficients c2025 = env::igrf_coefficients(2025.0);
    EXPECT_DOUBLE_EQ(c2025.g[1][0], -29350.0);
    EXPECT_DOUBLE_EQ(c2025.g[1][1], -1410.3);
    EXPECT_DOUBLE_EQ(c2025.h[1][1], 4545.5);
    const env::GaussCoefficients c = env::igrf_coefficients(2027.5);
    EXPECT_NEAR(c.g[1][0], -29350.0 + 2.5 * 12.6, 1e-9);
    EXPECT_NEAR(c.g[1][1], -1410.3 + 2.5 * 10.0, 1e-9);
    EXPECT_NEAR(c.h[1][1], 4545.5 - 2.5 * 21.5, 1e-9);
    EXPECT_EQ(ground::kIgrf14Coefficients.size(), 195u);
    EXPECT_THROW(env::igrf_coefficients(2024.99), std::domain_error);
    EXPECT_THROW(env::igrf_coefficients(2030.01), std::domain_error);
}

TEST(EnvironmentCoreIgrf, MatchesBgsReferenceValue) {
    // BGS reference program pyIGRF (github.com/ciaranbe/pyIGRF, tests/tests_igrf14.py, "checked
    // independently against igrf.f"): 2025.0, geocentric colatitude 90 deg, longitude 45 deg,
    // r = 6900 km -> X = 25587.26, Y = -826.43, Z = -7422.32 nT.
    const Eigen::Vector3d b =
        env::spherical_harmonic_field(env::igrf_coefficients(2025.0), 13, position(90.0, 45.0, 6900.0e3));
    const Eigen::Vector3d xyz = xyz_nt(b, 90.0, 45.0);
    EXPECT_NEAR(xyz.x(), 25587.26, 10.0);
    EXPECT_NEAR(xyz.y(), -826.43, 10.0);
    EXPECT_NEAR(xyz.z(), -7422.32, 10.0);
    std::printf("IGRF vs BGS reference: dX %.3f dY %.3f dZ %.3f nT\n", xyz.x() - 25587.26, xyz.y() + 826.43,
                xyz.z() + 7422.32);
}

TEST(EnvironmentCoreIgrf, MatchesCalculatorValuesOnTheEquator) {
    // Reference values at 2025.03288 (2025-01-13), latitude 0, longitude 0, for altitudes 500 km and 0 km
    // above the WGS-84 ellipsoid (on the equator geodetic = geocentric and r = 6378.137 km + altitude),
    // rounded to 0.1 nT, as listed in a public pyIGRF comparison script (code index id 18997043349):
    //   500 km: X 21550.0, Y -1684.8, Z -10816.4;   0 km: X 27455.6, Y -1924.6, Z -15996.8 nT.
    struct Case {
        double altitude, x, y, z;
    };
    for (const Case& k : {Case{500.0e3, 21550.0, -1684.8, -10816.4}, Case{0.0, 27455.6, -1924.6, -15996.8}}) {
        const Eigen::Vector3d b = env::spherical_harmonic_field(env::igrf_coefficients(2025.03288), 13,
                                                                position(90.0, 0.0, 6378137.0 + k.altitude));
        const Eigen::Vector3d xyz = xyz_nt(b, 90.0, 0.0);
        EXPECT_NEAR(xyz.x(), k.x, 10.0);
        EXPECT_NEAR(xyz.y(), k.y, 10.0);
        EXPECT_NEAR(xyz.z(), k.z, 10.0);
        std::printf("IGRF vs calculator at %.0f km: dX %.2f dY %.2f dZ %.2f nT\n", k.altitude / 1e3, xyz.x() - k.x,
                    xyz.y() - k.y, xyz.z() - k.z);
    }
}

TEST(EnvironmentCoreIgrf, FiniteAndContinuousAtThePoles) {
    const env::GaussCoefficients c = env::igrf_coefficients(2026.0);
    const Eigen::Vector3d at_pole = env::spherical_harmonic_field(c, 13, Eigen::Vector3d(0, 0, 6948137.0));
    const Eigen::Vector3d near_pole = env::spherical_harmonic_field(c, 13, position(1e-6, 30.0, 6948137.0));
    ASSERT_TRUE(at_pole.allFinite());
    // 1e-6 deg of colatitude is 0.12 m: the field gradient (~3B/r) allows ~2e-12 T of difference.
    EXPECT_LT((at_pole - near_pole).norm(), 1e-10);
}

TEST(EnvironmentCoreDipole, MagnitudeAtEquatorAndPoleFollowsB0) {
    // B0 from the published 2025 degree-1 coefficients (hand): sqrt(29350.0^2 + 1410.3^2 + 4545.5^2)
    // = 29733.3 nT; the dipole axis direction is (g11, h11, g10)/B0.
    const double b0 = std::sqrt(29350.0 * 29350.0 + 1410.3 * 1410.3 + 4545.5 * 4545.5) * 1e-9;
    EXPECT_NEAR(b0, 29733.3e-9, 0.1e-9);
    const Eigen::Vector3d m = Eigen::Vector3d(-1410.3, 4545.5, -29350.0).normalized();
    const env::GaussCoefficients c = env::igrf_coefficients(2025.0);
    for (double r : {6371.2e3, 6948.137e3}) {
        const double scale = std::pow(6371.2e3 / r, 3);
        // On the dipole axis: |B| = 2 B0 (a/r)^3; at the geomagnetic north pole (-m side) B points down.
        const Eigen::Vector3d north = -m * r;
        const Eigen::Vector3d b_north = env::dipole_field(c, north);
        EXPECT_NEAR(b_north.norm(), 2.0 * b0 * scale, 1e-12 * b0);
        EXPECT_LT(b_north.dot(north), 0.0);
        EXPECT_NEAR(env::dipole_field(c, m * r).norm(), 2.0 * b0 * scale, 1e-12 * b0);
        // On the dipole equator: |B| = B0 (a/r)^3, parallel to the axis, pointing north (along -m).
        const Eigen::Vector3d eq = m.unitOrthogonal() * r;
        const Eigen::Vector3d b_eq = env::dipole_field(c, eq);
        EXPECT_NEAR(b_eq.norm(), b0 * scale, 1e-12 * b0);
        EXPECT_NEAR(b_eq.normalized().dot(-m), 1.0, 1e-12);
    }
}

TEST(EnvironmentCoreDipole, EqualsDegreeOneSynthesis) {
    // Two independent formulas for the same field: the closed-form dipole and the n = 1 harmonic sum.
    const env::GaussCoefficients c = env::igrf_coefficients(2026.3);
    for (const Eigen::Vector3d& r :
         {position(33.0, -120.0, 6.9e6), position(120.0, 75.0, 7.2e6), position(90.0, 0.0, 6.5e6)}) {
        const Eigen::Vector3d a = env::dipole_field(c, r);
        const Eigen::Vector3d b = env::spherical_harmonic_field(c, 1, r);
        EXPECT_LT((a - b).norm(), 1e-12 * a.norm());
    }
}
