// One whole sample: synthetic raw inputs made from a known attitude by the inverse of the documented
// sensor models (i_sh = i_sc_norm ⊙ s of 000 eq. 5; v = v_ref + sensitivity · B of 000 §5), truth from Eigen.
#include "attitude_estimator/estimator.hpp"

#include "test_support.hpp"

namespace attitude_estimator::test {
namespace {

template <class T>
class EstimatorCoreSample : public ::testing::Test {};
TYPED_TEST_SUITE(EstimatorCoreSample, Scalars, ScalarName);

struct Scene {
    Eigen::Matrix3d a_true;
    Eigen::Vector3d sun_ref, mag_ref;  // unit
};

template <class T>
SampleInputs<T> raw_inputs(const Scene& scene, const EstimatorConfig<T>& config, double field_tesla) {
    const Eigen::Vector3d s = scene.a_true * scene.sun_ref;
    const Eigen::Vector3d b = scene.a_true * scene.mag_ref * field_tesla;
    SampleInputs<T> in;
    for (int k = 0; k < 3; ++k) {
        in.i_sh[k] = static_cast<T>(static_cast<double>(config.i_sc_norm[k]) * s[k]);
        in.v_mag[k] = static_cast<T>(2.5 + static_cast<double>(config.mag_sensitivity) * b[k]);
    }
    in.v_mag_ref = T(2.5);
    in.sun_ref = to_vec<T>(scene.sun_ref * 1.496e11);  // any length: e.g. the Earth–Sun distance in m
    in.mag_ref = to_vec<T>(scene.mag_ref * field_tesla);
    return in;
}

template <class T>
Scene random_scene(Random& rng, double min_separation_deg) {
    Scene sc{rng.rotation(), rng.unit(), rng.unit()};
    while (sc.sun_ref.cross(sc.mag_ref).norm() < std::sin(min_separation_deg * M_PI / 180.0)) sc.mag_ref = rng.unit();
    return sc;
}

TYPED_TEST(EstimatorCoreSample, IdealConvertersRecoverTheAttitude) {
    using T = TypeParam;
    EstimatorConfig<T> config;
    config.i_sc_norm = {T(0.62), T(0.65), T(0.70)};
    for (auto& a : config.sun_adc) a.bits = 0;
    for (auto& a : config.mag_adc) a.bits = 0;
    config.mag_ref_adc.bits = 0;
    Random rng(31);
    double worst[2] = {0, 0};
    for (int n = 0; n < 2000; ++n) {
        const Scene sc = random_scene<T>(rng, 20.0);
        for (int k = 0; k < 2; ++k) {
            config.solver = k == 0 ? SolverKind::qmethod : SolverKind::fast;
            const auto r = estimate_sample(raw_inputs(sc, config, 45e-6), config);
            ASSERT_TRUE(r.valid && r.sun_valid && r.mag_valid);
            worst[k] = std::max(worst[k], attitude_angle(to_eigen(r.a), sc.a_true));
            const Eigen::Vector3d s = sc.a_true * sc.sun_ref;
            for (int i = 0; i < 3; ++i) ASSERT_NEAR(r.sun_meas[i], s[i], tol<T>(1e-5, 1e-12));
            EXPECT_NEAR(r.sun_norm, 1.0, tol<T>(1e-5, 1e-12));
        }
    }
    std::printf("[%s] whole sample, ideal ADC, 2000 scenes: worst attitude error qmethod %.3g rad, fast %.3g rad\n",
                std::is_same_v<T, float> ? "float" : "double", worst[0], worst[1]);
    EXPECT_LT(worst[0], tol<T>(5e-5, 1e-9));
    EXPECT_LT(worst[1], tol<T>(5e-5, 1e-9));
}

TYPED_TEST(EstimatorCoreSample, TwelveBitQuantizationStaysWithinItsBound) {
    using T = TypeParam;
    // Hand bound: current LSB 4/4095 A with i_sc_norm = 1 A and |s| = 1 gives a sun direction error
    // <= √3 · ½ LSB = 8.5e-4 rad; voltage LSB 5/4095 V on both channel and reference gives <= √3 · 1 LSB /
    // (1e4 V/T · 45 µT) = 4.7e-3 rad on the field. With the two directions >= 30° apart the attitude error is
    // below (e_sun + e_mag) / sin 30° = 1.1e-2 rad.
    const double bound = (8.5e-4 + 4.7e-3) / 0.5;
    EstimatorConfig<T> config;
    Random rng(32);
    double worst = 0.0;
    bool quantized = false;
    for (int n = 0; n < 5000; ++n) {
        const Scene sc = random_scene<T>(rng, 30.0);
        const auto r = estimate_sample(raw_inputs(sc, config, 45e-6), config);
        ASSERT_TRUE(r.valid);
        const double e = attitude_angle(to_eigen(r.a), sc.a_true);
        worst = std::max(worst, e);
        quantized = quantized || e > 1e-5;
    }
    std::printf("[%s] whole sample, 12-bit ADC, 5000 scenes: worst attitude error %.3g rad (bound %.3g)\n",
                std::is_same_v<T, float> ? "float" : "double", worst, bound);
    EXPECT_LT(worst, bound);
    EXPECT_TRUE(quantized);
}

TYPED_TEST(EstimatorCoreSample, EclipseRailAndParallelAreInvalid) {
    using T = TypeParam;
    EstimatorConfig<T> config;
    Random rng(33);
    const Scene sc = random_scene<T>(rng, 30.0);
    SampleInputs<T> in = raw_inputs(sc, config, 45e-6);
    ASSERT_TRUE(estimate_sample(in, config).valid);

    SampleInputs<T> dark = in;  // eclipse: only 0.2 of full sun (albedo)
    for (auto& i : dark.i_sh) i *= T(0.2);
    auto r = estimate_sample(dark, config);
    EXPECT_FALSE(r.sun_valid);
    EXPECT_TRUE(r.mag_valid);
    EXPECT_FALSE(r.valid);
    EXPECT_EQ(r.q.w, T(1));
    EXPECT_EQ(r.a[0], T(1));

    SampleInputs<T> railed = in;  // field beyond the sensor's range: a channel pinned at 5 V
    railed.v_mag[1] = T(5.3);
    r = estimate_sample(railed, config);
    EXPECT_TRUE(r.sun_valid);
    EXPECT_FALSE(r.mag_valid);
    EXPECT_FALSE(r.valid);

    SampleInputs<T> parallel = in;  // field along the sun line in both frames
    Scene p = sc;
    p.mag_ref = -sc.sun_ref;
    parallel = raw_inputs(p, config, 45e-6);
    r = estimate_sample(parallel, config);
    EXPECT_TRUE(r.sun_valid && r.mag_valid);
    EXPECT_FALSE(r.valid);
}

TYPED_TEST(EstimatorCoreSample, SolversAgreeAndLossIsSmallForConsistentData) {
    using T = TypeParam;
    EstimatorConfig<T> config;
    Random rng(34);
    for (int n = 0; n < 500; ++n) {
        const Scene sc = random_scene<T>(rng, 30.0);
        const SampleInputs<T> in = raw_inputs(sc, config, 30e-6);
        config.solver = SolverKind::qmethod;
        const auto q = estimate_sample(in, config);
        config.solver = SolverKind::fast;
        const auto f = estimate_sample(in, config);
        ASSERT_TRUE(q.valid && f.valid);
        EXPECT_LT(attitude_angle(to_eigen(q.a), to_eigen(f.a)), tol<T>(5e-5, 1e-11));
        // Loss of quantized but consistent vectors: ½ Σ a |δ|² with |δ| <= 1.1e-2 → < 1e-4.
        EXPECT_LT(f.loss, T(1e-4));
    }
}

}  // namespace
}  // namespace attitude_estimator::test
