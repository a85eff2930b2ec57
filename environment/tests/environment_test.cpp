#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "environment/attitude.hpp"
#include "environment/constants.hpp"
#include "environment/environment.hpp"

namespace env = environment;

namespace {
Eigen::Vector3d v3(const std::array<double, 3>& a) {
    return {a[0], a[1], a[2]};
}
}  // namespace

TEST(EnvironmentCoreEnvironment, DefaultsGiveConsistentOutputs) {
    const env::Environment e(env::EnvironmentParams{});
    for (double t : {0.0, 1.5, 600.0, 3000.0}) {
        const env::EnvironmentOutputs o = e.evaluate(t);
        const Eigen::Matrix3d A = env::attitude_matrix(o.q_true);
        EXPECT_NEAR(v3(o.sun_eci).norm(), 1.0, 1e-14);
        EXPECT_LT((A * v3(o.sun_eci) - v3(o.sun_body)).norm(), 1e-12);
        EXPECT_LT((A * v3(o.mag_eci) - v3(o.mag_body)).norm(), 1e-9 * v3(o.mag_eci).norm());
        EXPECT_NEAR(v3(o.r_eci).norm(), env::kEarthRadius + 570.0e3, 1e-6);
        // At 570 km the main field is between about 18 and 55 uT everywhere (dipole bound B0 (a/r)^3 .. 2 B0 (a/r)^3
        // = 22.2 .. 44.4 uT, with non-dipole terms up to about 25 %).
        EXPECT_GT(v3(o.mag_eci).norm(), 15e-6);
        EXPECT_LT(v3(o.mag_eci).norm(), 60e-6);
        // Irradiance: 1367 W/m^2 scaled to the March distance (~0.996 AU) when lit.
        if (o.sunlight_fraction == 1.0) {
            EXPECT_NEAR(o.irradiance, 1367.0 / std::pow(o.sun_distance / env::kAstronomicalUnit, 2), 1e-9);
            EXPECT_NEAR(o.irradiance, 1378.0, 6.0);
        }
        for (double a : o.albedo_face) EXPECT_GE(a, 0.0);
    }
}

TEST(EnvironmentCoreEnvironment, SpinModeFollowsSeedFormulaWithMovingSun) {
    // The sun seen from the satellite moves by parallax (< 5e-5 rad) and by the Earth's orbital motion
    // (2e-7 rad/s) relative to the epoch direction the spin attitude is built on.
    const env::Environment e(env::EnvironmentParams{});
    for (double t : {0.0, 0.5, 2.0, 30.0, 100.0}) {
        const env::EnvironmentOutputs o = e.evaluate(t);
        const double phi = 1.26 * t, theta = 6.28 * t;  // seed 000 section 4
        const Eigen::Vector3d seed(std::sin(phi) * std::sin(theta), std::cos(phi) * std::sin(theta), std::cos(theta));
        EXPECT_LT((v3(o.sun_body) - seed).norm(), 1e-4 + 2e-7 * t) << "t = " << t;
        EXPECT_NEAR(v3(o.omega_body).norm(), std::hypot(1.26, 6.28), 1e-12);
    }
}

TEST(EnvironmentCoreEnvironment, RigidBodyModeUsesTheState) {
    env::EnvironmentParams p;
    p.attitude_mode = env::AttitudeMode::rigid_body;
    const env::Environment e(p);
    EXPECT_THROW(e.evaluate(0.0), std::invalid_argument);
    env::RigidBodyState x = e.initial_state();
    const env::EnvironmentOutputs o = e.evaluate(0.0, &x);
    for (int i = 0; i < 4; ++i) EXPECT_DOUBLE_EQ(o.q_true[i], x[i]);
    for (int i = 0; i < 3; ++i) EXPECT_DOUBLE_EQ(o.omega_body[i], x[4 + i]);
    x[2] = std::nan("");
    EXPECT_THROW(e.evaluate(0.0, &x), std::invalid_argument);
}

TEST(EnvironmentCoreEnvironment, RejectsBadParametersAndDates) {
    env::EnvironmentParams p;
    p.epoch = {2013, 5, 10, 0, 0, 0.0};  // seed 004's flight date: before IGRF-14's 2025-2030
    EXPECT_THROW(env::Environment{p}, std::domain_error);
    p = env::EnvironmentParams{};
    p.albedo.reflectivity = 1.5;
    EXPECT_THROW(env::Environment{p}, std::invalid_argument);
    p = env::EnvironmentParams{};
    p.orbit.altitude = 0.0;
    EXPECT_THROW(env::Environment{p}, std::invalid_argument);
    const env::Environment ok(env::EnvironmentParams{});
    EXPECT_THROW(ok.evaluate(std::nan("")), std::invalid_argument);
}

TEST(EnvironmentCoreEnvironment, EclipseZeroesIrradianceButNotAlbedoSwitch) {
    // Over one orbit of the default scenario (beta ~ 20 deg in March with RAAN 0) there is an eclipse:
    // irradiance 0 in the umbra, full sun elsewhere, and the albedo can be switched off.
    env::EnvironmentParams p;
    p.albedo.enabled = false;
    const env::Environment e(p);
    int dark = 0, lit = 0;
    for (double t = 0.0; t < 5766.0; t += 30.0) {
        const env::EnvironmentOutputs o = e.evaluate(t);
        if (o.sunlight_fraction == 0.0) {
            ++dark;
            EXPECT_DOUBLE_EQ(o.irradiance, 0.0);
        }
        if (o.sunlight_fraction == 1.0) ++lit;
        for (double a : o.albedo_face) EXPECT_DOUBLE_EQ(a, 0.0);
    }
    EXPECT_GT(dark, 0);
    EXPECT_GT(lit, dark);
}

TEST(EnvironmentCoreEnvironment, TheDirectSunOnTheFacesIsTheIrradianceOnTheLitHalfOfTheCube) {
    // A unit cube's faces see the sun along ±x, ±y, ±z: of each opposite pair one is lit by |s_i| of the
    // irradiance and the other not, so the six add up to (|s_x| + |s_y| + |s_z|) E, between E and √3 E; in the
    // umbra all are 0.
    const env::Environment e(env::EnvironmentParams{});
    int dark = 0;
    for (double t = 0.0; t < 5766.0; t += 30.0) {
        const env::EnvironmentOutputs o = e.evaluate(t);
        double sum = 0.0;
        for (std::size_t i = 0; i < 3; ++i) {
            EXPECT_EQ(std::min(o.sun_face[2 * i], o.sun_face[2 * i + 1]), 0.0) << t;
            EXPECT_NEAR(std::max(o.sun_face[2 * i], o.sun_face[2 * i + 1]), std::abs(o.sun_body[i]) * o.irradiance,
                        1e-9);
            sum += o.sun_face[2 * i] + o.sun_face[2 * i + 1];
        }
        EXPECT_GE(sum, o.irradiance * (1.0 - 1e-12));
        EXPECT_LE(sum, o.irradiance * std::sqrt(3.0) * (1.0 + 1e-12));
        if (o.sunlight_fraction == 0.0) {
            ++dark;
            for (double g : o.sun_face) EXPECT_EQ(g, 0.0);
        }
    }
    EXPECT_GT(dark, 0);
}

TEST(EnvironmentCoreEnvironment, DipoleAndIgrfAgreeRoughly) {
    // The dipole carries ~90 % of the field energy: the two models agree to within ~30 % in magnitude.
    env::EnvironmentParams p;
    const env::Environment igrf(p);
    p.field_model = env::FieldModel::dipole;
    const env::Environment dip(p);
    for (double t : {0.0, 1000.0, 2000.0, 4000.0}) {
        const double a = v3(igrf.evaluate(t).mag_eci).norm(), b = v3(dip.evaluate(t).mag_eci).norm();
        EXPECT_NEAR(a / b, 1.0, 0.3);
    }
}
