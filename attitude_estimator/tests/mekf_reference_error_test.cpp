// The reference field's error along the orbit (mekf.hpp, MekfConfig::mag_ref_rms, mag_ref_correlation): an rms σ
// correlated over τ, weighed per field update as σ² (2τ/Δt) T/(T + τ), T the filter's memory (MekfState::memory:
// its attitude variance over the rate the propagation adds to it). Checked against closed forms of one step from
// an isotropic attitude covariance σ₀² I with the rate known and only attitude noise q_a: the step adds q_a Δt per
// axis, so T = σ₀²/q_a, and the field update along z leaves x and y at 1 / (1/(σ₀² + q_a Δt) + |B|²/R).
#include <cmath>

#include "attitude_estimator/mekf.hpp"
#include "mekf_variances.hpp"
#include "test_support.hpp"

namespace attitude_estimator::test {
namespace {

template <class T>
class EstimatorCoreMekfReferenceError : public ::testing::Test {};
TYPED_TEST_SUITE(EstimatorCoreMekfReferenceError, Scalars, ScalarName);

constexpr double kStartSigma = 0.01;  // rad, per axis
constexpr double kField = 40e-6;      // T, along z
constexpr double kStep = 0.05;        // s, one 20 Hz sample
constexpr double kMagSigma = 1e-6;    // T
constexpr double kRms = 30e-9;        // T: the omitted degrees' size at a LEO altitude
constexpr double kTau = 150.0;        // s

template <class T>
MekfConfig<T> config(double attitude_noise, double correlation) {
    MekfConfig<T> c;
    c.estimate_offset = false;
    c.init_attitude_sigma = T(kStartSigma);
    c.init_rate_sigma = T(1e-12);  // the rate known: only the attitude noise grows the covariance
    c.attitude_noise = T(attitude_noise);
    c.rate_noise = T(0);
    c.mag_sigma = T(kMagSigma);
    c.mag_ref_rms = T(kRms);
    c.mag_ref_correlation = T(correlation);
    return c;
}

struct OneStep {
    double memory;
    std::array<double, 3> p;
};

template <class T>
OneStep after_one_step(const MekfConfig<T>& c, double unknown = 0.0) {
    MekfState<T> s;
    mekf_start(s, Quaternion<T>{T(0), T(0), T(0), T(1)}, Vec3<T>{}, T(10), c);
    MekfSampleInputs<T> in;
    in.t = T(10 + kStep);
    in.mag_valid = true;
    in.mag_ref = {T(0), T(0), T(kField)};
    in.mag_body = in.mag_ref;
    in.mag_unknown_sigma = T(unknown);
    mekf_sample(s, in, c);
    return {static_cast<double>(s.memory), attitude_variances(s)};
}

double across_field(double variance_before, double r) {
    return 1.0 / (1.0 / variance_before + kField * kField / r);
}

TYPED_TEST(EstimatorCoreMekfReferenceError, TheMemoryIsTheVarianceOverWhatTheProcessNoiseAdds) {
    using T = TypeParam;
    // q_a = σ₀²/100 s: a memory of 100 s.
    const double qa = kStartSigma * kStartSigma / 100.0;
    const OneStep one = after_one_step(config<T>(std::sqrt(qa), kTau));
    EXPECT_NEAR(one.memory, 100.0, tol<T>(2e-3, 1e-9) * 100.0);
    // σ² (2τ/Δt) T/(T + τ) = σ² · 6000 · 100/250.
    const double r = kMagSigma * kMagSigma + kRms * kRms * (2.0 * kTau / kStep) * 100.0 / (100.0 + kTau);
    const double before = kStartSigma * kStartSigma + qa * kStep;
    EXPECT_NEAR(one.p[0], across_field(before, r), tol<T>(1e-3, 1e-9) * across_field(before, r));
    EXPECT_NEAR(one.p[1], across_field(before, r), tol<T>(1e-3, 1e-9) * across_field(before, r));
    EXPECT_NEAR(one.p[2], before, tol<T>(1e-5, 1e-12));
}

TYPED_TEST(EstimatorCoreMekfReferenceError, ALongMemoryWeighsItAsItsWhiteEquivalent) {
    using T = TypeParam;
    // No process noise: nothing forgotten, memory 0 (not known), the white equivalent σ² 2τ/Δt.
    const OneStep one = after_one_step(config<T>(0.0, kTau));
    EXPECT_EQ(one.memory, 0.0);
    const double r = kMagSigma * kMagSigma + kRms * kRms * 2.0 * kTau / kStep;
    const double before = kStartSigma * kStartSigma;
    EXPECT_NEAR(one.p[0], across_field(before, r), tol<T>(1e-3, 1e-9) * across_field(before, r));
}

TYPED_TEST(EstimatorCoreMekfReferenceError, AMemoryShorterThanOneSampleKeepsItsOwnVariance) {
    using T = TypeParam;
    // A memory of 1 ms: σ² (2τ/Δt) T/(T + τ) would be 0.04 σ²; one sample's error is never below σ².
    const double qa = kStartSigma * kStartSigma / 1e-3;
    const OneStep one = after_one_step(config<T>(std::sqrt(qa), kTau));
    const double r = kMagSigma * kMagSigma + kRms * kRms;
    const double before = kStartSigma * kStartSigma + qa * kStep;
    EXPECT_NEAR(one.p[0], across_field(before, r), tol<T>(1e-3, 1e-9) * across_field(before, r));
}

// A part of the field known only within a range (MekfSampleInputs::mag_unknown_sigma: an excluded face's string)
// is weighed the same way, correlated over a radian of the tumble at most the reference's τ (here the rate is 0:
// τ itself), in quadrature with the reference's error.
TYPED_TEST(EstimatorCoreMekfReferenceError, AFieldKnownOnlyWithinARangeIsWeighedForTheMemoryToo) {
    using T = TypeParam;
    const double qa = kStartSigma * kStartSigma / 100.0, unknown = 200e-9;
    const OneStep one = after_one_step(config<T>(std::sqrt(qa), kTau), unknown);
    const double share = (2.0 * kTau / kStep) * 100.0 / (100.0 + kTau);
    const double r = kMagSigma * kMagSigma + (kRms * kRms + unknown * unknown) * share;
    const double before = kStartSigma * kStartSigma + qa * kStep;
    EXPECT_NEAR(one.p[0], across_field(before, r), tol<T>(1e-3, 1e-9) * across_field(before, r));
}

TYPED_TEST(EstimatorCoreMekfReferenceError, WithoutACorrelationTheRmsIsNotUsed) {
    using T = TypeParam;
    MekfConfig<T> c = config<T>(0.0, 0.0);
    c.mag_ref_sigma = T(2e-6);
    const OneStep one = after_one_step(c);
    const double r = kMagSigma * kMagSigma + 4e-12;
    const double before = kStartSigma * kStartSigma;
    EXPECT_NEAR(one.p[0], across_field(before, r), tol<T>(1e-3, 1e-9) * across_field(before, r));
}

// The reference's tilt (MekfConfig::mag_ref_tilt: the lag's turn of the field about the orbit's normal, a bias no
// memory averages) is considered, not estimated: the weights and so P are the filter's own, and what it reports
// and judges its validity by adds tilt² along the normal, r × v of the on-board orbit (v the wind plus the air's
// turn with the Earth), turned into the body. Here the orbit lies in the inertial x–y plane (normal +z) and the
// body is turned 90° about x, so the normal lies along a body axis across z; without an orbit, tilt²/3 per axis.
// A valid bound between the bounds with and without it tells them apart.
TYPED_TEST(EstimatorCoreMekfReferenceError, TheTiltIsConsideredAboutTheOrbitsNormalNotInTheWeights) {
    using T = TypeParam;
    const double tilt = 0.004, r = 6.9e6, speed = 7.6e3, earth = 7.292115e-5;  // rad, m, m/s, rad/s
    MekfConfig<T> plain = config<T>(0.0, kTau);
    MekfConfig<T> with_tilt = plain;
    with_tilt.mag_ref_tilt = T(tilt);
    const double half = std::sqrt(0.5);
    const Quaternion<T> q{T(half), T(0), T(0), T(half)};  // 90° about x
    const auto sample = [&](const MekfConfig<T>& c, MekfState<T>& s, bool orbit) {
        mekf_start(s, q, Vec3<T>{}, T(10), c);
        MekfSampleInputs<T> in;
        in.t = T(10 + kStep);
        in.mag_valid = true;
        in.mag_ref = {T(0), T(0), T(kField)};
        in.mag_body = to_vec<T>(matrix_of(q) * Eigen::Vector3d(0.0, 0.0, kField));
        if (orbit) {
            in.position = {T(r), T(0), T(0)};
            in.air_velocity = {T(0), T(speed - earth * r), T(0)};  // the air turns with the Earth
            in.air_density = T(1e-12);
        }
        return mekf_sample(s, in, c);
    };
    MekfState<T> a, b, c;
    const MekfSampleResult<T> without = sample(plain, a, true), with = sample(with_tilt, b, true);
    sample(with_tilt, c, false);
    const std::array<double, 3> pa = attitude_variances(a), pb = attitude_variances(b);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(pa[i], pb[i]) << i;
    const double trace = pa[0] + pa[1] + pa[2];
    EXPECT_NEAR(static_cast<double>(without.bound), 3.0 * std::sqrt(trace), tol<T>(1e-6, 1e-12));
    EXPECT_NEAR(static_cast<double>(with.bound), 3.0 * std::sqrt(trace + tilt * tilt), tol<T>(1e-6, 1e-12));
    const Eigen::Vector3d normal = matrix_of(q) * Eigen::Vector3d::UnitZ();  // the orbit's normal in the body
    const Matrix3RowMajor<T> reported = mekf_attitude_covariance(b, with_tilt);
    const Matrix3RowMajor<T> own = mekf_attitude_covariance(b, plain);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const double added = static_cast<double>(reported[3 * i + j] - own[3 * i + j]);
            EXPECT_NEAR(added, tilt * tilt * normal(i) * normal(j), tol<T>(1e-4, 1e-9) * tilt * tilt) << i << j;
        }
    const Matrix3RowMajor<T> no_orbit = mekf_attitude_covariance(c, with_tilt);
    for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(static_cast<double>(no_orbit[4 * i] - own[4 * i]), tilt * tilt / 3.0,
                    tol<T>(1e-4, 1e-9) * tilt * tilt)
            << i;
    // Valid below a bound halfway between: without the tilt, not with it.
    plain.valid_bound = with_tilt.valid_bound = T(0.5 * (without.bound + with.bound));
    EXPECT_TRUE(mekf_valid(a, plain));
    EXPECT_FALSE(mekf_valid(b, with_tilt));
}

}  // namespace
}  // namespace attitude_estimator::test
