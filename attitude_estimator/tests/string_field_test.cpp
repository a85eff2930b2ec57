// The field of the panels' string currents the computer takes out of its magnetometer reading
// (mag_string_field): each face's loop field per ampere derived from the uplinked layout (mag_string_loop_*,
// mag_prior_sensor_position) with the named error mag_string_field_error, checked against the truth's own model
// of that field (the magnetometer block's SpacecraftField) and against the closed form at a rectangle's centre;
// then the sample: the field before the calibration is the reading less Σ K_f i_face[f].
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "attitude_estimator/estimator_data.hpp"
#include "block_simulation.hpp"
#include "magnetometer/spacecraft_field.hpp"

namespace attitude_estimator {
namespace {

// The magnetometer's default layout as the system connects it (harness/systems/leo_orbit.ssd).
EstimatorData with_default_layout() {
    EstimatorData d;
    const magnetometer::SpacecraftLayout layout = magnetometer::default_layout();
    d.mag_string_field = true;
    for (std::size_t f = 0; f < 6; ++f)
        for (std::size_t i = 0; i < 3; ++i) {
            d.mag_string_loop_center[3 * f + i] = layout.string_loop[f].center[i];
            d.mag_string_loop_side_a[3 * f + i] = layout.string_loop[f].side_a[i];
            d.mag_string_loop_side_b[3 * f + i] = layout.string_loop[f].side_b[i];
        }
    for (std::size_t i = 0; i < 3; ++i) d.mag_prior_sensor_position[i] = layout.sensor_position[i];
    return d;
}

// The truth's field per ampere of face f's string at the sensor: one ampere in that string alone.
magnetometer::Vec3 truth_per_ampere(std::size_t f) {
    magnetometer::PlantCurrents i;
    i.string[f] = 1.0;
    return magnetometer::SpacecraftField(magnetometer::default_layout()).at_sensor(i);
}

TEST(StringField, PerAmpereIsTheTruthsLoopFieldTimesTheNamedError) {
    const EstimatorData d = with_default_layout();
    ASSERT_EQ(d.mag_string_field_error, 0.05);
    const auto k = string_field_per_ampere(d);
    // The magnetometer's README: 0.61 µT/A from +x and +y, 0.27 from −x and −y, 0.25 from +z, 4 nT/A from −z.
    const double readme[6] = {0.61e-6, 0.27e-6, 0.61e-6, 0.27e-6, 0.25e-6, 0.004e-6};
    for (std::size_t f = 0; f < 6; ++f) {
        const magnetometer::Vec3 truth = truth_per_ampere(f);
        EXPECT_NEAR(std::hypot(truth[0], truth[1], truth[2]), readme[f], 0.006e-6) << "face " << f;
        for (std::size_t i = 0; i < 3; ++i)
            EXPECT_NEAR(k[f][i], 1.05 * truth[i], 1e-9 * std::abs(truth[i]) + 1e-18) << "face " << f << " axis " << i;
    }
    // The computer's settings carry the six vectors, and nothing without mag_string_field.
    const OnboardSettings<double> s = onboard_settings_from<double>(d);
    for (std::size_t f = 0; f < 6; ++f)
        for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(s.string_field_per_amp[f][i], k[f][i]);
    EstimatorData off = d;
    off.mag_string_field = false;
    for (const auto& v : string_field_per_ampere(off)) EXPECT_EQ(v, (Vec3<double>{0.0, 0.0, 0.0}));
}

TEST(StringField, AtARectanglesCentreTheFieldIsTheClosedForm) {
    // A 0.3 × 0.1 m loop in the x–y plane: at its centre B = 2 μ0 I √(a² + b²) / (π a b) along side_a × side_b.
    const StringLoop loop{.center = {0.1, -0.2, 0.3}, .side_a = {0.3, 0.0, 0.0}, .side_b = {0.0, 0.1, 0.0}};
    const double a = 0.3, b = 0.1, mu0 = 4e-7 * std::numbers::pi;
    const double expected = 2.0 * mu0 * std::sqrt(a * a + b * b) / (std::numbers::pi * a * b);
    const Vec3<double> field = string_loop_field_per_ampere(loop, loop.center);
    EXPECT_NEAR(field[2], expected, 1e-12 * expected);
    EXPECT_NEAR(field[0], 0.0, 1e-18);
    EXPECT_NEAR(field[1], 0.0, 1e-18);
    // The current the other way round (side_b reversed): the field reverses.
    const StringLoop reversed{.center = loop.center, .side_a = loop.side_a, .side_b = {0.0, -0.1, 0.0}};
    EXPECT_NEAR(string_loop_field_per_ampere(reversed, loop.center)[2], -expected, 1e-12 * expected);
    EXPECT_NEAR(string_loop_wire_distance(loop, loop.center), 0.05, 1e-15);
}

// One sample of the computer with the strings' field known and not: the same reading, the field before the
// calibration differs by Σ K_f i_f (ideal converters: the currents as given).
TEST(StringField, TheSampleTakesTheMeasuredCurrentsFieldOutBeforeTheCalibration) {
    EstimatorData d = with_default_layout();
    d.adc_bits = 0;
    d.i_face = {0.8, 0.0, 0.55, 0.0, 0.3, 0.02};
    d.v_mag = {2.6, 2.3, 2.8};
    EstimatorData off = d;
    off.mag_string_field = false;
    const auto run = [](const EstimatorData& data) {
        const OnboardSettings<double> s = onboard_settings_from<double>(data);
        OnboardState<double> state;
        onboard_start(state, s);
        return onboard_sample(state, onboard_inputs_from<double>(data), s, 0.0);
    };
    const OnboardOutputs<double> with = run(d);
    const OnboardOutputs<double> without = run(off);
    ASSERT_TRUE(with.sample.mag_valid);
    for (std::size_t i = 0; i < 3; ++i) {
        double expected = 0.0;
        for (std::size_t f = 0; f < 6; ++f) expected += 1.05 * truth_per_ampere(f)[i] * d.i_face[f];
        EXPECT_NEAR(without.sample.mag_field_uncalibrated[i] - with.sample.mag_field_uncalibrated[i], expected, 1e-14)
            << "axis " << i;
        EXPECT_NEAR(without.sample.mag_field[i] - with.sample.mag_field[i], expected, 1e-14) << "axis " << i;
    }
    // Of the order the magnetometer's README gives: 0.61 µT/A × 0.8 A along the +x string's field.
    EXPECT_GT(std::abs(without.sample.mag_field_uncalibrated[0] - with.sample.mag_field_uncalibrated[0]), 0.1e-6);
}

TEST(StringField, AWireAtTheSensorIsRefusedNamingTheFaceAndTheLimit) {
    test::Simulation sim;
    sim.data() = with_default_layout();
    // The +z string's loop moved onto the sensor (10, 10, 110) mm: a wire 0.5 mm from it.
    sim.data().mag_string_loop_center[12] = 0.01;
    sim.data().mag_string_loop_center[13] = 0.0125 + 0.0005;
    sim.data().mag_string_loop_center[14] = 0.11;
    try {
        sim.start(0.0);
        FAIL() << "a wire 0.5 mm from the sensor was accepted";
    } catch (const fmu::Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("face +z"), std::string::npos) << what;
        EXPECT_NE(what.find("min_string_wire_distance"), std::string::npos) << what;
    }
    test::Simulation fine;
    fine.data() = with_default_layout();
    EXPECT_NO_THROW(fine.start(0.0));
}

}  // namespace
}  // namespace attitude_estimator
