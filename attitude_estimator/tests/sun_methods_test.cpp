// The sun methods of sun_methods.hpp (issue 8). Currents are made from a known sun direction through the
// panel law (the cosine by hand; the Kelly table through panel_response, which its own test ties to the
// plant's function); expected directions are that truth, expected angles come from the seeds' formulas
// evaluated here or by hand — never from the code under test.
#include "attitude_estimator/sun_methods.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "attitude_estimator/sun_vector.hpp"
#include "test_support.hpp"

namespace attitude_estimator::test {
namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr double kNorm = 0.84754;

enum class Law { cosine, kelly };

template <class T>
SunMethodConfig<T> config(SunMethod m, Law law) {
    SunMethodConfig<T> cfg;
    cfg.method = m;
    cfg.response = law == Law::cosine ? panel_response::cosine<T>() : panel_response::kelly<T>();
    return cfg;
}

// Face currents of a sun direction s (unit, body axes) in full sun, face order +x, −x, +y, −y, +z, −z.
template <class T>
std::array<T, 6> currents(const Eigen::Vector3d& s, Law law) {
    std::array<T, 6> i{};
    for (int k = 0; k < 6; ++k) {
        const double c = (k % 2 == 0 ? 1.0 : -1.0) * s[k / 2];
        const double r = law == Law::cosine ? std::max(0.0, c)
                                            : panel_response::response_from_cos(panel_response::kelly<double>(), c);
        i[k] = static_cast<T>(kNorm * r);
    }
    return i;
}

template <class T>
double angle_to(const Vec3<T>& u, const Eigen::Vector3d& s) {
    const Eigen::Vector3d v(u[0], u[1], u[2]);
    return std::atan2(v.cross(s).norm(), v.dot(s));
}

// A random direction with every component at least `margin` in magnitude (all three axes lit).
inline Eigen::Vector3d lit_direction(Random& rng, double margin) {
    for (;;) {
        const Eigen::Vector3d s = rng.unit();
        if (std::abs(s.x()) >= margin && std::abs(s.y()) >= margin && std::abs(s.z()) >= margin) return s;
    }
}

template <class T>
class EstimatorCoreSunMethods : public ::testing::Test {};
TYPED_TEST_SUITE(EstimatorCoreSunMethods, Scalars, ScalarName);

TEST(EstimatorCoreSunMethodNames, EveryMethodHasItsName) {
    EXPECT_STREQ(sun_method_name(SunMethod::difference), "difference");
    EXPECT_STREQ(sun_method_name(SunMethod::inverse_response), "inverse_response");
    EXPECT_STREQ(sun_method_name(SunMethod::cones), "cones");
    EXPECT_STREQ(sun_method_name(SunMethod::three_faces), "three_faces");
}

TEST(EstimatorCoreSunMethodNames, CubeGraphOfSeed002) {
    static_assert(cube_state_of(0, 0, 0) == kCubeDark);
    static_assert(cube_axis(cube_state_of(1, -1, 0), 0) == 1 && cube_axis(cube_state_of(1, -1, 0), 1) == -1 &&
                  cube_axis(cube_state_of(1, -1, 0), 2) == 0);
    // Face +x to its edge and vertex: allowed; +x straight to −x, or vertex (1,1,1) to (−1,1,1): forbidden;
    // anything from darkness: allowed.
    EXPECT_TRUE(cube_transition_allowed(cube_state_of(1, 0, 0), cube_state_of(1, 1, 0)));
    EXPECT_TRUE(cube_transition_allowed(cube_state_of(1, 1, 0), cube_state_of(1, 1, -1)));
    EXPECT_TRUE(cube_transition_allowed(cube_state_of(1, 1, 1), cube_state_of(0, 1, 1)));
    EXPECT_FALSE(cube_transition_allowed(cube_state_of(1, 0, 0), cube_state_of(-1, 0, 0)));
    EXPECT_FALSE(cube_transition_allowed(cube_state_of(1, 1, 1), cube_state_of(-1, 1, 1)));
    EXPECT_TRUE(cube_transition_allowed(kCubeDark, cube_state_of(-1, -1, -1)));
}

TYPED_TEST(EstimatorCoreSunMethods, DifferenceIsEq5OnTheFaceCurrents) {
    using T = TypeParam;
    Random rng(8);
    SunMethodState<T> st;
    const auto cfg = config<T>(SunMethod::difference, Law::cosine);
    for (int n = 0; n < 200; ++n) {
        const Eigen::Vector3d s = rng.unit();
        const auto r = sun_from_faces(currents<T>(s, Law::cosine), cfg, st);
        ASSERT_TRUE(r.valid);
        EXPECT_LT(angle_to(r.unit, s), tol<T>(1e-5, 1e-12));
        EXPECT_NEAR(r.norm, 1.0, tol<T>(1e-5, 1e-12));
    }
    // Same as sun_vector_from_currents on (I+ − I−).
    const std::array<T, 6> i{T(0.5), T(0.1), T(0.0), T(0.3), T(0.6), T(0.0)};
    const auto r = sun_difference(i, cfg);
    const auto m = sun_vector_from_currents<T>({T(0.4), T(-0.3), T(0.6)}, {T(kNorm), T(kNorm), T(kNorm)});
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(r.unit[k], m.unit[k], tol<T>(1e-6, 1e-15));
}

TYPED_TEST(EstimatorCoreSunMethods, InverseResponseRecoversDirectionsWithBothLaws) {
    using T = TypeParam;
    Random rng(81);
    for (Law law : {Law::cosine, Law::kelly}) {
        const auto cfg = config<T>(SunMethod::inverse_response, law);
        SunMethodState<T> st;
        double worst = 0.0;
        for (int n = 0; n < 300; ++n) {
            // Every axis lit: |s_k| ≥ 0.15 puts every sunlit face below 81.4°, well inside the Kelly table.
            const Eigen::Vector3d s = lit_direction(rng, 0.15);
            const auto r = sun_from_faces(currents<T>(s, law), cfg, st);
            ASSERT_TRUE(r.valid);
            worst = std::max(worst, angle_to(r.unit, s));
            EXPECT_EQ(r.rejected_faces, 0);
            EXPECT_EQ(std::popcount(static_cast<unsigned>(r.lit_faces)), 3);
            EXPECT_EQ(r.cube_state, cube_state_of(s.x() > 0 ? 1 : -1, s.y() > 0 ? 1 : -1, s.z() > 0 ? 1 : -1));
            EXPECT_LT(r.residual, tol<T>(1e-4, 1e-9));
        }
        EXPECT_LT(worst, tol<T>(2e-4, 1e-9)) << (law == Law::kelly ? "kelly" : "cosine");
    }
}

TYPED_TEST(EstimatorCoreSunMethods, DifferenceIsBiasedByKellyWhereInverseResponseIsNot) {
    using T = TypeParam;
    // s = (0.3, 0.5, 0.8124): the x face at 72.5°, where Kelly is far below the cosine.
    const Eigen::Vector3d s = Eigen::Vector3d(0.3, 0.5, std::sqrt(1 - 0.09 - 0.25));
    SunMethodState<T> st;
    const auto i = currents<T>(s, Law::kelly);
    const auto d = sun_from_faces(i, config<T>(SunMethod::difference, Law::kelly), st);
    const auto v = sun_from_faces(i, config<T>(SunMethod::inverse_response, Law::kelly), st);
    ASSERT_TRUE(v.valid);
    EXPECT_GT(angle_to(d.unit, s), 2.0 * kDeg);
    EXPECT_LT(angle_to(v.unit, s), tol<T>(1e-4, 1e-9));
}

TYPED_TEST(EstimatorCoreSunMethods, InverseResponseTakesTheBrighterOfOppositeFaces) {
    using T = TypeParam;
    const Eigen::Vector3d s = Eigen::Vector3d(0.48, 0.6, 0.64);
    auto i = currents<T>(s, Law::cosine);
    i[5] = T(0.2 * kNorm);  // albedo on −z, the face toward nadir
    SunMethodState<T> st;
    const auto r = sun_from_faces(i, config<T>(SunMethod::inverse_response, Law::cosine), st);
    ASSERT_TRUE(r.valid);
    EXPECT_EQ(r.rejected_faces, 1 << 5);
    EXPECT_EQ(r.lit_faces, 0b110101);
    EXPECT_LT(angle_to(r.unit, s), tol<T>(1e-6, 1e-12));
}

TYPED_TEST(EstimatorCoreSunMethods, InverseResponseDarkAxisBoundAndValidity) {
    using T = TypeParam;
    for (Law law : {Law::cosine, Law::kelly}) {
        const auto cfg = config<T>(SunMethod::inverse_response, law);
        SunMethodState<T> st;
        // Sun at 84° from +z, with x and y lit: with Kelly the z faces read 0 (the table's tail), the z component
        // (cos 84° = 0.105) is unknown and taken as 0: the error is asin(0.105) = 6.0° at most.
        const double sz = std::cos(84 * kDeg);
        const Eigen::Vector3d s =
            Eigen::Vector3d(0.6, 0.8, 0).normalized() * std::sqrt(1 - sz * sz) + Eigen::Vector3d(0, 0, sz);
        const auto r = sun_from_faces(currents<T>(s, law), cfg, st);
        ASSERT_TRUE(r.valid);
        if (law == Law::kelly) {
            EXPECT_EQ(r.lit_faces, 0b0101);
            EXPECT_NEAR(angle_to(r.unit, s), std::asin(sz), tol<T>(1e-4, 1e-9));
        } else {
            EXPECT_LT(angle_to(r.unit, s), tol<T>(1e-5, 1e-12));  // the cosine law still sees 0.105 > 0.02
        }
        // One axis lit: invalid by default (min_lit_axes = 2), valid with min_lit_axes = 1.
        const auto one = sun_from_faces(currents<T>(Eigen::Vector3d(0, 0, -1), law), cfg, st);
        EXPECT_FALSE(one.valid);
        EXPECT_NEAR(one.unit[2], -1.0, tol<T>(1e-6, 1e-15));
        auto cfg1 = cfg;
        cfg1.min_lit_axes = 1;
        EXPECT_TRUE(sun_from_faces(currents<T>(Eigen::Vector3d(0, 0, -1), law), cfg1, st).valid);
        // Albedo only (eclipse): one face at 0.25 of full sun cannot reach |s| = 0.5 even with the dark axes.
        std::array<T, 6> albedo{};
        albedo[5] = T(0.25 * kNorm);
        EXPECT_FALSE(sun_from_faces(albedo, cfg1, st).valid);
        EXPECT_FALSE(sun_from_faces(std::array<T, 6>{}, cfg, st).valid);
        std::array<T, 6> bad = currents<T>(s, law);
        bad[2] = std::numeric_limits<T>::quiet_NaN();
        EXPECT_FALSE(sun_from_faces(bad, cfg, st).valid);
    }
}

// ---- cones ----

TYPED_TEST(EstimatorCoreSunMethods, ConesRecoverDirectionsWithBothLaws) {
    using T = TypeParam;
    Random rng(82);
    for (Law law : {Law::cosine, Law::kelly}) {
        const auto cfg = config<T>(SunMethod::cones, law);
        double worst = 0.0;
        for (int n = 0; n < 300; ++n) {
            SunMethodState<T> st;  // fresh each time: no tracking
            const Eigen::Vector3d s = lit_direction(rng, 0.15);
            const auto r = sun_from_faces(currents<T>(s, law), cfg, st);
            ASSERT_TRUE(r.valid);
            worst = std::max(worst, angle_to(r.unit, s));
            EXPECT_EQ(r.rejected_faces, 0);
            const int cube = cube_state_of(s.x() > 0 ? 1 : -1, s.y() > 0 ? 1 : -1, s.z() > 0 ? 1 : -1);
            EXPECT_EQ(r.cube_state, cube);
            EXPECT_EQ(st.cube_state, cube);
        }
        EXPECT_LT(worst, tol<T>(2e-4, 1e-9)) << (law == Law::kelly ? "kelly" : "cosine");
    }
}

TYPED_TEST(EstimatorCoreSunMethods, ConePairMatchesSeedEq20CorrectedNotAsPrinted) {
    using T = TypeParam;
    // Sun (0.48, 0.6, 0.64): the +x and +y cones have α_x = acos 0.48, α_y = acos 0.6. Seed 002 eq. 20's
    // first line, solved with tan² α_x in the denominator (as in eq. 12), gives θ_x and, through eq. 14–15 on
    // the unit sphere (x = cos α_x), the truth; the printed second line (tan α_x, not squared) does not.
    const double ax = std::acos(0.48), ay = std::acos(0.6);
    const double tx2 = std::tan(ax) * std::tan(ax), ty2 = std::tan(ay) * std::tan(ay);
    const double sin_theta = std::sqrt((tx2 + 1) / (tx2 * (ty2 + 1)));
    const double x = std::cos(ax);
    const double y = x * sin_theta * std::tan(ax);
    const double z = x * std::sqrt(1 - sin_theta * sin_theta) * std::tan(ax);
    EXPECT_NEAR(y, 0.6, 1e-12);
    EXPECT_NEAR(z, 0.64, 1e-12);
    const double printed = (tx2 + 1) / (std::tan(ax) * (ty2 + 1));  // sin²θ_x as printed
    EXPECT_GT(std::abs(printed - sin_theta * sin_theta), 0.1);
    // The method with only +x, +y and +z lit picks the +z candidate of the (+x, +y) pair, i.e. the truth.
    SunMethodState<T> st;
    const auto r = sun_from_faces(currents<T>(Eigen::Vector3d(0.48, 0.6, 0.64), Law::cosine),
                                  config<T>(SunMethod::cones, Law::cosine), st);
    ASSERT_TRUE(r.valid);
    EXPECT_NEAR(r.unit[0], 0.48, tol<T>(1e-6, 1e-12));
    EXPECT_NEAR(r.unit[1], 0.6, tol<T>(1e-6, 1e-12));
    EXPECT_NEAR(r.unit[2], 0.64, tol<T>(1e-6, 1e-12));
}

TYPED_TEST(EstimatorCoreSunMethods, ConesRejectTheMirrorCandidate) {
    using T = TypeParam;
    const auto cfg = config<T>(SunMethod::cones, Law::cosine);
    // The (+x, +y) pair gives (0.6, 0.6, ±0.529); which of the two is the sun only the z faces tell.
    const double sz = std::sqrt(1 - 0.72);
    for (double sign : {1.0, -1.0}) {
        SunMethodState<T> st;
        const Eigen::Vector3d s(0.6, 0.6, sign * sz);
        const auto r = sun_from_faces(currents<T>(s, Law::cosine), cfg, st);
        ASSERT_TRUE(r.valid);
        EXPECT_LT(angle_to(r.unit, s), tol<T>(1e-5, 1e-12));
        EXPECT_EQ(r.cube_state, cube_state_of(1, 1, sign > 0 ? 1 : -1));
    }
    // Both z faces dark while the pair needs |s_z| = 0.529: both candidates would light a dark face, and no
    // face alone explains the readings: invalid, nothing to average.
    SunMethodState<T> st;
    auto i = currents<T>(Eigen::Vector3d(0.6, 0.6, sz), Law::cosine);
    i[4] = T(0);
    const auto r = sun_from_faces(i, cfg, st);
    EXPECT_FALSE(r.valid);
    EXPECT_EQ(r.rejected_faces, r.lit_faces);
}

TYPED_TEST(EstimatorCoreSunMethods, ConesRejectAnAlbedoLitNadirFace) {
    using T = TypeParam;
    Random rng(83);
    for (Law law : {Law::cosine, Law::kelly}) {
        // The model-free cones (albedo model off): the offsets below light single faces only, which the Earth
        // cannot do from LEO (it is 133° wide at 570 km: a face at 90° to the nadir gets ~30 % of the nadir
        // face's albedo, and both y faces cannot be dark at once); the model's own test is
        // ConesAlbedoModelRecoversTheSunUnderAnEarthLikeAlbedo.
        auto cfg = config<T>(SunMethod::cones, law);
        cfg.cone_fit_tolerance = T(0);
        for (int n = 0; n < 100; ++n) {
            SunMethodState<T> st;
            Eigen::Vector3d s = lit_direction(rng, 0.3);
            // Albedo lights the face opposite the sunlit z face (toward nadir), less than the sun lights the z face
            // (a brighter albedo makes the readings those of the mirror sun with the roles swapped: no single
            // sample can tell them apart, docs/sun_methods.md), and a little of one side face the sun does not see.
            const int nadir = s.z() > 0 ? 5 : 4;
            const int side = s.x() > 0 ? 1 : 0;
            auto i = currents<T>(s, law);
            const double sunlit_z = static_cast<double>(i[nadir ^ 1]) / kNorm;
            i[nadir] += T(rng.uniform(0.05, std::max(0.05, 0.9 * sunlit_z)) * kNorm);
            i[side] += T(0.04 * kNorm);
            const auto r = sun_from_faces(i, cfg, st);
            ASSERT_TRUE(r.valid);
            EXPECT_LT(angle_to(r.unit, s), tol<T>(2e-4, 1e-9));
            EXPECT_EQ(r.rejected_faces, (1 << nadir) | (1 << side));
        }
    }
}

TYPED_TEST(EstimatorCoreSunMethods, ConesRejectAPollutedSunlitFace) {
    using T = TypeParam;
    // The model-free cones (albedo model off): an offset on one sunlit face alone is not an Earth-like albedo
    // (see ConesRejectAnAlbedoLitNadirFace).
    auto cfg = config<T>(SunMethod::cones, Law::cosine);
    cfg.cone_fit_tolerance = T(0);
    // Sun (0.7, 0.6, 0.387): the +z face reads 0.9 (albedo 0.51 on top of its 0.387): its cone no longer meets
    // the others (0.9² + 0.6² > 1), the seed's criterion; only the (+x, +y) pair remains and +z is rejected.
    {
        const Eigen::Vector3d s(0.7, 0.6, std::sqrt(1 - 0.85));
        auto i = currents<T>(s, Law::cosine);
        i[4] = T(0.9 * kNorm);
        SunMethodState<T> st;
        const auto r = sun_from_faces(i, cfg, st);
        ASSERT_TRUE(r.valid);
        EXPECT_EQ(r.rejected_faces, 1 << 4);
        EXPECT_LT(angle_to(r.unit, s), tol<T>(1e-5, 1e-12));
    }
    // A small offset leaves every pair intersecting and the three readings alone ambiguous (any of the three
    // faces could carry it); continuity decides: after a clean sample 1° away, the polluted face is found.
    for (Law law : {Law::cosine, Law::kelly}) {
        auto cfgl = config<T>(SunMethod::cones, law);
        cfgl.cone_fit_tolerance = T(0);
        Random rng(84);
        for (int n = 0; n < 50; ++n) {
            const Eigen::Vector3d s0 = lit_direction(rng, 0.25);
            const Eigen::Vector3d s1 = rng.rotation(1.0 * kDeg) * s0;
            SunMethodState<T> st;
            ASSERT_TRUE(sun_from_faces(currents<T>(s0, law), cfgl, st).valid);
            const int k = rng.integer(0, 2);
            const int face = 2 * k + (s1[k] > 0 ? 0 : 1);
            auto i = currents<T>(s1, law);
            i[face] += T(0.1 * kNorm);
            const auto r = sun_from_faces(i, cfgl, st);
            ASSERT_TRUE(r.valid);
            EXPECT_EQ(r.rejected_faces, 1 << face) << n;
            EXPECT_LT(angle_to(r.unit, s1), tol<T>(2e-4, 1e-9)) << n;
        }
    }
}

TYPED_TEST(EstimatorCoreSunMethods, ConesRefuseForbiddenCubeJumpsUntilDarkness) {
    using T = TypeParam;
    auto cfg = config<T>(SunMethod::cones, Law::cosine);
    cfg.cube_refusals_before_reset = 0;  // refuse until darkness
    SunMethodState<T> st;
    const Eigen::Vector3d px(1, 0, 0), mx(-1, 0, 0);
    const Eigen::Vector3d pxy = Eigen::Vector3d(1, 1, 0).normalized();
    auto r = sun_from_faces(currents<T>(px, Law::cosine), cfg, st);
    ASSERT_TRUE(r.valid);
    EXPECT_EQ(st.cube_state, cube_state_of(1, 0, 0));
    // +x straight to −x: refused, the state kept.
    for (int n = 0; n < 6; ++n) {
        r = sun_from_faces(currents<T>(mx, Law::cosine), cfg, st);
        EXPECT_FALSE(r.valid);
        EXPECT_EQ(r.cube_state, cube_state_of(1, 0, 0));
        EXPECT_EQ(st.cube_state, cube_state_of(1, 0, 0));
    }
    // +x to the edge (+x, +y): allowed.
    r = sun_from_faces(currents<T>(pxy, Law::cosine), cfg, st);
    ASSERT_TRUE(r.valid);
    EXPECT_EQ(st.cube_state, cube_state_of(1, 1, 0));
    EXPECT_LT(angle_to(r.unit, pxy), tol<T>(1e-6, 1e-12));
    // Darkness, then −x: allowed.
    r = sun_from_faces(std::array<T, 6>{}, cfg, st);
    EXPECT_FALSE(r.valid);
    EXPECT_EQ(st.cube_state, kCubeDark);
    r = sun_from_faces(currents<T>(mx, Law::cosine), cfg, st);
    ASSERT_TRUE(r.valid);
    EXPECT_EQ(st.cube_state, cube_state_of(-1, 0, 0));
    EXPECT_LT(angle_to(r.unit, mx), tol<T>(1e-6, 1e-12));
    // With the default recovery (4 refusals), a persistent jump is accepted on the 4th sample.
    cfg.cube_refusals_before_reset = 4;
    for (int n = 1; n <= 4; ++n) {
        r = sun_from_faces(currents<T>(px, Law::cosine), cfg, st);
        EXPECT_EQ(r.valid, n == 4) << n;
    }
    EXPECT_EQ(st.cube_state, cube_state_of(1, 0, 0));
}

TYPED_TEST(EstimatorCoreSunMethods, ConesAllowASmallStepAcrossAnAxisWhenAsked) {
    using T = TypeParam;
    // (0.7, 0.1, 0.707) to (0.7, −0.1, 0.707): 11.5° apart, y flips sign without a sample in the y-dark band.
    const Eigen::Vector3d a = Eigen::Vector3d(0.7, 0.1, 0.707).normalized();
    const Eigen::Vector3d b = Eigen::Vector3d(0.7, -0.1, 0.707).normalized();
    auto cfg = config<T>(SunMethod::cones, Law::cosine);
    cfg.cube_refusals_before_reset = 0;
    SunMethodState<T> st;
    ASSERT_TRUE(sun_from_faces(currents<T>(a, Law::cosine), cfg, st).valid);
    EXPECT_FALSE(sun_from_faces(currents<T>(b, Law::cosine), cfg, st).valid);  // the graph alone: refused
    cfg.cube_max_step = T(15 * kDeg);
    const auto r = sun_from_faces(currents<T>(b, Law::cosine), cfg, st);
    ASSERT_TRUE(r.valid);
    EXPECT_LT(angle_to(r.unit, b), tol<T>(1e-5, 1e-12));
    // A 180° jump stays refused.
    EXPECT_FALSE(sun_from_faces(currents<T>(Eigen::Vector3d(-b), Law::cosine), cfg, st).valid);
}

TYPED_TEST(EstimatorCoreSunMethods, ConesInvalidOnAlbedoAlone) {
    using T = TypeParam;
    // Eclipse with the Earth lighting one, two or three faces: no sun direction explains the readings (each
    // candidate would light some face far more than it reads).
    const auto cfg = config<T>(SunMethod::cones, Law::cosine);
    SunMethodState<T> st;
    const std::array<std::array<double, 6>, 3> cases = {
        {{0, 0, 0, 0, 0, 0.3}, {0, 0.2, 0, 0, 0, 0.3}, {0, 0.1, 0.15, 0, 0, 0.3}}};
    for (const auto& c : cases) {
        std::array<T, 6> i{};
        for (int k = 0; k < 6; ++k) i[k] = T(c[k] * kNorm);
        const auto r = sun_from_faces(i, cfg, st);
        EXPECT_FALSE(r.valid);
        EXPECT_EQ(st.cube_state, kCubeDark);
    }
}

// Earth albedo on the six faces as the Earth gives it from 570 km (sin λ = R_E/(R_E + h) = 0.91788): a
// Lambertian sphere of reflectivity 0.3 lit by the sun s, radiance 0.3 cos z/π at each point (z its solar
// zenith), integrated over the visible cap by a midpoint rule in the angle from the nadir and the azimuth —
// independent of the closed-form view factor inside the method (which assumes a uniformly bright sphere).
inline std::array<double, 6> earth_albedo(const Eigen::Vector3d& s, const Eigen::Vector3d& nadir) {
    const double sin_l = 0.91788, h = 1.0 / sin_l, lambda = std::asin(sin_l);
    Eigen::Vector3d e1 = nadir.unitOrthogonal(), e2 = nadir.cross(e1);
    std::array<double, 6> a{};
    const int ng = 120, np = 120;
    for (int i = 0; i < ng; ++i) {
        const double g = (i + 0.5) * lambda / ng;
        for (int j = 0; j < np; ++j) {
            const double psi = (j + 0.5) * 2 * M_PI / np;
            const Eigen::Vector3d u = std::cos(g) * nadir + std::sin(g) * (std::cos(psi) * e1 + std::sin(psi) * e2);
            // The ray from the satellite (at −h·nadir from the Earth's centre, radius 1) meets the sphere at p.
            const double b = h * std::cos(g);
            const double t = b - std::sqrt(std::max(0.0, b * b - (h * h - 1)));
            const Eigen::Vector3d p = -h * nadir + t * u;
            const double cos_z = p.normalized().dot(s);
            if (cos_z <= 0) continue;
            const double w = 0.3 * cos_z / M_PI * std::sin(g) * (lambda / ng) * (2 * M_PI / np);
            for (int k = 0; k < 6; ++k) a[k] += w * std::max(0.0, (k % 2 == 0 ? 1.0 : -1.0) * u[k / 2]);
        }
    }
    return a;
}

TYPED_TEST(EstimatorCoreSunMethods, ConesAlbedoModelRecoversTheSunUnderAnEarthLikeAlbedo) {
    using T = TypeParam;
    for (Law law : {Law::cosine, Law::kelly}) {
        Random rng(86);
        const auto cfg = config<T>(SunMethod::cones, law);
        auto free_cfg = cfg;
        free_cfg.cone_fit_tolerance = T(0);  // the model-free cones, for comparison
        std::vector<double> err, free_err;
        double largest_albedo = 0;
        for (int n = 0; n < 200; ++n) {
            const Eigen::Vector3d s = lit_direction(rng, 0.15);
            Eigen::Vector3d nadir;
            do nadir = rng.unit();
            while (nadir.dot(s) > std::cos(75 * kDeg));  // sunlit: the sun at least 66.6° from the nadir
            const auto a = earth_albedo(s, nadir);
            auto i = currents<T>(s, law);
            for (int k = 0; k < 6; ++k) {
                i[k] += T(a[k] * kNorm);
                largest_albedo = std::max(largest_albedo, a[k]);
            }
            SunMethodState<T> st, st_free;
            const auto r = sun_from_faces(i, cfg, st);
            const auto rf = sun_from_faces(i, free_cfg, st_free);
            ASSERT_TRUE(r.valid);
            err.push_back(angle_to(r.unit, s) / kDeg);
            free_err.push_back(rf.valid ? angle_to(rf.unit, s) / kDeg : 180.0);
        }
        std::sort(err.begin(), err.end());
        std::sort(free_err.begin(), free_err.end());
        const char* name = law == Law::kelly ? "kelly" : "cosine";
        std::printf("%s: albedo model median %.3f° p90 %.3f°, model-free median %.3f° p90 %.3f°\n", name, err[100],
                    err[179], free_err[100], free_err[179]);
        EXPECT_GT(largest_albedo, 0.15) << name;  // a real test: the Earth lights faces by up to a fifth of the sun
        EXPECT_LT(err[100], 0.2) << name;         // median
        EXPECT_LT(err[179], 1.0) << name;         // 90th percentile
        EXPECT_GT(free_err[179], 2.0 * err[179]) << name;
    }
}

TYPED_TEST(EstimatorCoreSunMethods, ConesTrackATumblingSatelliteUnderAnEarthLikeAlbedo) {
    using T = TypeParam;
    // A satellite tumbling at 1° per sample (three random axes, a full turn each) with the sun 110° from the
    // nadir (Earth-like albedo as above): tracking (the cube graph and the last direction) must not lock onto
    // a wrong branch — after a mirror-ambiguous sample the next unambiguous fit would be a forbidden jump; it is
    // refused at most cube_refusals_before_reset − 1 times, never replaced by a model-free guess. (1° per
    // sample: faster, the cosine law's 2 × 1.15° dark band could be skipped, which the graph refuses by design —
    // cube_max_step.)
    for (Law law : {Law::cosine, Law::kelly}) {
        Random rng(87);
        const auto cfg = config<T>(SunMethod::cones, law);
        const Eigen::Vector3d sun(1, 0, 0);
        const Eigen::Vector3d nadir(std::cos(110 * kDeg), std::sin(110 * kDeg), 0);
        std::vector<double> err;
        int refused = 0, total = 0;
        for (int run = 0; run < 3; ++run) {
            const Eigen::Vector3d axis = rng.unit();
            const Eigen::Matrix3d a0 = rng.rotation();
            SunMethodState<T> st;
            for (int n = 0; n < 360; ++n, ++total) {
                const Eigen::Matrix3d a = Eigen::AngleAxisd(1.0 * n * kDeg, axis).toRotationMatrix() * a0;
                const Eigen::Vector3d s = a * sun;
                const auto alb = earth_albedo(s, a * nadir);
                auto i = currents<T>(s, law);
                for (int k = 0; k < 6; ++k) i[k] += T(alb[k] * kNorm);
                const auto r = sun_from_faces(i, cfg, st);
                if (!r.valid) {
                    ++refused;
                    continue;
                }
                err.push_back(angle_to(r.unit, s) / kDeg);
            }
        }
        std::sort(err.begin(), err.end());
        const char* name = law == Law::kelly ? "kelly" : "cosine";
        const double p95 = err[err.size() * 95 / 100];
        std::printf("%s: tracked %d samples, %d refused, median %.3f° p95 %.3f° max %.3f°\n", name, total, refused,
                    err[err.size() / 2], p95, err.back());
        EXPECT_LE(refused, total / 50) << name;
        EXPECT_LT(err[err.size() / 2], 0.3) << name;
        // The dark band bounds an axis's component by δ (Kelly: cos 83.3° = 0.117, asin δ = 6.7°; cosine 1.15°).
        EXPECT_LT(p95, law == Law::kelly ? 6.8 : 1.2) << name;
    }
}

// ---- three faces ----

TYPED_TEST(EstimatorCoreSunMethods, ThreeFacesPrintedVersusConsistentVersusTruth) {
    using T = TypeParam;
    const auto cfg = config<T>(SunMethod::three_faces, Law::cosine);
    // Truth in the seed-000 parametrization s = (sin φ sin θ, cos φ sin θ, cos θ).
    for (double phi : {0.3, 1.2, 2.0, -0.7, -2.5}) {
        for (double theta : {0.4, 1.0, 2.2}) {
            const Eigen::Vector3d s(std::sin(phi) * std::sin(theta), std::cos(phi) * std::sin(theta), std::cos(theta));
            const auto t = three_faces(currents<T>(s, Law::cosine), cfg);
            ASSERT_TRUE(t.three_lit);
            EXPECT_TRUE(t.consistent_admissible);
            EXPECT_NEAR(t.consistent_check, 0.0, tol<T>(1e-5, 1e-12));
            EXPECT_NEAR(t.theta, theta, tol<T>(1e-4, 1e-10));
            EXPECT_NEAR(t.phi, phi, tol<T>(1e-4, 1e-10));
            EXPECT_LT(angle_to(t.unit, s), tol<T>(1e-5, 1e-12));
        }
    }
    // (1, 1, 1)/√3, a lit vertex: eq. 3 as printed gives 3c + c − c − 2 = √3 − 2 = −0.268: "inadmissible";
    // eq. 2 as printed gives ε1 = asin √(2 − √3) = 31.17°, ε2 = ε3 = asin √(1 − 1/√3) = 40.55°.
    const double c = 1 / std::sqrt(3.0);
    const auto v = three_faces(currents<T>(Eigen::Vector3d(c, c, c), Law::cosine), cfg);
    EXPECT_NEAR(v.printed_check, std::sqrt(3.0) - 2, tol<T>(1e-5, 1e-12));
    EXPECT_FALSE(v.printed_admissible);
    EXPECT_TRUE(v.consistent_admissible);
    EXPECT_NEAR(v.printed_epsilon[0], 31.1740 * kDeg, 1e-4);
    EXPECT_NEAR(v.printed_epsilon[1], 40.5503 * kDeg, 1e-4);
    EXPECT_NEAR(v.printed_epsilon[2], 40.5503 * kDeg, 1e-4);
    // Near +y (c = (0.1, 0.99, 0.1) normalized), eq. 2's third radicand 1 − c1 + c2 − c3 exceeds 1: no angle.
    const auto w = three_faces(currents<T>(Eigen::Vector3d(0.1, 0.99, 0.1).normalized(), Law::cosine), cfg);
    EXPECT_FALSE(w.printed_defined[2]);
    EXPECT_TRUE(w.consistent_admissible);
    // Printed eq. 3 holds only on a circle of the sphere, e.g. c = (2/3, √(5/18), √(5/18)).
    const double q = std::sqrt(5.0 / 18.0);
    const auto u = three_faces(currents<T>(Eigen::Vector3d(2.0 / 3.0, q, q), Law::cosine), cfg);
    EXPECT_TRUE(u.printed_admissible);
    EXPECT_NEAR(u.printed_check, 0.0, tol<T>(1e-5, 1e-12));
    // Readings no unit vector can make (Σc² = 1.29): the consistent check refuses them.
    std::array<T, 6> bad{T(0.7 * kNorm), T(0), T(0.7 * kNorm), T(0), T(0.5 * kNorm), T(0)};
    SunMethodState<T> st;
    const auto b = sun_from_faces(bad, cfg, st);
    EXPECT_FALSE(b.valid);
    EXPECT_NEAR(b.residual, 0.49 + 0.49 + 0.25 - 1, tol<T>(1e-5, 1e-12));
    // Two lit axes: not three faces.
    EXPECT_FALSE(sun_from_faces(currents<T>(Eigen::Vector3d(0.6, -0.8, 0), Law::cosine), cfg, st).valid);
}

TYPED_TEST(EstimatorCoreSunMethods, ThreeFacesWithKellyUsesTheInverseTable) {
    using T = TypeParam;
    const auto cfg = config<T>(SunMethod::three_faces, Law::kelly);
    Random rng(85);
    SunMethodState<T> st;
    for (int n = 0; n < 100; ++n) {
        const Eigen::Vector3d s = lit_direction(rng, 0.15);
        const auto r = sun_from_faces(currents<T>(s, Law::kelly), cfg, st);
        ASSERT_TRUE(r.valid);
        EXPECT_LT(angle_to(r.unit, s), tol<T>(2e-4, 1e-9));
    }
}

}  // namespace
}  // namespace attitude_estimator::test
