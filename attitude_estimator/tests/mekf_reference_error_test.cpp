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

}  // namespace
}  // namespace attitude_estimator::test
