#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "environment/constants.hpp"
#include "environment/earth_albedo.hpp"

namespace env = environment;

namespace {
// Independent 1-D integral for the nadir face of a satellite directly above the sub-solar point of a
// Lambertian sphere (sun at the satellite's zenith). With u = cos(central angle), element at distance
// l^2 = R^2 + r^2 - 2 R r u, solar zenith cos z = u, emission cos = (r u - R)/l, face cos = (r - R u)/l:
//   E = rho S / pi * integral cos z cos_e cos_f / l^2 dA = 2 rho S R^2 * integral_{R/r}^{1} u (r u - R)(r - R u) / l^4 du
// evaluated by composite Simpson with 20000 panels.
double nadir_albedo_subsolar(double rho, double s, double r) {
    const double R = env::kEarthRadius;
    auto f = [&](double u) {
        const double l2 = R * R + r * r - 2.0 * R * r * u;
        return u * (r * u - R) * (r - R * u) / (l2 * l2);
    };
    const int n = 20000;
    const double a = R / r, b = 1.0, h = (b - a) / n;
    double sum = f(a) + f(b);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(a + i * h);
    return 2.0 * rho * s * R * R * sum * h / 3.0;
}

// Same geometry, a side face (normal perpendicular to nadir): the face cosine is R sin g sin psi / l,
// and the integral of max(0, sin psi) over psi is 2, so
//   E = (2 rho S R^3 / pi) * integral_0^{g_max} cos g (r cos g - R) sin^2 g / l^4 dg.
double side_albedo_subsolar(double rho, double s, double r) {
    const double R = env::kEarthRadius;
    const double g_max = std::acos(R / r);
    auto f = [&](double g) {
        const double l2 = R * R + r * r - 2.0 * R * r * std::cos(g);
        return std::cos(g) * (r * std::cos(g) - R) * std::sin(g) * std::sin(g) / (l2 * l2);
    };
    const int n = 20000;
    const double h = g_max / n;
    double sum = f(0.0) + f(g_max);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(i * h);
    return 2.0 * rho * s * R * R * R / env::kPi * sum * h / 3.0;
}
}  // namespace

TEST(EnvironmentCoreAlbedo, NadirFaceAboveSubsolarPoint) {
    env::AlbedoParams p;  // reflectivity 0.3
    const double r = env::kEarthRadius + 570.0e3;
    const Eigen::Vector3d sun = Eigen::Vector3d::UnitX();
    // Body = ECI: face -x looks at nadir.
    const auto e = env::earth_albedo(p, r * sun, sun, 1367.0, Eigen::Matrix3d::Identity());
    const double expected = nadir_albedo_subsolar(0.3, 1367.0, r);
    EXPECT_NEAR(e[1], expected, 1e-6 * expected);
    std::printf("albedo nadir face: %.4f W/m^2, independent integral %.4f (rel %.2e); uniform-disc bound %.4f\n", e[1],
                expected, e[1] / expected - 1.0, 0.3 * 1367.0 * std::pow(env::kEarthRadius / r, 2));
    // Upper bound: a plate facing a uniformly bright Lambertian sphere of exitance rho S gets rho S (R/r)^2
    // (view factor of a sphere from a facing plate); the real cap is dimmer towards its edge.
    EXPECT_LT(e[1], 0.3 * 1367.0 * std::pow(env::kEarthRadius / r, 2));
    EXPECT_DOUBLE_EQ(e[0], 0.0);  // zenith face sees no Earth
    // Side faces: the independent 1-D integral; the azimuthal midpoint rule meets the face's shadow line
    // (a kink), so this converges only as O(h^2): 0.5 % allowed with the default 36 sectors.
    const double side = side_albedo_subsolar(0.3, 1367.0, r);
    for (int k = 2; k < 6; ++k) EXPECT_NEAR(e[k], side, 5e-3 * side) << "face " << k;
    std::printf("albedo side faces: %.4f %.4f %.4f %.4f W/m^2, independent integral %.4f\n", e[2], e[3], e[4], e[5],
                side);
    // And this is the largest nadir albedo over all sun directions.
    for (double ang = 0.1; ang < 3.2; ang += 0.3) {
        const Eigen::Vector3d s2(std::cos(ang), std::sin(ang), 0.0);
        EXPECT_LE(env::earth_albedo(p, r * sun, s2, 1367.0, Eigen::Matrix3d::Identity())[1], e[1]);
    }
}

TEST(EnvironmentCoreAlbedo, KellyPanelsSeeLessOfTheGrazingDisc) {
    // Independent reference: a Python midpoint integral over the central angle (200000 panels, azimuthal
    // symmetry) of the same geometry, with the Kelly curve sampled every 0.01 deg from panel_response (the
    // curve the plant uses; it is tested on its own) and interpolated linearly: nadir face above the
    // sub-solar point at 570 km, rho 0.3: cosine 343.173 W/m^2, Kelly 334.863 W/m^2, ratio 0.975784.
    // (With the table interpolated linearly in angle instead of panel_response's cubic: 0.96968.)
    env::AlbedoParams cosine_face, kelly_face;
    kelly_face.response = env::AlbedoResponse::kelly;
    const double r = env::kEarthRadius + 570.0e3;
    const Eigen::Vector3d sun = Eigen::Vector3d::UnitX();
    const auto c = env::earth_albedo(cosine_face, r * sun, sun, 1367.0, Eigen::Matrix3d::Identity());
    const auto k = env::earth_albedo(kelly_face, r * sun, sun, 1367.0, Eigen::Matrix3d::Identity());
    EXPECT_NEAR(c[1], 343.173, 0.01);
    EXPECT_NEAR(k[1] / c[1], 0.975784, 5e-4);  // the 16-ring quadrature
    // Every face sees less through the Kelly response (it lies below cos at every angle of the table), and
    // the side faces, which see the disc only at grazing incidence, lose far more than the nadir face.
    for (int f = 1; f < 6; ++f) EXPECT_LT(k[f], c[f]) << "face " << f;
    for (int f = 2; f < 6; ++f) EXPECT_LT(k[f] / c[f], k[1] / c[1] - 0.05) << "face " << f;
    std::printf("albedo through the Kelly response: nadir %.3f of the cosine value, side faces %.3f\n", k[1] / c[1],
                k[2] / c[2]);
}

TEST(EnvironmentCoreAlbedo, ZeroOverTheNightSide) {
    // Satellite above the anti-solar point at 570 km: the visible cap (half-angle 23.4 deg) is all dark.
    env::AlbedoParams p;
    const double r = env::kEarthRadius + 570.0e3;
    const auto e = env::earth_albedo(p, -r * Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitX(), 1367.0,
                                     Eigen::Matrix3d::Identity());
    for (double v : e) EXPECT_DOUBLE_EQ(v, 0.0);
}

TEST(EnvironmentCoreAlbedo, ScalesWithReflectivityAndSwitchesOff) {
    env::AlbedoParams p;
    const double r = env::kEarthRadius + 570.0e3;
    const Eigen::Vector3d sun = Eigen::Vector3d(0.6, 0.8, 0.0);
    const auto e3 = env::earth_albedo(p, r * Eigen::Vector3d::UnitX(), sun, 1367.0, Eigen::Matrix3d::Identity());
    p.reflectivity = 0.6;
    const auto e6 = env::earth_albedo(p, r * Eigen::Vector3d::UnitX(), sun, 1367.0, Eigen::Matrix3d::Identity());
    for (int k = 0; k < 6; ++k) EXPECT_NEAR(e6[k], 2.0 * e3[k], 1e-12 * (1.0 + e3[k]));
    p.enabled = false;
    for (double v : env::earth_albedo(p, r * Eigen::Vector3d::UnitX(), sun, 1367.0, Eigen::Matrix3d::Identity())) {
        EXPECT_DOUBLE_EQ(v, 0.0);
    }
}

namespace environment {
namespace {

// The zonal reflectivity model against the uniform one it reduces to, and against bounds from the latitudes
// the visible cap spans: at 570 km the cap reaches gamma_max = acos(R_E / r) = 23.37 deg from the
// sub-satellite point (hand calculation), so above a pole every element lies at latitude >= 66.63 deg and its
// reflectivity within [0.2 + 0.4 sin^2(66.63 deg), 0.6] = [0.5371, 0.6]; above the equator within
// [0.2, 0.2 + 0.4 sin^2(23.37 deg)] = [0.2, 0.2629]. The result must lie between the uniform runs at those ends.
TEST(EnvironmentAlbedoZonal, ReducesToUniformAndStaysWithinItsLatitudeBounds) {
    const double r = kEarthRadius + 570e3;
    AlbedoParams uniform;
    uniform.reflectivity = 0.3;
    AlbedoParams zonal = uniform;
    zonal.model = ReflectivityModel::zonal;
    zonal.reflectivity_equator = zonal.reflectivity_pole = 0.3;
    const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
    const Eigen::Vector3d sun(0.3, 0.1, 0.95);
    const auto a =
        earth_albedo(uniform, Eigen::Vector3d(0.2, 0.3, 0.93).normalized() * r, sun.normalized(), 1361.0, identity);
    const auto b =
        earth_albedo(zonal, Eigen::Vector3d(0.2, 0.3, 0.93).normalized() * r, sun.normalized(), 1361.0, identity);
    for (int k = 0; k < 6; ++k) EXPECT_NEAR(a[k], b[k], 1e-12 * (1.0 + a[k])) << "face " << k;

    zonal.reflectivity_equator = 0.2;
    zonal.reflectivity_pole = 0.6;
    auto nadir_face = [&](const AlbedoParams& p, const Eigen::Vector3d& where, const Eigen::Vector3d& s) {
        return earth_albedo(p, where * r, s, 1361.0, identity);
    };
    const Eigen::Vector3d pole(0, 0, 1), equator(1, 0, 0);
    AlbedoParams lo = uniform, hi = uniform;
    // Above the north pole, sun overhead: the -z face looks down.
    lo.reflectivity = 0.5370;
    hi.reflectivity = 0.6;
    const double polar = nadir_face(zonal, pole, pole)[5];
    EXPECT_GT(polar, nadir_face(lo, pole, pole)[5]);
    EXPECT_LT(polar, nadir_face(hi, pole, pole)[5]);
    // Above the equator, sun overhead: the -x face looks down.
    lo.reflectivity = 0.2;
    hi.reflectivity = 0.2630;
    const double tropical = nadir_face(zonal, equator, equator)[1];
    EXPECT_GT(tropical, nadir_face(lo, equator, equator)[1]);
    EXPECT_LT(tropical, nadir_face(hi, equator, equator)[1]);
    EXPECT_NEAR(reflectivity_at(zonal, 1.0), 0.6, 1e-15);
    EXPECT_NEAR(reflectivity_at(zonal, 0.0), 0.2, 1e-15);
}

}  // namespace
}  // namespace environment
