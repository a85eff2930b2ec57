// The albedo at its own pace (AlbedoHarmonics, Environment's albedo.interval) against the full integration
// at every evaluation (earth_albedo, interval 0), which is the reference: the same quadrature elements, so
// the differences are the truncation at degree L and the linear interpolation between nodes alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "environment/attitude.hpp"
#include "environment/constants.hpp"
#include "environment/earth_albedo.hpp"
#include "environment/environment.hpp"
#include "ordered_draws.hpp"

namespace environment {
namespace {

Eigen::Matrix3d random_attitude(std::mt19937& rng) {
    std::normal_distribution<double> n(0.0, 1.0);
    Eigen::Quaterniond q = ordered_draws::quaternion(n, rng);
    q.normalize();
    return q.toRotationMatrix();
}

struct Worst {
    double abs = 0.0;  // W/m^2
    double peak = 0.0;
};

// Sun and satellite over the whole range of geometries (day side, terminator, night), random attitudes.
Worst worst_over_geometries(const AlbedoParams& p, int degree) {
    AlbedoHarmonics h(p, degree);
    std::vector<double> c(h.size());
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Worst w;
    for (int i = 0; i < 300; ++i) {
        const Eigen::Vector3d where = ordered_draws::vector3(u, rng).normalized();
        const Eigen::Vector3d sun = ordered_draws::vector3(u, rng).normalized();
        const double r = kEarthRadius + 570e3;
        h.project(r * where, sun, 1361.0, c.data());
        for (int a = 0; a < 4; ++a) {
            const Eigen::Matrix3d A = random_attitude(rng);
            const auto exact = earth_albedo(p, r * where, sun, 1361.0, A);
            const auto fast = h.faces(c.data(), A);
            for (int k = 0; k < 6; ++k) {
                w.abs = std::max(w.abs, std::abs(fast[k] - exact[k]));
                w.peak = std::max(w.peak, exact[k]);
            }
        }
    }
    return w;
}

TEST(EnvironmentAlbedoHarmonics, ConvergeToTheFullIntegrationWithTheDegree) {
    AlbedoParams cosine;
    AlbedoParams kelly_zonal;
    kelly_zonal.response = AlbedoResponse::kelly;
    kelly_zonal.model = ReflectivityModel::zonal;
    double previous = 1e9;
    for (int degree : {4, 8, 12, 16}) {
        const Worst c = worst_over_geometries(cosine, degree);
        const Worst k = worst_over_geometries(kelly_zonal, degree);
        std::printf(
            "degree %2d: largest error on a face, cosine uniform %.3f W/m^2 (of %.1f), Kelly zonal %.3f W/m^2 "
            "(of %.1f)\n",
            degree, c.abs, c.peak, k.abs, k.peak);
        EXPECT_LT(c.abs, previous);  // the truncation error falls with the degree
        previous = c.abs;
        if (degree == AlbedoParams{}.degree) {  // the default: the bound docs/speed.md states
            EXPECT_LT(c.abs, 0.5);
            EXPECT_LT(k.abs, 0.5);
        }
    }
}

TEST(EnvironmentAlbedoHarmonics, NadirAndZenithFacesAboveTheSubsolarPoint) {
    // Sun overhead, the -x face squarely down, the +x face up: the nadir face within 3e-4 of the full
    // integration (343.173 W/m^2, earth_albedo_test's independent integral); the zenith face sees nothing
    // and gets only the truncation's ringing, clipped at zero.
    AlbedoParams p;
    AlbedoHarmonics h(p, AlbedoParams{}.degree);
    std::vector<double> c(h.size());
    const double r = kEarthRadius + 570e3;
    h.project(r * Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitX(), 1367.0, c.data());
    const auto fast = h.faces(c.data(), Eigen::Matrix3d::Identity());
    const auto exact =
        earth_albedo(p, r * Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitX(), 1367.0, Eigen::Matrix3d::Identity());
    EXPECT_NEAR(fast[1], exact[1], 3e-4 * exact[1]);
    EXPECT_LT(fast[0], 0.2);
}

// Along the bundled kind of orbit (SGP4-free circular 570 km, tumbling at 1 deg/s): the environment with the
// default interval against the one integrating at every evaluation; and the values a function of t alone.
TEST(EnvironmentAlbedoHarmonics, AlongAnOrbitWithinTheStatedBoundAndIndependentOfTheCallOrder) {
    EnvironmentParams p;
    p.attitude_mode = AttitudeMode::rigid_body;
    p.albedo.response = AlbedoResponse::kelly;
    p.albedo.model = ReflectivityModel::zonal;
    EnvironmentParams every = p;
    every.albedo.interval = 0.0;
    const Environment fast(p), reference(every);
    const double period = fast.orbit_period();
    std::array<double, 6> worst{}, peak{};
    std::mt19937 rng(3);
    for (double t = 0.0; t < period; t += 7.3) {
        // A tumble: the attitude about a fixed axis at 1 deg/s.
        const double angle = t * kPi / 180.0;
        const Eigen::Quaterniond q(Eigen::AngleAxisd(angle, Eigen::Vector3d(1.0, 2.0, 3.0).normalized()));
        const RigidBodyState x{q.x(), q.y(), q.z(), q.w(), 0.0, 0.0, 0.0};
        const auto a = fast.evaluate(t, &x);
        const auto b = reference.evaluate(t, &x);
        for (int k = 0; k < 6; ++k) {
            worst[k] = std::max(worst[k], std::abs(a.albedo_face[k] - b.albedo_face[k]));
            peak[k] = std::max(peak[k], b.albedo_face[k]);
        }
    }
    for (int k = 0; k < 6; ++k) {
        std::printf("face %d: largest error %.3f W/m^2 of a peak %.1f W/m^2\n", k, worst[k], peak[k]);
        EXPECT_LT(worst[k], 0.5) << "face " << k;
    }
    // Backwards and forwards, bit for bit: the nodes are a memo, not a state.
    const RigidBodyState x{0.1, 0.2, 0.3, 0.927, 0.0, 0.0, 0.0};
    const Environment fresh(p);
    const auto later = fast.evaluate(1234.5, &x);
    const auto again = fresh.evaluate(1234.5, &x);
    for (int k = 0; k < 6; ++k) EXPECT_EQ(later.albedo_face[k], again.albedo_face[k]);
    (void)fast.evaluate(5000.0, &x);
    const auto back = fast.evaluate(1234.5, &x);
    for (int k = 0; k < 6; ++k) EXPECT_EQ(back.albedo_face[k], again.albedo_face[k]);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(back.mag_body[i], again.mag_body[i]);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(back.sun_eci[i], again.sun_eci[i]);
}

}  // namespace
}  // namespace environment
