// The sun's correlation from the tumble (mekf.hpp, MekfConfig::sun_turn_correlation): the sun vector's error,
// 1σ sun_sigma, correlated over τ = 1/|ω̂| (at most sun_correlation_time), weighed as white noise σ √(2τ/Δt),
// Δt the time since the previous sun update. Checked against the closed form of two sun updates one step apart
// from an isotropic attitude covariance σ₀² I, the sun and the rate along z, the rate known, no process noise:
// the first update (no previous one: σ itself) and the second (σ √(2τ/Δt)) each take the variance about x and y
// to 1 / (1/v + 1/σ²); about z it stays σ₀².
#include <cmath>

#include "attitude_estimator/mekf.hpp"
#include "mekf_variances.hpp"
#include "test_support.hpp"

namespace attitude_estimator::test {
namespace {

template <class T>
class EstimatorCoreMekfSunTurn : public ::testing::Test {};
TYPED_TEST_SUITE(EstimatorCoreMekfSunTurn, Scalars, ScalarName);

constexpr double kStartSigma = 0.5;  // rad, per axis
constexpr double kStep = 0.05;       // s, one 20 Hz sample
constexpr double kSunSigma = 0.094;  // rad: the difference method's, leo_orbit.ssd
constexpr double kLongest = 200.0;   // s

template <class T>
MekfConfig<T> config(bool turn) {
    MekfConfig<T> c;
    c.estimate_offset = false;
    c.init_attitude_sigma = T(kStartSigma);
    c.init_rate_sigma = T(1e-12);  // the rate known: the attitude's covariance stays isotropic about z
    c.attitude_noise = T(0);
    c.rate_noise = T(0);
    c.sun_sigma = T(kSunSigma);
    c.sun_correlation_time = T(kLongest);
    c.sun_turn_correlation = turn;
    return c;
}

// Started at t = 10 s turning at `rate` about z, then two samples with the sun alone (along z) one step apart;
// the attitude covariance's diagonal.
template <class T>
std::array<double, 3> after_two_suns(const MekfConfig<T>& c, double rate) {
    MekfState<T> s;
    mekf_start(s, Quaternion<T>{T(0), T(0), T(0), T(1)}, Vec3<T>{T(0), T(0), T(rate)}, T(10), c);
    MekfSampleInputs<T> in;
    in.sun_valid = true;
    in.sun_ref = {T(0), T(0), T(1)};
    in.sun_body = in.sun_ref;  // turned about z: still along z
    for (int k = 1; k <= 2; ++k) {
        in.t = T(10 + k * kStep);
        mekf_sample(s, in, c);
    }
    return attitude_variances(s);
}

// The closed form: the first update at σ itself, the second at `second`.
double closed_form(double second) {
    const double first = variance_after_one_field(kStartSigma, 1.0, kSunSigma);
    return variance_after_one_field(std::sqrt(first), 1.0, second);
}

TYPED_TEST(EstimatorCoreMekfSunTurn, ATumbleSetsTheCorrelation) {
    using T = TypeParam;
    // 0.05 rad/s: τ = 20 s, σ = 0.094 √(2 · 20 / 0.05) = 2.66 rad.
    const double sigma = kSunSigma * std::sqrt(2.0 * 20.0 / kStep);
    const auto p = after_two_suns(config<T>(true), 0.05);
    EXPECT_NEAR(p[0], closed_form(sigma), tol<T>(1e-3, 1e-9) * closed_form(sigma));
    EXPECT_NEAR(p[1], closed_form(sigma), tol<T>(1e-3, 1e-9) * closed_form(sigma));
    EXPECT_NEAR(p[2], kStartSigma * kStartSigma, tol<T>(1e-5, 1e-12));
}

TYPED_TEST(EstimatorCoreMekfSunTurn, ASlowTumbleIsCappedAtTheLongestCorrelation) {
    using T = TypeParam;
    // 0.001 rad/s would be τ = 1000 s: held at 200 s.
    const double sigma = kSunSigma * std::sqrt(2.0 * kLongest / kStep);
    const auto p = after_two_suns(config<T>(true), 0.001);
    EXPECT_NEAR(p[0], closed_form(sigma), tol<T>(1e-3, 1e-9) * closed_form(sigma));
}

TYPED_TEST(EstimatorCoreMekfSunTurn, OffTheCorrelationIsAsSet) {
    using T = TypeParam;
    // The same tumble as above, but τ = 200 s whatever the rate.
    const double sigma = kSunSigma * std::sqrt(2.0 * kLongest / kStep);
    const auto p = after_two_suns(config<T>(false), 0.05);
    EXPECT_NEAR(p[0], closed_form(sigma), tol<T>(1e-3, 1e-9) * closed_form(sigma));
}

}  // namespace
}  // namespace attitude_estimator::test
