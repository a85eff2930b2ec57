// The HMC2003 signal chain against values computed by hand from the datasheet numbers
// (1 V/gauss, 2.5 V null, 0–5 V rails, −600 ppm/°C).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "magnetometer/hmc2003.hpp"

namespace magnetometer {
namespace {

constexpr double gauss = tesla_per_gauss;
const OutputStage ideal{.sensitivity = 1.0 / gauss, .v_null = 2.5, .offset = 0.0, .v_low = 0.0, .v_high = 5.0};

TEST(Hmc2003, ZeroFieldGivesTheNullVoltage) {
    EXPECT_DOUBLE_EQ(output_voltage(ideal, 0.0, 0.0, 1.0), 2.5);
}

TEST(Hmc2003, PlusMinusTwoGaussSpanHalfToFourAndAHalfVolts) {
    EXPECT_NEAR(output_voltage(ideal, 2.0 * gauss, 0.0, 1.0), 4.5, 1e-12);
    EXPECT_NEAR(output_voltage(ideal, -2.0 * gauss, 0.0, 1.0), 0.5, 1e-12);
}

TEST(Hmc2003, OutputsSaturateAtTheRails) {
    EXPECT_DOUBLE_EQ(output_voltage(ideal, 3.0 * gauss, 0.0, 1.0), 5.0);
    EXPECT_DOUBLE_EQ(output_voltage(ideal, -3.0 * gauss, 0.0, 1.0), 0.0);
}

TEST(Hmc2003, SetResetFlipsTheFieldTermAndTheOffsetStays) {
    // AN-213: after a set V = 2.5 + S·B + V_os, after a reset V = 2.5 − S·B + V_os. With 0.3 gauss at
    // 1 V/gauss and a 20 mV offset: 2.5 + 0.3 + 0.02 = 2.82 V and 2.5 − 0.3 + 0.02 = 2.22 V; half the
    // difference is the field alone (0.3 V), half the sum the null plus the offset (2.52 V).
    OutputStage stage = ideal;
    stage.offset = 0.02;
    const double b = 0.3 * gauss;
    const double after_set = output_voltage(stage, b, 0.0, +1.0);
    const double after_reset = output_voltage(stage, b, 0.0, -1.0);
    EXPECT_NEAR(after_set, 2.82, 1e-12);
    EXPECT_NEAR(after_reset, 2.22, 1e-12);
    EXPECT_NEAR(0.5 * (after_set - after_reset), 0.3, 1e-12);
    EXPECT_NEAR(0.5 * (after_set + after_reset), 2.52, 1e-12);
}

TEST(Hmc2003, SensitivityFollowsItsTemperatureCoefficient) {
    // 50 K above 25 °C at −600 ppm/K: 1 − 0.03 = 0.97 of nominal.
    EXPECT_NEAR(sensitivity_at(1.0 / gauss, -600e-6, 75.0) * gauss, 0.97, 1e-12);
    EXPECT_DOUBLE_EQ(sensitivity_at(1.0 / gauss, -600e-6, 25.0), 1.0 / gauss);
}

TEST(Hmc2003, CrossAxisSensitivityCouplesTransverseFields) {
    const Mat3 m = sensor_matrix(0.01, {0, 0, 0});
    const Vec3 sensed = multiply(m, {0.0, 1.0 * gauss, 0.0});
    EXPECT_NEAR(sensed[0], 0.01 * gauss, 1e-18);
    EXPECT_NEAR(sensed[1], 1.0 * gauss, 1e-18);
    EXPECT_NEAR(sensed[2], 0.01 * gauss, 1e-18);
}

TEST(Hmc2003, MisalignmentRotatesTheSensorAxes) {
    // Sensor frame turned by +a about z: a field along body x appears at −a on the sensor's y axis
    // (first order in a), and the x reading is unchanged to first order.
    const double a = 0.01;
    const Vec3 sensed = multiply(sensor_matrix(0.0, {0, 0, a}), {1.0 * gauss, 0.0, 0.0});
    EXPECT_NEAR(sensed[0], 1.0 * gauss, 1e-18);
    EXPECT_NEAR(sensed[1], -a * gauss, 1e-18);
    EXPECT_NEAR(sensed[2], 0.0, 1e-18);
}

TEST(Hmc2003, FilterRateIsTwoPiTimesTheBandwidth) {
    const Vec3 d = filter_derivative({1.0, 0.0, -2.0}, {0.0, 0.0, 0.0}, 1000.0);
    EXPECT_NEAR(d[0], 2.0 * std::numbers::pi * 1000.0, 1e-9);
    EXPECT_DOUBLE_EQ(d[1], 0.0);
    EXPECT_NEAR(d[2], -4.0 * std::numbers::pi * 1000.0, 1e-9);
}

}  // namespace
}  // namespace magnetometer
