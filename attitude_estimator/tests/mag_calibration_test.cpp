// In-flight magnetometer calibration (mag_calibration.hpp): a sensor with known scale errors, cross-axis
// coupling and offset read over many field directions and magnitudes; the calibration, given only the
// reference field's magnitude, must return I + D = M⁻¹ (Eigen's inverse of the simulated sensor matrix)
// and b = M⁻¹ b_sensor, and the corrected fields must match the true ones.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <random>

#include "attitude_estimator/mag_calibration.hpp"

namespace {

using namespace attitude_estimator;

struct Truth {
    Eigen::Matrix3d m;  // reading = M B + p b_sensor
    Eigen::Vector3d b_sensor;
};

Truth sensor() {
    Truth t;
    const double c = 0.003;  // the HMC2003 model's cross-axis coupling (symmetric)
    t.m << 1.01, c, c, c, 0.995, c, c, c, 1.004;
    t.b_sensor = Eigen::Vector3d(0.4e-6, -0.25e-6, 0.1e-6);
    return t;
}

template <class T>
MagCalibrationState<T> calibrate(const Truth& t, int equations, double noise, bool alternate, std::uint32_t seed) {
    MagCalibrationConfig<T> cfg;
    cfg.every = 1;
    cfg.min_equations = equations;
    cfg.solve_every = equations;
    cfg.sigma = T(std::max(noise, 1e-9));  // the readings' noise, as the block's mag_calibration_sigma states it
    MagCalibrationState<T> s;
    std::mt19937 gen(seed);
    std::normal_distribution<double> n01(0.0, 1.0);
    std::uniform_real_distribution<double> mag(20e-6, 50e-6);
    for (int k = 0; k < equations; ++k) {
        Eigen::Vector3d dir(n01(gen), n01(gen), n01(gen));
        const Eigen::Vector3d b = dir.normalized() * mag(gen);
        const double p = alternate && (k % 2) ? -1.0 : 1.0;
        const Eigen::Vector3d h = t.m * b + p * t.b_sensor + noise * Eigen::Vector3d(n01(gen), n01(gen), n01(gen));
        mag_calibration_offer(s, Vec3<T>{T(h(0)), T(h(1)), T(h(2))}, T(p), T(b.norm()), cfg);
    }
    return s;
}

template <class T>
void expect_recovered(const MagCalibrationState<T>& s, const Truth& t, double gain_tol, double offset_tol) {
    ASSERT_TRUE(s.valid);
    const Eigen::Matrix3d inv = t.m.inverse();
    const Eigen::Vector3d b = inv * t.b_sensor;
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(double(s.offset[i]), b(i), offset_tol) << i;
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(double(s.gain[3 * i + j]), inv(i, j), gain_tol) << i << j;
    }
}

TEST(EstimatorCoreMagCalibration, RecoversScaleCrossAxisAndOffsetFromTheMagnitudeAlone) {
    const Truth t = sensor();
    expect_recovered(calibrate<double>(t, 2000, 0.0, false, 1), t, 1e-9, 1e-13);
    // With the set/reset polarity alternating, the offset keeps its sign while the field term flips.
    expect_recovered(calibrate<double>(t, 2000, 0.0, true, 2), t, 1e-9, 1e-13);
}

TEST(EstimatorCoreMagCalibration, NoisyReadingsInFloatStillResolveTheCoupling) {
    // 40 nT per axis (ten times the HMC2003's noise, about a third of a 12-bit step): the 0.3 % coupling
    // (3e-3) must come out to a tenth of itself.
    const Truth t = sensor();
    expect_recovered(calibrate<double>(t, 6000, 40e-9, true, 3), t, 3e-4, 30e-9);
    expect_recovered(calibrate<float>(t, 6000, 40e-9, true, 3), t, 3e-4, 30e-9);
    const auto s = calibrate<double>(t, 6000, 40e-9, true, 4);
    // The corrected field of a fresh reading is the true field.
    const Eigen::Vector3d b(30e-6, -20e-6, 10e-6);
    const Eigen::Vector3d h = t.m * b - t.b_sensor;
    const auto c = mag_calibration_apply(s, Vec3<double>{h(0), h(1), h(2)}, -1.0);
    EXPECT_LT((Eigen::Vector3d(c[0], c[1], c[2]) - b).norm(), 20e-9);
}

TEST(EstimatorCoreMagCalibration, NothingAppliedWithoutEnoughRotation) {
    // The field always along one axis: the other axes' scale is not observable, the solve refuses.
    MagCalibrationConfig<double> cfg;
    cfg.every = 1;
    cfg.min_equations = 100;
    cfg.solve_every = 100;
    MagCalibrationState<double> s;
    for (int k = 0; k < 100; ++k) mag_calibration_offer(s, Vec3<double>{30e-6 + k * 1e-8, 0.0, 0.0}, 1.0, 30e-6, cfg);
    EXPECT_EQ(s.equations, 100);
    EXPECT_FALSE(s.valid);
    const auto same = mag_calibration_apply(s, Vec3<double>{1e-6, 2e-6, 3e-6}, 1.0);
    EXPECT_EQ(same[2], 3e-6);
}

}  // namespace
