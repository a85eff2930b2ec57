// In-flight magnetometer calibration (mag_calibration.hpp): a sensor with known scale errors, cross-axis
// coupling and a field of the spacecraft's own read over many field directions and magnitudes; the
// calibration, given only the reference field's magnitude, must return I + D = M⁻¹ (Eigen's inverse of the
// simulated sensor matrix) and b = M⁻¹ b_own, and the corrected fields must match the true ones.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <random>

#include "attitude_estimator/mag_calibration.hpp"

namespace {

using namespace attitude_estimator;

struct Truth {
    Eigen::Matrix3d m;  // reading = M B + b_own (the set/reset offset estimate taken out)
    Eigen::Vector3d b_own;
};

Truth sensor() {
    Truth t;
    const double c = 0.003;  // the HMC2003 model's cross-axis coupling (symmetric)
    t.m << 1.01, c, c, c, 0.995, c, c, c, 1.004;
    t.b_own = Eigen::Vector3d(0.4e-6, -0.25e-6, 0.1e-6);
    return t;
}

template <class T>
MagCalibrationState<T> calibrate(const Truth& t, int equations, double noise, std::uint32_t seed) {
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
        const Eigen::Vector3d h = t.m * b + t.b_own + noise * Eigen::Vector3d(n01(gen), n01(gen), n01(gen));
        mag_calibration_offer(s, Vec3<T>{T(h(0)), T(h(1)), T(h(2))}, T(b.norm()), cfg);
    }
    return s;
}

template <class T>
void expect_recovered(const MagCalibrationState<T>& s, const Truth& t, double gain_tol, double offset_tol) {
    ASSERT_TRUE(s.valid);
    const Eigen::Matrix3d inv = t.m.inverse();
    const Eigen::Vector3d b = inv * t.b_own;
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(double(s.offset[i]), b(i), offset_tol) << i;
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(double(s.gain[3 * i + j]), inv(i, j), gain_tol) << i << j;
    }
}

TEST(EstimatorCoreMagCalibration, RecoversScaleCrossAxisAndOffsetFromTheMagnitudeAlone) {
    const Truth t = sensor();
    expect_recovered(calibrate<double>(t, 2000, 0.0, 1), t, 1e-9, 1e-13);
}

TEST(EstimatorCoreMagCalibration, TakesTheSpacecraftsDipoleAtEitherPolarity) {
    // The block's cadence: a set/reset pulse every sample (the polarity alternates), an equation every 20th
    // sample, so every equation is taken at the same polarity. The spacecraft's residual dipole (7.3 µT,
    // leo_orbit's) is fixed in body axes in the reading at both polarities, as the earth's field is; a
    // residual of the sensor's own offset (20 nT) changes sign with the polarity. The corrected field must be
    // the true one at both polarities, to that residual and the noise: a calibration that took the dipole as
    // an offset flipping with the polarity corrects one polarity and doubles the dipole (14.6 µT) at the other.
    const Eigen::Vector3d dipole(0.0, 0.0, 7.29e-6);
    const Eigen::Vector3d residual(20e-9, -15e-9, 10e-9);
    MagCalibrationConfig<double> cfg;
    cfg.sigma = 10e-9;  // the readings' noise (4 nT) and the residual's share
    MagCalibrationState<double> s;
    std::mt19937 gen(5);
    std::normal_distribution<double> n01(0.0, 1.0);
    const auto truth = [](int k) {  // a tumbling spacecraft (one turn in 600 samples) in a 25-45 µT field
        const double a = 2.0 * M_PI * k / 600.0, b = 2.0 * M_PI * k / 1370.0;
        const Eigen::Vector3d dir(std::cos(a) * std::cos(b), std::sin(a) * std::cos(b), std::sin(b));
        return Eigen::Vector3d(dir * (35e-6 + 10e-6 * std::sin(2.0 * M_PI * k / 5000.0)));
    };
    const auto reading = [&](const Eigen::Vector3d& b, double p) {
        return Eigen::Vector3d(b + dipole + p * residual + 4e-9 * Eigen::Vector3d(n01(gen), n01(gen), n01(gen)));
    };
    for (int k = 0; k < 20 * 1200; ++k) {
        const Eigen::Vector3d b = truth(k);
        const Eigen::Vector3d h = reading(b, k % 2 ? -1.0 : 1.0);
        mag_calibration_offer(s, Vec3<double>{h(0), h(1), h(2)}, b.norm(), cfg);
    }
    ASSERT_TRUE(s.valid);
    for (const double p : {1.0, -1.0}) {
        const Eigen::Vector3d b(30e-6, -20e-6, 10e-6);
        const Eigen::Vector3d h = reading(b, p);
        const auto c = mag_calibration_apply(s, Vec3<double>{h(0), h(1), h(2)});
        EXPECT_LT((Eigen::Vector3d(c[0], c[1], c[2]) - b).norm(), 100e-9) << "polarity " << p;
    }
}

TEST(EstimatorCoreMagCalibration, NoisyReadingsInFloatStillResolveTheCoupling) {
    // 40 nT per axis (ten times the HMC2003's noise, about a third of a 12-bit step): the 0.3 % coupling
    // (3e-3) must come out to a tenth of itself.
    const Truth t = sensor();
    expect_recovered(calibrate<double>(t, 6000, 40e-9, 3), t, 3e-4, 30e-9);
    expect_recovered(calibrate<float>(t, 6000, 40e-9, 3), t, 3e-4, 30e-9);
    const auto s = calibrate<double>(t, 6000, 40e-9, 4);
    // The corrected field of a fresh reading is the true field.
    const Eigen::Vector3d b(30e-6, -20e-6, 10e-6);
    const Eigen::Vector3d h = t.m * b + t.b_own;
    const auto c = mag_calibration_apply(s, Vec3<double>{h(0), h(1), h(2)});
    EXPECT_LT((Eigen::Vector3d(c[0], c[1], c[2]) - b).norm(), 20e-9);
}

TEST(EstimatorCoreMagCalibration, NothingAppliedWithoutEnoughRotation) {
    // The field always along one axis: the other axes' scale is not observable, the solve refuses.
    MagCalibrationConfig<double> cfg;
    cfg.every = 1;
    cfg.min_equations = 100;
    cfg.solve_every = 100;
    MagCalibrationState<double> s;
    for (int k = 0; k < 100; ++k) mag_calibration_offer(s, Vec3<double>{30e-6 + k * 1e-8, 0.0, 0.0}, 30e-6, cfg);
    EXPECT_EQ(s.equations, 100);
    EXPECT_FALSE(s.valid);
    const auto same = mag_calibration_apply(s, Vec3<double>{1e-6, 2e-6, 3e-6});
    EXPECT_EQ(same[2], 3e-6);
}

}  // namespace
