// The divergence watch of the MEKF (MekfConfig::watch_time, watch_sun; docs/filter.md, "The watch"). The truth is the
// exact solution of a constant-rate tumble (2.9 deg/s, issue 39's lost scene) in a fixed inertial field and
// sun; the field errs by a correlated error (0.2 µT per axis, first-order Gauss–Markov over 60 s, as the
// currents' field on leo_orbit) that the filter weighs, as leo_orbit does, as white noise of the same
// information, 0.2 µT · √(2 · 60 s / 0.05 s) = 9.8 µT. Weighed so, no single field can refuse a 4 µT error.
#include <algorithm>
#include <cmath>
#include <vector>

#include "attitude_estimator/mekf.hpp"
#include "test_support.hpp"

namespace attitude_estimator::test {
namespace {

template <class T>
class EstimatorCoreMekfWatch : public ::testing::Test {};
TYPED_TEST_SUITE(EstimatorCoreMekfWatch, Scalars, ScalarName);

const Eigen::Vector3d kOmega = 0.0506 * Eigen::Vector3d(0.6, -0.3, 0.74).normalized();  // rad/s: 2.9 deg/s
const Eigen::Vector3d kSunRef = Eigen::Vector3d(0.3, -0.8, 0.5).normalized();
const Eigen::Vector3d kFieldRef(-12e-6, 25e-6, 30e-6);  // T
constexpr double kPeriod = 0.05;                        // s
constexpr double kFieldSigma = 0.2e-6;                  // T per axis, the correlated error's
constexpr double kFieldTau = 60.0;                      // s

template <class T>
MekfConfig<T> leo_like(double watch_time, bool watch_sun = false) {
    MekfConfig<T> c;
    c.watch_sun = watch_sun;
    c.estimate_offset = false;
    c.rate_noise = T(1e-7);
    c.sun_sigma = T(0.02 * std::sqrt(2.0 * 50.0 / kPeriod));  // 0.02 rad correlated over 50 s, as weighed
    if (watch_sun) {
        // The same weighting given as leo_orbit gives it (the filter turns it into white noise per sample), so
        // that the sun's watch knows the correlated error's own size.
        c.sun_sigma = T(0.02);
        c.sun_correlation_time = T(50);
    }
    c.mag_sigma = T(kFieldSigma * std::sqrt(2.0 * kFieldTau / kPeriod));
    c.watch_time = T(watch_time);
    return c;
}

struct Outcome {
    int resets = 0;
    double first_reset = -1;         // s (-1: none)
    std::vector<double> late_error;  // rad, over the last third
    double late_nees = 0;            // mean δθᵀ P⁻¹ δθ / 3 over the last third
};

// Runs `duration` s from state s (already started, or not: then from the single-frame attitudes).
template <class T>
Outcome run(MekfState<T>& s, const MekfConfig<T>& c, const Eigen::Matrix3d& a0, double duration, std::uint64_t seed) {
    Random rng(seed);
    GaussMarkov3 field_error(kFieldSigma, kFieldTau, kPeriod, rng);
    GaussMarkov3 sun_error(0.02, 50.0, kPeriod, rng);
    Outcome o;
    int late = 0;
    const int n = static_cast<int>(duration / kPeriod);
    for (int k = 0; k <= n; ++k) {
        const double t = k * kPeriod;
        const Eigen::Matrix3d a = turn(kOmega, t) * a0;
        const Eigen::Vector3d field_noise = field_error.step(rng), sun_noise = sun_error.step(rng);
        MekfSampleInputs<T> in;
        in.t = static_cast<T>(t);
        in.attitude_valid = true;
        in.q_single = quaternion_of<T>(rng.rotation(0.01) * a);
        in.sun_valid = true;
        in.sun_ref = to_vec<T>(kSunRef);
        in.sun_body = to_vec<T>((a * kSunRef + sun_noise).normalized());
        in.mag_valid = true;
        in.mag_ref = to_vec<T>(kFieldRef);
        in.mag_body = to_vec<T>(a * kFieldRef + field_noise);
        const MekfSampleResult<T> r = mekf_sample(s, in, c);
        o.resets += r.reset;
        if (r.reset && o.first_reset < 0) o.first_reset = t;
        if (k > 2 * n / 3 && s.stage == 2) {
            const Eigen::Matrix3d d = a * matrix_of(s.q).transpose();  // I − [δθ×]
            const Eigen::Vector3d dtheta(d(1, 2), d(2, 0), d(0, 1));
            Eigen::Matrix3d p;
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) p(i, j) = static_cast<double>(s.p[i * kMekfStates + j]);
            o.late_error.push_back(attitude_angle(matrix_of(s.q), a));
            o.late_nees += dtheta.dot(p.ldlt().solve(dtheta)) / 3.0;
            ++late;
        }
    }
    if (late > 0) o.late_nees /= late;
    return o;
}

double percentile(std::vector<double> v, double p) {
    std::sort(v.begin(), v.end());
    return v[static_cast<std::size_t>(p * static_cast<double>(v.size() - 1))];
}

// A filter that has lost the attitude but is sure of it: 8 deg off (perpendicular to the field), P_θθ of
// 0.1 deg and a rate known to 1e-5 rad/s, as a converged filter's. The field's innovation (5.7 µT) is within
// the innovation test at 9.8 µT, the sun's too: without the watch nothing refuses, nothing resets, and the
// weak updates leave it degrees off for ten minutes. With it, the averaged field says it is lost; it
// restarts from the single-frame attitude and is consistent again.
template <class T>
Outcome lost_start(double watch_time) {
    Random rng(5);
    const Eigen::Matrix3d a0 = rng.rotation();
    const Eigen::Vector3d axis = (a0 * kFieldRef).cross(Eigen::Vector3d(0.2, 0.9, -0.4)).normalized();
    MekfConfig<T> confident = leo_like<T>(watch_time);
    confident.init_attitude_sigma = T(0.1 * M_PI / 180.0);
    confident.init_rate_sigma = T(1e-5);
    MekfState<T> s;
    const Eigen::Matrix3d wrong = Eigen::AngleAxisd(8.0 * M_PI / 180.0, axis).toRotationMatrix() * a0;
    mekf_start(s, quaternion_of<T>(wrong), to_vec<T>(kOmega), T(0), confident);
    return run<T>(s, leo_like<T>(watch_time), a0, 600.0, 17);
}

TYPED_TEST(EstimatorCoreMekfWatch, WithoutTheWatchALostButConfidentFilterStaysLost) {
    // What the watch is for (issue 39's noon–midnight scene: NEES/dof 1267, valid, no reset).
    const Outcome o = lost_start<TypeParam>(0.0);
    EXPECT_EQ(o.resets, 0);
    EXPECT_GT(percentile(o.late_error, 0.5), 3.0 * M_PI / 180.0);
    EXPECT_GT(o.late_nees, 100.0);
}

TYPED_TEST(EstimatorCoreMekfWatch, ALostButConfidentFilterIsFoundAndResetToTheSingleFrameAttitude) {
    const Outcome o = lost_start<TypeParam>(300.0);
    EXPECT_EQ(o.resets, 1);
    EXPECT_LT(percentile(o.late_error, 0.95), 1.0 * M_PI / 180.0);
    EXPECT_GT(o.late_nees, 0.2);
    EXPECT_LT(o.late_nees, 2.0);
}

TYPED_TEST(EstimatorCoreMekfWatch, AConsistentFilterUnderCorrelatedFieldErrorsIsNeverReset) {
    // 25 minutes from the single-frame start, three seeds: the correlated field and sun errors averaged over
    // the watch's 300 s are what their white-noise weighting says, and the watch stays quiet, on the field
    // alone and on both.
    for (const bool watch_sun : {false, true})
        for (std::uint64_t seed : {1u, 2u, 3u}) {
            Random rng(100 + seed);
            MekfState<TypeParam> s;
            const Outcome o = run<TypeParam>(s, leo_like<TypeParam>(300.0, watch_sun), rng.rotation(), 1500.0, seed);
            EXPECT_EQ(o.resets, 0) << "seed " << seed << " watch_sun " << watch_sun;
            EXPECT_LT(percentile(o.late_error, 0.95), 1.0 * M_PI / 180.0) << "seed " << seed;
        }
}

// Lost about the field (MekfConfig::watch_sun; robustness seed 42's run 23): a filter sure of itself (P_θθ of
// 0.1 deg, the rate known to 1e-5 rad/s) but 60 deg off about the field's direction. The field is fixed in
// inertial axes, so its prediction is exact and the field's watch sees nothing until the sun's weak updates
// have pulled the attitude off the field (618 s here); the sun's innovation, 2 sin(30 deg) sin θ with θ the
// sun's angle from the field, is far inside the innovation test of a sun weighed as 0.89 rad of white noise:
// nothing refuses. The sun's watch averages the squared innovation over the sun's own 0.02 rad and the covariance
// (a ratio near 800), reaches its gate of 16 within seconds, and the restart from the single-frame attitude is
// consistent.
template <class T>
Outcome lost_about_the_field(bool watch_sun, double duration) {
    Random rng(7);
    const Eigen::Matrix3d a0 = rng.rotation();
    const Eigen::Vector3d axis = kFieldRef.normalized();  // inertial
    MekfConfig<T> confident = leo_like<T>(300.0, watch_sun);
    confident.init_attitude_sigma = T(0.1 * M_PI / 180.0);
    confident.init_rate_sigma = T(1e-5);
    MekfState<T> s;
    // A turn about the inertial field: A' = A R(axis)ᵀ leaves A' B_ref = A B_ref.
    const Eigen::Matrix3d wrong = a0 * Eigen::AngleAxisd(60.0 * M_PI / 180.0, axis).toRotationMatrix().transpose();
    mekf_start(s, quaternion_of<T>(wrong), to_vec<T>(kOmega), T(0), confident);
    return run<T>(s, leo_like<T>(300.0, watch_sun), a0, duration, 19);
}

TYPED_TEST(EstimatorCoreMekfWatch, LostAboutTheFieldOnlyTheSunsWatchFindsIt) {
    // The field's watch alone: ten minutes lost (400-600 s), nothing reset.
    const Outcome field_only = lost_about_the_field<TypeParam>(false, 600.0);
    EXPECT_EQ(field_only.resets, 0);
    EXPECT_GT(percentile(field_only.late_error, 0.5), 10.0 * M_PI / 180.0);
    EXPECT_GT(field_only.late_nees, 100.0);
    // With the sun's: reset in the first seconds, then right and consistent (600-900 s).
    const Outcome both = lost_about_the_field<TypeParam>(true, 900.0);
    EXPECT_EQ(both.resets, 1);
    EXPECT_GT(both.first_reset, 0.0);
    EXPECT_LT(both.first_reset, 10.0);
    EXPECT_LT(percentile(both.late_error, 0.95), 1.0 * M_PI / 180.0);
    EXPECT_GT(both.late_nees, 0.2);
    EXPECT_LT(both.late_nees, 2.0);
}

}  // namespace
}  // namespace attitude_estimator::test
