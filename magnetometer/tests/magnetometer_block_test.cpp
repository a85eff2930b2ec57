// The magnetometer block driven through the runtime's C++ layer (ModelRunner, CsSolver), without
// the FMI C API: events, the filter's step response, set/reset averaging and seeded noise.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "fmu/cs_solver.hpp"
#include "fmu/errors.hpp"
#include "fmu/model_runner.hpp"
#include "fmu/testing/block_driver.hpp"
#include "magnetometer/magnetometer_block.hpp"

namespace magnetometer {
namespace {

constexpr double gauss = tesla_per_gauss;

using Simulation = fmu::testing::BlockDriver<MagnetometerBlock>;

TEST(MagnetometerBlock, ZeroFieldGivesTwoAndAHalfVoltsOnEveryAxis) {
    Simulation sim;
    sim.data().noise_rms = 0.0;
    sim.data().bridge_offset = 0.0;
    sim.start();
    sim.advance_to(0.1);
    for (double v : sim.data().v_out) EXPECT_DOUBLE_EQ(v, 2.5);
    EXPECT_DOUBLE_EQ(sim.data().v_ref, 2.5);
}

TEST(MagnetometerBlock, FilterStepResponseHasTheBandwidthTimeConstant) {
    Simulation sim;
    auto& d = sim.data();
    d.noise_rms = 0.0;
    d.bridge_offset = 0.0;
    d.cross_axis = 0.0;
    sim.start();  // zero field: the filter starts at rest
    d.mag_body = {1.0 * gauss, 0.0, 0.0};
    sim.runner.mark_changed();
    const double tau = 1.0 / (2.0 * std::numbers::pi * d.bandwidth);  // 159.15 µs at 1 kHz
    sim.advance_to(tau);
    EXPECT_NEAR(d.b_filt[0] / gauss, 1.0 - std::exp(-1.0), 1e-5);
    sim.advance_to(3.0 * tau);
    EXPECT_NEAR(d.b_filt[0] / gauss, 1.0 - std::exp(-3.0), 1e-5);
    EXPECT_NEAR(d.v_out[0], 2.5 + (1.0 - std::exp(-3.0)), 1e-5);
}

TEST(MagnetometerBlock, TimerSetResetFlipsTheFieldTermAndTheOffsetStays) {
    Simulation sim;
    auto& d = sim.data();
    d.noise_rms = 0.0;
    d.cross_axis = 0.0;
    d.bridge_offset = 0.02;
    d.set_reset_source = SetResetSource::timer;
    d.set_reset_period = 0.5;
    d.mag_body = {0.3 * gauss, -0.2 * gauss, 0.1 * gauss};
    sim.start();
    sim.advance_to(0.25);  // after the power-up set pulse
    EXPECT_TRUE(d.set_polarity);
    const auto after_set = d.v_out;
    sim.advance_to(0.75);  // after the reset pulse at 0.5 s
    EXPECT_FALSE(d.set_polarity);
    const auto after_reset = d.v_out;
    // By hand, 1 V/gauss: set 2.5 + B + 0.02 = 2.82, 2.32, 2.62 V; reset 2.5 − B + 0.02 = 2.22, 2.72, 2.42 V.
    const double set[3] = {2.82, 2.32, 2.62};
    const double reset[3] = {2.22, 2.72, 2.42};
    const double field[3] = {0.3, -0.2, 0.1};
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(after_set[i], set[i], 1e-9);
        EXPECT_NEAR(after_reset[i], reset[i], 1e-9);
        EXPECT_NEAR(0.5 * (after_set[i] - after_reset[i]), field[i], 1e-9);  // the offset is gone
        EXPECT_NEAR(0.5 * (after_set[i] + after_reset[i]), 2.52, 1e-9);      // null + offset
    }
    sim.advance_to(1.25);  // set again at 1.0 s
    EXPECT_TRUE(d.set_polarity);
}

TEST(MagnetometerBlock, CommandedSetResetFollowsTheInputWithoutTimeEvents) {
    Simulation sim;
    auto& d = sim.data();
    d.noise_rms = 0.0;
    d.cross_axis = 0.0;
    d.bridge_offset = -0.03;
    d.mag_body = {0.25 * gauss, 0.0, -0.4 * gauss};
    sim.start();  // set_reset_source = input is the default
    EXPECT_EQ(sim.runner.next_time_event(), fmu::no_time_event);
    sim.advance_to(0.1);
    EXPECT_TRUE(d.set_polarity);
    EXPECT_NEAR(d.v_out[0], 2.5 + 0.25 - 0.03, 1e-9);  // 2.72 V
    d.set_reset_command = false;                       // the computer pulses the reset strap
    sim.runner.mark_changed();
    sim.runner.event_iteration();
    EXPECT_FALSE(d.set_polarity);
    EXPECT_NEAR(d.v_out[0], 2.5 - 0.25 - 0.03, 1e-9);  // 2.22 V
    EXPECT_NEAR(d.v_out[2], 2.5 + 0.4 - 0.03, 1e-9);   // 2.87 V
    sim.advance_to(0.2);
    EXPECT_FALSE(d.set_polarity);
}

TEST(MagnetometerBlock, NoSetResetKeepsThePolarity) {
    Simulation sim;
    sim.data().set_reset_source = SetResetSource::none;
    sim.data().noise_rms = 0.0;
    sim.start();
    EXPECT_EQ(sim.runner.next_time_event(), fmu::no_time_event);
    sim.advance_to(3.0);
    EXPECT_TRUE(sim.data().set_polarity);
}

std::vector<double> noise_trace(std::int32_t seed, int samples) {
    Simulation sim;
    sim.data().noise_seed = seed;
    sim.data().set_reset_source = SetResetSource::none;
    sim.data().bridge_offset = 0.0;
    sim.start();
    std::vector<double> trace;
    for (int k = 1; k <= samples; ++k) {
        sim.advance_to(k * sim.data().noise_sample_period + 0.001);
        trace.push_back(sim.data().v_out[0] - 2.5);
    }
    return trace;
}

TEST(MagnetometerBlock, NoiseIsSeededAndHasTheDatasheetRms) {
    const auto a = noise_trace(7, 4000);
    const auto b = noise_trace(7, 4000);
    const auto c = noise_trace(8, 50);
    EXPECT_EQ(a, b);  // bit-identical with the same seed
    EXPECT_NE(std::vector<double>(a.begin(), a.begin() + 50), c);
    double sum2 = 0.0;
    for (double v : a) sum2 += v * v;
    const double rms_volts = std::sqrt(sum2 / a.size());
    // 40 µgauss at 1 V/gauss = 40 µV; 4000 samples estimate an RMS to about 1.1 % (1σ).
    EXPECT_NEAR(rms_volts, 40e-6, 40e-6 * 0.05);
}

TEST(MagnetometerBlock, HeldNoiseNeedsNoTimeEventsAndIsAFunctionOfTheInterval) {
    Simulation sim;
    auto& d = sim.data();
    d.set_reset_source = SetResetSource::none;
    d.bridge_offset = 0.0;
    d.noise_seed = 1;
    sim.start();
    EXPECT_EQ(sim.runner.next_time_event(), fmu::no_time_event);  // no event for the noise
    // Seed 1, interval 1, axis x: the Python transcription gives z = -0.7412925122837931, so
    // v − 2.5 = 1e4 V/T · 4e-9 T · z = -2.9651700491351724e-5 V. Interval 0, axis y: z = -0.07892058778528543.
    sim.advance_to(0.015);
    EXPECT_NEAR(d.v_out[0] - 2.5, -2.9651700491351724e-5, 1e-15);
    sim.advance_to(0.5);
    // Going back in time (a host that rejects a step) gives the same sample again: no hidden sequence.
    sim.runner.set_time(0.005);
    sim.runner.ensure_evaluated();
    EXPECT_NEAR(d.v_out[1] - 2.5, 1e4 * 4e-9 * -0.07892058778528543, 1e-15);
    sim.runner.set_time(0.015);
    sim.runner.ensure_evaluated();
    EXPECT_NEAR(d.v_out[0] - 2.5, -2.9651700491351724e-5, 1e-15);
}

TEST(MagnetometerBlock, TimeBeyondTheNoiseIndexLimitIsAnErrorNotAnOverflow) {
    Simulation sim;
    sim.data().set_reset_source = SetResetSource::none;
    sim.start();
    sim.runner.set_time(1e300);
    EXPECT_THROW(sim.runner.ensure_evaluated(), fmu::Error);
}

TEST(MagnetometerBlock, TableDeclaresEveryFieldOnceWithUnitsAndDescriptions) {
    const auto& table = MagnetometerBlock::static_table();
    EXPECT_EQ(table.states().size(), 3u);
    for (const auto& v : table.variables()) {
        EXPECT_FALSE(v.description.empty()) << v.name;
        if (v.type == fmu::ValueType::Real) {
            EXPECT_FALSE(v.unit.empty()) << v.name;
        }
    }
    EXPECT_EQ(table.by_name("der(b_filt[1])").dependencies->size(), 4u);  // b_filt[1] and mag_body[1..3]
    // b_filt[3], set_reset_command and the 14 currents (i_string, i_shunt, i_batt, i_load)
    EXPECT_EQ(table.by_name("v_out[3]").dependencies->size(), 16u);
    EXPECT_EQ(table.by_name("mag_spacecraft[3]").dependencies->size(), 14u);
}

// With no currents and no dipole (the defaults) the sensor reads mag_body alone, bit for bit: the filter
// starts at M · mag_body and the outputs are the HMC2003 chain's of it.
TEST(MagnetometerBlock, NoCurrentsAndNoDipoleReadTheEarthFieldAlone) {
    Simulation sim;
    auto& d = sim.data();
    d.noise_rms = 0.0;
    d.mag_body = {0.21 * gauss, -0.13 * gauss, 0.37 * gauss};
    sim.start();
    sim.advance_to(0.05);
    const Vec3 sensed = multiply(sensor_matrix(d.cross_axis, d.misalignment), d.mag_body);
    EXPECT_EQ(d.b_filt, sensed);
    EXPECT_EQ(d.mag_spacecraft, (Vec3{0.0, 0.0, 0.0}));
    const OutputStage stage{.sensitivity = d.sensitivity, .v_null = 2.5, .offset = 0.02, .v_low = 0.0, .v_high = 5.0};
    for (int i = 0; i < 3; ++i) EXPECT_EQ(d.v_out[i], output_voltage(stage, sensed[i], 0.0, 1.0));
}

// No noise, offset or cross-axis coupling (the field reads 1 V/gauss straight), the sensor on the body's z
// axis 120 mm above the centre.
void make_ideal_on_axis(MagnetometerData& d) {
    d.noise_rms = 0.0;
    d.bridge_offset = 0.0;
    d.cross_axis = 0.0;
    d.sensor_position = {0.0, 0.0, 0.12};
}

// A residual dipole on the body's z axis, 120 mm below the sensor: B_z = 2 (μ0/4π) m / r³ by hand,
// 2e-7 · 0.05 / 0.12³ = 5.787 µT, read on top of the Earth's field.
TEST(MagnetometerBlock, ResidualDipoleAddsItsAxialField) {
    Simulation sim;
    auto& d = sim.data();
    make_ideal_on_axis(d);
    d.dipole_moment = {0.0, 0.0, 0.05};
    d.dipole_position = {0.0, 0.0, 0.0};
    d.mag_body = {0.1 * gauss, 0.0, 0.2 * gauss};
    sim.start();
    sim.advance_to(0.01);
    const double b_dipole = 2e-7 * 0.05 / (0.12 * 0.12 * 0.12);
    EXPECT_NEAR(d.mag_spacecraft[2], b_dipole, 1e-15);
    EXPECT_NEAR(d.mag_spacecraft[0], 0.0, 1e-20);
    EXPECT_NEAR(d.v_out[2], 2.5 + 0.2 + 1e4 * b_dipole, 1e-9);
    EXPECT_NEAR(d.v_out[0], 2.5 + 0.1, 1e-9);
    // A sensor calibrated against it: the field is still shown, no longer read.
    d.read_spacecraft_field = false;
    sim.runner.mark_changed();
    sim.advance_to(0.02);
    EXPECT_NEAR(d.mag_spacecraft[2], b_dipole, 1e-15);
    EXPECT_NEAR(d.v_out[2], 2.5 + 0.2, 1e-9);
}

// The +z string made a 60 mm square centred on the sensor's axis 50 mm above it, every other loop removed
// (zero sides): the face's cell current gives the textbook on-axis field
// μ0 I s² / (2π (z² + s²/4) √(z² + s²/2)), along +z (the loop's normal); it follows the inputs.
TEST(MagnetometerBlock, FaceCurrentsGiveTheirStringLoopsField) {
    Simulation sim;
    auto& d = sim.data();
    make_ideal_on_axis(d);
    d.string_loop_side_a = {};
    d.string_loop_side_b = {};
    d.shunt_loop_side_a = d.battery_loop_side_a = d.load_loop_side_a = {};
    const double s = 0.06, z = 0.05;
    d.string_loop_center[12] = 0.0;
    d.string_loop_center[13] = 0.0;
    d.string_loop_center[14] = 0.12 + z;
    d.string_loop_side_a[12] = s;  // +z face: side_a along x, side_b along y, normal +z
    d.string_loop_side_b[13] = s;
    sim.start();
    EXPECT_EQ(d.mag_spacecraft, (Vec3{0.0, 0.0, 0.0}));
    d.i_string[4] = 0.5;
    d.i_string[0] = 0.3;  // another face's string and the shunt path: their loops are removed
    d.i_shunt[0] = 0.4;
    d.i_batt = 0.5;
    d.i_load = 0.2;
    sim.runner.mark_changed();
    sim.advance_to(0.01);
    const double mu0 = 4e-7 * std::numbers::pi;
    const double expected =
        mu0 * 0.5 * s * s / (2.0 * std::numbers::pi * (z * z + s * s / 4.0) * std::sqrt(z * z + s * s / 2.0));
    EXPECT_NEAR(d.mag_spacecraft[2], expected, 1e-12 * expected);
    EXPECT_NEAR(std::hypot(d.mag_spacecraft[0], d.mag_spacecraft[1]), 0.0, 1e-12 * expected);
    EXPECT_NEAR(d.v_out[2], 2.5 + 1e4 * expected, 1e-8);
}

TEST(MagnetometerBlock, SensorOnAWireIsRefusedAtInitialization) {
    Simulation sim;
    sim.data().sensor_position = {0.05, 0.0025, 0.1};  // on the +x string loop's long wire (y = +2.5 mm)
    EXPECT_THROW(sim.start(), fmu::Error);
}

}  // namespace
}  // namespace magnetometer
