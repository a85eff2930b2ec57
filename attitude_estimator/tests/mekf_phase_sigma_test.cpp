// The calibrated field's σ per phase (mekf.hpp, MekfConfig::mag_sigma_calibrated_eclipse): in a sample without a
// sun vector the field is weighed with its own σ, in sunlight with mag_sigma_calibrated. Checked against the
// closed form of one field update from an isotropic start covariance σ₀² I at the identity attitude with the
// field along z: the variance about x and y becomes 1 / (1/σ₀² + |B|²/σ²), about z it stays σ₀².
#include <cmath>

#include "attitude_estimator/mekf.hpp"
#include "mekf_variances.hpp"
#include "test_support.hpp"

namespace attitude_estimator::test {
namespace {

template <class T>
class EstimatorCoreMekfPhaseSigma : public ::testing::Test {};
TYPED_TEST_SUITE(EstimatorCoreMekfPhaseSigma, Scalars, ScalarName);

constexpr double kStartSigma = 0.5;  // rad, the start covariance per axis (the field, not it, decides)
constexpr double kField = 40e-6;     // T, along z
constexpr double kSunlit = 14e-6;    // T, mag_sigma_calibrated
constexpr double kEclipse = 6e-6;    // T, mag_sigma_calibrated_eclipse

template <class T>
MekfConfig<T> config(double eclipse_sigma) {
    MekfConfig<T> c;
    c.estimate_offset = false;  // the attitude alone: the closed form above
    c.init_attitude_sigma = T(kStartSigma);
    c.mag_sigma = T(100e-6);
    c.mag_sigma_calibrated = T(kSunlit);
    c.mag_sigma_calibrated_eclipse = T(eclipse_sigma);
    c.sun_sigma = T(0.5);
    return c;
}

// One sample at the start time (no propagation) with the calibrated field, the sun offered or not; returns the
// attitude covariance's diagonal.
template <class T>
std::array<double, 3> after_one_field(const MekfConfig<T>& c, bool sun) {
    MekfState<T> s;
    mekf_start(s, Quaternion<T>{T(0), T(0), T(0), T(1)}, Vec3<T>{T(0), T(0), T(0)}, T(10), c);
    MekfSampleInputs<T> in;
    in.t = T(10);
    in.mag_valid = true;
    in.mag_calibrated = true;
    in.mag_ref = {T(0), T(0), T(kField)};
    in.mag_body = in.mag_ref;
    in.sun_valid = sun;
    in.sun_ref = {T(0), T(0), T(1)};  // along the field: adds nothing about x and y's difference below
    in.sun_body = in.sun_ref;
    mekf_sample(s, in, c);
    return attitude_variances(s);
}

double closed_form(double sigma) {
    return variance_after_one_field(kStartSigma, kField, sigma);
}

TYPED_TEST(EstimatorCoreMekfPhaseSigma, EclipseFieldWeighedWithItsOwnSigma) {
    using T = TypeParam;
    const auto eclipse = after_one_field(config<T>(kEclipse), false);
    EXPECT_NEAR(eclipse[0], closed_form(kEclipse), tol<T>(1e-3, 1e-9) * closed_form(kEclipse));
    EXPECT_NEAR(eclipse[1], closed_form(kEclipse), tol<T>(1e-3, 1e-9) * closed_form(kEclipse));
    EXPECT_NEAR(eclipse[2], kStartSigma * kStartSigma, tol<T>(1e-5, 1e-12));
    // 0 leaves the eclipse at the sunlit σ.
    const auto same = after_one_field(config<T>(0.0), false);
    EXPECT_NEAR(same[0], closed_form(kSunlit), tol<T>(1e-3, 1e-9) * closed_form(kSunlit));
}

TYPED_TEST(EstimatorCoreMekfPhaseSigma, SunlitFieldKeepsTheCalibratedSigma) {
    using T = TypeParam;
    // With the sun along the field, the sun update adds to x and y alike: the eclipse σ must change nothing.
    const auto with = after_one_field(config<T>(kEclipse), true);
    const auto without = after_one_field(config<T>(0.0), true);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(with[i], without[i]) << i;
    EXPECT_GT(with[0], closed_form(kEclipse) * 1.5);  // far from the eclipse σ's figure
}

}  // namespace
}  // namespace attitude_estimator::test
