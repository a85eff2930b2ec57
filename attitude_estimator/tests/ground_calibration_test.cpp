// Issue 39: the ground calibration the computer starts from is derived from the scenario, never read from the
// truth: the residual dipole's field at the sensor from the spacecraft's magnetic budget (mag_prior_dipole, the
// system's dipole_moment) and the magnetometer's layout, plus the named error mag_prior_offset_error. Checked
// against the truth's own model of that field (the magnetometer block's SpacecraftField, zero currents).
#include <gtest/gtest.h>

#include <cmath>

#include "attitude_estimator/estimator_data.hpp"
#include "magnetometer/spacecraft_field.hpp"

namespace attitude_estimator {
namespace {

// leo_orbit's spacecraft: 0.05 A m² along body +z at the box's centre (harness/systems/leo_orbit.ssd).
constexpr magnetometer::Vec3 kDipole{0.0, 0.0, 0.05};

magnetometer::Vec3 truth_hard_iron() {
    magnetometer::SpacecraftLayout layout = magnetometer::default_layout();
    layout.dipole_moment = kDipole;
    return magnetometer::SpacecraftField(layout).at_sensor(magnetometer::PlantCurrents{});
}

EstimatorData leo_orbit_computer() {
    EstimatorData d;
    d.mag_calibration = true;
    d.mag_prior_offset_sigma = 0.5e-6;
    d.mag_prior_dipole = {kDipole[0], kDipole[1], kDipole[2]};
    return d;
}

TEST(GroundCalibration, TheComputersLayoutIsTheMagnetometersDefault) {
    const EstimatorData d;
    const magnetometer::SpacecraftLayout layout = magnetometer::default_layout();
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(d.mag_prior_sensor_position[i], layout.sensor_position[i]) << i;
        EXPECT_EQ(d.mag_prior_dipole_position[i], layout.dipole_position[i]) << i;
    }
}

TEST(GroundCalibration, DerivedOffsetIsTheTruthsHardIronWithinTheNamedError) {
    const EstimatorData d = leo_orbit_computer();
    const magnetometer::Vec3 truth = truth_hard_iron();
    // The magnetometer's README: 7.29 µT at the sensor for this dipole.
    EXPECT_NEAR(std::hypot(truth[0], truth[1], truth[2]), 7.29e-6, 0.01e-6);
    const Vec3<double> prior = ground_calibration_offset(d);
    for (std::size_t i = 0; i < 3; ++i) {
        const double error = d.mag_prior_offset_error[i];
        EXPECT_NEAR(prior[i] - truth[i], error, 1e-12) << "axis " << i;
        EXPECT_LE(std::abs(prior[i] - truth[i]), std::abs(error) + 1e-12) << "axis " << i;
        // The named error is a plausible residual for the 1σ the computer gives it (not a lucky zero either).
        EXPECT_LE(std::abs(error), 2.0 * d.mag_prior_offset_sigma) << "axis " << i;
        EXPECT_GE(std::abs(error), 0.2 * d.mag_prior_offset_sigma) << "axis " << i;
    }
    // The computer's settings carry it, with its 1σ, to the calibration.
    const OnboardSettings<double> s = onboard_settings_from<double>(d);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(s.mag_cal.prior_offset[i], prior[i]) << i;
    EXPECT_EQ(s.mag_cal.prior_offset_sigma, 0.5e-6);
}

TEST(GroundCalibration, WithoutTheErrorThePriorIsTheTruthsField) {
    EstimatorData d = leo_orbit_computer();
    d.mag_prior_offset_error = {0.0, 0.0, 0.0};
    const magnetometer::Vec3 truth = truth_hard_iron();
    const Vec3<double> exact = ground_calibration_offset(d);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(exact[i], truth[i], 1e-15) << i;
}

}  // namespace
}  // namespace attitude_estimator
