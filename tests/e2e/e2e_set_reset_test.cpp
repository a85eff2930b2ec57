// The HMC2003 set/reset loop in the bundled LEO system: the on-board computer pulses the strap and takes
// the sensor's offset out of the field; without pulses the offset tilts the measured field.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "engine/execution.hpp"
#include "engine/system.hpp"
#include "engine/system_description.hpp"
#include "recorder.hpp"

namespace {

// Median and 95th percentile of the angle between the board's measured field (est.mag_meas) and the
// true field at the sensor (env.mag_body plus the spacecraft's own, mag.mag_spacecraft: the sensor reads
// both, set/reset removes neither), over 60 s of leo_orbit at the estimator's 20 Hz.
std::pair<double, double> field_direction_error(std::vector<std::string> settings) {
    cosim::SystemOptions options;
    options.fmu_dirs = {PVATT_FMU_DIR};
    options.settings = std::move(settings);
    // What set/reset takes out, against the field at the sensor: without the ground calibration (issue 39), which
    // would take the spacecraft's own field out of est.mag_meas as well.
    options.settings.push_back("est.mag_prior_offset_sigma=0");
    cosim::System system(cosim::read_system_description(PVATT_SYSTEMS_DIR "/leo_orbit.ssd"), options);
    cosim::ExecutionOptions ex;
    ex.stop_time = 60.0;
    ex.output_interval = 0.25;  // on sample instants (5 samples apart)
    ex.relative_tolerance = 1e-6;
    std::vector<std::string> cols = e2e::vec("env.mag_body", 3);
    for (const auto& n : e2e::vec("est.mag_meas", 3)) cols.push_back(n);
    for (const auto& n : e2e::vec("mag.mag_spacecraft", 3)) cols.push_back(n);
    e2e::Recorder rec(system, cols);
    cosim::Execution(system, ex).run({&rec});
    std::vector<double> errors;
    for (std::size_t k = 1; k < rec.time.size(); ++k) {  // from the second row: the first pair is formed
        double truth[3];
        for (int i = 0; i < 3; ++i) {
            const std::string axis = "[" + std::to_string(i + 1) + "]";
            truth[i] = rec["env.mag_body" + axis][k] + rec["mag.mag_spacecraft" + axis][k];
        }
        const double meas[3] = {rec["est.mag_meas[1]"][k], rec["est.mag_meas[2]"][k], rec["est.mag_meas[3]"][k]};
        errors.push_back(e2e::angle_deg(truth, meas));
    }
    std::sort(errors.begin(), errors.end());
    return {errors[errors.size() / 2], errors[errors.size() * 95 / 100]};
}

}  // namespace

// By hand: the default bridge offset, 0.02 V on each axis, is a 0.035 V vector against the 0.25–0.31 V
// (25–31 µT at 1 V/gauss) of the field in the first minute, up to atan(0.035/0.25) = 7.9° of tilt when
// across the field. What remains with set/reset is the 0.3 % cross-axis coupling (up to 0.35°), the 12-bit
// converters (1.2 mV LSB: 0.25° per axis at 0.28 V) and the 4 nT noise (0.01°).
TEST(E2eLeoSetReset, PulsesTakeTheMagnetometerOffsetOutOfTheField) {
    const auto [with_median, with_p95] = field_direction_error({});
    const auto [without_median, without_p95] = field_direction_error({"est.mag_set_reset_samples=0"});
    std::printf(
        "leo_orbit 0-60 s, field-direction error: set/reset every sample median %.3f deg, p95 %.3f deg; "
        "no pulses median %.3f deg, p95 %.3f deg\n",
        with_median, with_p95, without_median, without_p95);
    EXPECT_LT(with_median, 0.4);
    EXPECT_LT(with_p95, 0.6);
    EXPECT_GT(without_median, 2.0);  // the offset's tilt, several degrees
    EXPECT_LT(without_p95, 8.0);
}
