// Issue 39: the filter valid early on the bundled orbit, and honest about it. Until the in-flight calibration
// applies (about 3000 s into leo_orbit) the field carried the spacecraft's own 7.3 µT and was weighed at
// 100 µT: the sun alone carried the attitude and the filter was first valid (3σ bound below 10°) at 1402 s (1 s rows),
// its bound below 2° only after the calibration (4359 s). With the ground calibration uplinked (est.mag_prior_*:
// the scenario's dipole at the sensor plus the named error mag_prior_offset_error, weighed at 0.5 µT per axis)
// the field is weighed from the first sample by the tumble (est.mag_prior_field_fluctuation, _correlation; a constant
// est.mag_prior_field_sigma of 25 µT at first), and the start's rate is fused with the
// spacecraft's largest tumble (est.filter_start_rate) rather than taken at the 1.4 rad/s σ of two attitudes
// 0.05 s apart. Asked over the first 10 minutes of the bundled leo_orbit: filter_valid (its own 10° bound),
// the 3σ bound below 10° at 600 s (measured 7.3° at 25 µT, 3.3° as bundled now; below 2° from 784 s), NEES/dof at most 1.5 over the rows
// the filter runs (not overconfident while it converges) and over the last 5 minutes.
// Short on purpose (600 s of the orbit).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "engine/system_description.hpp"
#include "filter_nees.hpp"
#include "recorder.hpp"

namespace {

constexpr double kStop = 600.0;      // s: the first 10 minutes
constexpr double kLastSpan = 300.0;  // s: the second half of the run

TEST(E2eLeoFilterStart, ValidWithinTenMinutesAndConsistentWhileConverging) {
    cosim::SystemOptions options;
    options.fmu_dirs = {PVATT_FMU_DIR};
    cosim::System system(cosim::read_system_description(PVATT_SYSTEMS_DIR "/leo_orbit.ssd"), options);
    cosim::ExecutionOptions ex;
    ex.stop_time = kStop;
    ex.output_interval = 1.0;
    std::vector<std::string> columns = e2e::nees_columns();
    columns.push_back("est.attitude_bound");
    columns.push_back("est.filter_valid");
    e2e::Recorder r(system, columns);
    cosim::Execution(system, ex).run({&r});

    double nees_sum = 0.0, nees_late = 0.0, first_valid = NAN, first_below = NAN;
    int rows = 0, late_rows = 0;
    for (std::size_t i = 0; i < r.time.size(); ++i) {
        const std::optional<double> recorded = e2e::recorded_nees_per_dof(r, i);
        if (!recorded) continue;  // the filter not running yet
        const double nees = *recorded;
        nees_sum += nees;
        ++rows;
        if (r.time[i] > kStop - kLastSpan) {
            nees_late += nees;
            ++late_rows;
        }
        if (std::isnan(first_valid) && r["est.filter_valid"][i] > 0.5) first_valid = r.time[i];
        if (std::isnan(first_below) && r["est.attitude_bound"][i] < 2.0 * std::numbers::pi / 180.0)
            first_below = r.time[i];
    }
    const double nees = rows ? nees_sum / rows : NAN, late = late_rows ? nees_late / late_rows : NAN;
    const double bound_end = r["est.attitude_bound"].back() * 180.0 / std::numbers::pi;
    std::printf(
        "leo_orbit first 600 s: first valid at %.0f s, bound below 2 deg from %.0f s, %.2f deg at 600 s; NEES/dof "
        "%.3f over %d rows, %.3f over the last 300 s\n",
        first_valid, first_below, bound_end, nees, rows, late);
    RecordProperty("first_valid", std::to_string(first_valid));
    RecordProperty("bound_at_600s_deg", std::to_string(bound_end));
    EXPECT_LE(first_valid, kStop);  // NaN (never valid) fails too
    // 3.3° as bundled (7.3° with the field weighed at a constant 25 µT, 4.2° at 8 µT): the tumble's σ holds it below 5°.
    EXPECT_LT(bound_end, 5.0);
    EXPECT_LE(nees, 1.5);
    EXPECT_LE(late, 1.5);
}

}  // namespace
