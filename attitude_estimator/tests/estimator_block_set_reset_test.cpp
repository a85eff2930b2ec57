// The block pulses the magnetometer's set/reset strap and takes the offset out, against a sensor emulated
// here by hand: v = 2.5 + p·S·B + v_os with p the polarity the block commanded (AN-213).
#include <gtest/gtest.h>

#include "block_simulation.hpp"

namespace attitude_estimator::test {
namespace {

TEST(EstimatorFmuSetReset, CommandsAlternatingPulsesAndRemovesTheOffset) {
    Simulation sim;
    auto& d = sim.data();
    d.adc_bits = 0;  // ideal converters: the hand values hold exactly
    d.mag_set_reset_samples = 1;
    d.mag_offset_window = 1;                         // apply the first estimate
    const double field[3] = {30e-6, -20e-6, 10e-6};  // T; at 1e4 V/T: 0.3, −0.2, 0.1 V
    const double offset = 0.02;                      // V
    auto sensor = [&] {                              // the HMC2003 in the polarity the block commanded last
        const double p = d.mag_set_reset ? 1.0 : -1.0;
        for (int k = 0; k < 3; ++k) d.v_mag[k] = 2.5 + p * 1e4 * field[k] + offset;
        d.v_mag_ref = 2.5;
        sim.inputs_changed();
    };
    sensor();
    sim.start();
    EXPECT_TRUE(d.mag_set_reset);  // no pulse at the start sample (a host re-reads the sensor meanwhile)
    // Without an offset estimate yet the field is the set reading's: B + v_os/S = (32, −18, 12) µT.
    EXPECT_NEAR(d.mag_field[0], 32e-6, 1e-12);
    const bool expected_command[] = {false, true, false, true, false};  // after the samples at 0.05 … 0.25
    for (int n = 1; n <= 5; ++n) {
        sensor();
        sim.advance_to(0.05 * n + 0.01);
        EXPECT_EQ(d.mag_set_reset, expected_command[n - 1]) << "after the sample at " << 0.05 * n;
    }
    // Readings set (0.05), reset (0.10), set (0.15) gave v_os = (s + 2r + s)/4 = 0.02 V at 0.15; the
    // samples at 0.20 (reset) and 0.25 (set) give B itself.
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(d.mag_offset[k], offset, 1e-12);
        EXPECT_NEAR(d.mag_field[k], field[k], 1e-12);
    }
}

TEST(EstimatorFmuSetReset, WithoutPulsesTheCommandStaysSetAndTheOffsetInTheField) {
    Simulation sim;
    auto& d = sim.data();
    d.adc_bits = 0;
    d.v_mag = {2.5 + 0.3 + 0.02, 2.5 - 0.2 + 0.02, 2.5 + 0.1 + 0.02};
    sim.start();  // mag_set_reset_samples = 0 is the default
    sim.advance_to(0.51);
    EXPECT_TRUE(d.mag_set_reset);
    EXPECT_EQ(d.mag_offset[0], 0.0);
    EXPECT_NEAR(d.mag_field[0], 32e-6, 1e-12);  // (0.3 + 0.02) V / 1e4 V/T
}

// The model description says mag_set_reset and mag_offset leave initialization independent of every input
// and parameter (InitialUnknowns dependencies=""), which lets a host start the mag -> est -> mag loop
// without iterating: whatever the readings and the pulse period, the start sample commands set, offset 0.
TEST(EstimatorFmuSetReset, StartValuesDependOnNoInputOrParameter) {
    for (const double v : {0.3, 2.5, 4.9})
        for (const int period : {0, 1, 3}) {
            Simulation sim;
            auto& d = sim.data();
            d.mag_set_reset_samples = period;
            d.mag_offset_window = 1;
            d.v_mag = {v, 5.0 - v, v};
            d.v_mag_ref = v;
            sim.inputs_changed();
            sim.start();
            EXPECT_TRUE(d.mag_set_reset) << v << " V, period " << period;
            EXPECT_EQ(d.mag_offset, (Vec3d{0.0, 0.0, 0.0})) << v << " V, period " << period;
        }
}

}  // namespace
}  // namespace attitude_estimator::test
