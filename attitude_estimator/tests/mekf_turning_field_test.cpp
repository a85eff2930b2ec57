// The field's σ before the in-flight calibration from its turn through the uncalibrated sensor (mekf.hpp,
// MekfConfig::mag_turn_fluctuation, mag_turn_correlation): 1σ fluctuation correlated over τ = 1/|ω̂| (at most
// the correlation), weighed as white noise σ √(2τ/Δt). Checked against the closed form of one field update after
// one step from an isotropic attitude covariance σ₀² I, the rate along the field (z) and known, no process noise:
// the variance about x and y becomes 1 / (1/σ₀² + |B|²/σ²), about z it stays σ₀².
#include <cmath>

#include "attitude_estimator/mekf.hpp"
#include "mekf_variances.hpp"
#include "test_support.hpp"

namespace attitude_estimator::test {
namespace {

template <class T>
class EstimatorCoreMekfTurningField : public ::testing::Test {};
TYPED_TEST_SUITE(EstimatorCoreMekfTurningField, Scalars, ScalarName);

constexpr double kStartSigma = 0.5;     // rad, per axis
constexpr double kField = 40e-6;        // T, along z
constexpr double kStep = 0.05;          // s, one 20 Hz sample
constexpr double kFluctuation = 1e-7;   // T
constexpr double kCorrelation = 200.0;  // s
constexpr double kUncalibrated = 100e-6;
constexpr double kCalibrated = 1.5e-6;

template <class T>
MekfConfig<T> config(double fluctuation) {
    MekfConfig<T> c;
    c.estimate_offset = false;
    c.init_attitude_sigma = T(kStartSigma);
    c.init_rate_sigma = T(1e-12);  // the rate known: the attitude's covariance stays isotropic over the step
    c.attitude_noise = T(0);
    c.rate_noise = T(0);
    c.mag_sigma = T(kUncalibrated);
    c.mag_sigma_calibrated = T(kCalibrated);
    c.mag_turn_fluctuation = T(fluctuation);
    c.mag_turn_correlation = T(kCorrelation);
    return c;
}

// Started at t = 10 s turning at `rate` about z, one sample a step later with the field alone; the attitude
// covariance's diagonal.
template <class T>
std::array<double, 3> after_one_step(const MekfConfig<T>& c, double rate, bool calibrated) {
    MekfState<T> s;
    mekf_start(s, Quaternion<T>{T(0), T(0), T(0), T(1)}, Vec3<T>{T(0), T(0), T(rate)}, T(10), c);
    MekfSampleInputs<T> in;
    in.t = T(10 + kStep);
    in.mag_valid = true;
    in.mag_calibrated = calibrated;
    in.mag_ref = {T(0), T(0), T(kField)};
    in.mag_body = in.mag_ref;  // turned about z: still along z
    mekf_sample(s, in, c);
    return attitude_variances(s);
}

double closed_form(double sigma) {
    return variance_after_one_field(kStartSigma, kField, sigma);
}

TYPED_TEST(EstimatorCoreMekfTurningField, ATumbleSetsTheCorrelationAndTheSigma) {
    using T = TypeParam;
    // 0.05 rad/s: τ = 20 s, σ = 100 nT √(2 · 20 / 0.05) = 2.83 µT.
    const double sigma = kFluctuation * std::sqrt(2.0 * 20.0 / kStep);
    const auto p = after_one_step(config<T>(kFluctuation), 0.05, false);
    EXPECT_NEAR(p[0], closed_form(sigma), tol<T>(1e-3, 1e-9) * closed_form(sigma));
    EXPECT_NEAR(p[1], closed_form(sigma), tol<T>(1e-3, 1e-9) * closed_form(sigma));
    EXPECT_NEAR(p[2], kStartSigma * kStartSigma, tol<T>(1e-5, 1e-12));
}

TYPED_TEST(EstimatorCoreMekfTurningField, ASlowTumbleIsCappedAtTheCorrelation) {
    using T = TypeParam;
    // 0.001 rad/s would be τ = 1000 s: held at 200 s, σ = 100 nT √(2 · 200 / 0.05) = 8.94 µT.
    const double sigma = kFluctuation * std::sqrt(2.0 * kCorrelation / kStep);
    const auto p = after_one_step(config<T>(kFluctuation), 0.001, false);
    EXPECT_NEAR(p[0], closed_form(sigma), tol<T>(1e-3, 1e-9) * closed_form(sigma));
}

TYPED_TEST(EstimatorCoreMekfTurningField, OffOrCalibratedTheSigmaIsAsSet) {
    using T = TypeParam;
    const auto off = after_one_step(config<T>(0.0), 0.05, false);
    EXPECT_NEAR(off[0], closed_form(kUncalibrated), tol<T>(1e-3, 1e-9) * closed_form(kUncalibrated));
    const auto calibrated = after_one_step(config<T>(kFluctuation), 0.05, true);
    EXPECT_NEAR(calibrated[0], closed_form(kCalibrated), tol<T>(1e-3, 1e-9) * closed_form(kCalibrated));
}

}  // namespace
}  // namespace attitude_estimator::test
