// Issue 8 end to end: the LEO system (tumbling, Earth albedo on, Kelly-cosine panels) with each of the
// estimator's sun methods chosen by a setting, as a user does with `cosim run --set est.sun_method=...`.
// The measured sun direction (est.sun_meas) is scored against the truth (env.sun_body) in the sunlit first
// 1800 s of the orbit (the eclipse begins near 1900 s). Thresholds come from the physics, stated beside
// each check; the numbers themselves are printed for the record (and in the closing note).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "analysis/angle_error.hpp"
#include "engine/execution.hpp"
#include "engine/system.hpp"
#include "engine/system_description.hpp"
#include "recorder.hpp"

namespace {

struct SunScore {
    int lit = 0;          // rows with direct sun
    int valid = 0;        // of those, rows with a valid sun vector
    double median = 0.0;  // degrees, over the valid rows
    double p95 = 0.0;
    double attitude_median = 0.0;    // degrees, q_est against q_true over the valid attitudes
    double rate_error_median = 0.0;  // |rate_mean − |ω|| / |ω| over the rows with a valid rate
    int rate_rows = 0;
};

double median_of(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

SunScore run_leo(const std::string& method) {
    cosim::SystemOptions options;
    options.fmu_dirs = {PVATT_FMU_DIR};
    // Mean |ω| by 004 eq. 4 from attitudes a minute apart (the seed's telemetry rate), 4 increments averaged.
    options.settings = {"est.sample_period=1", "mag.noise_sample_period=1", "est.sun_method=" + method,
                        "est.rate_interval=60", "est.rate_window=4"};
    cosim::System system(cosim::read_system_description(PVATT_SYSTEMS_DIR "/leo_orbit.ssd"), options);
    cosim::ExecutionOptions ex;
    ex.stop_time = 1800.0;
    ex.output_interval = 1.0;  // every sample: the rate's window is read at the sample that closed it
    ex.relative_tolerance = 1e-6;
    auto cols = e2e::columns();
    for (const char* c : {"est.sun_valid", "est.rate_mean", "est.rate_valid", "est.rate_window_time",
                          "env.omega_body[1]", "env.omega_body[2]", "env.omega_body[3]"})
        cols.push_back(c);
    e2e::Recorder rec(system, cols);
    cosim::Execution(system, ex).run({&rec});

    std::vector<double> spin(rec.time.size());  // |ω| (rad/s), the truth
    for (std::size_t k = 0; k < rec.time.size(); ++k)
        spin[k] = std::hypot(rec["env.omega_body[1]"][k], rec["env.omega_body[2]"][k], rec["env.omega_body[3]"][k]);
    SunScore score;
    std::vector<double> errors, attitude_errors, rate_errors;
    std::size_t closed = 0;  // the row of the sample whose attitude closed the rate's last increment
    for (std::size_t k = 1; k < rec.time.size(); ++k) {
        if (rec["est.rate_mean"][k] != rec["est.rate_mean"][k - 1] ||
            rec["est.rate_window_time"][k] != rec["est.rate_window_time"][k - 1])
            closed = k;
        if (std::lround(rec.time[k]) % 10 != 0) continue;  // scored every 10 s: 180 rows
        if (rec["env.irradiance"][k] <= 0.0) continue;
        ++score.lit;
        if (rec["est.sun_valid"][k] < 0.5) continue;
        ++score.valid;
        const double real[3] = {rec["env.sun_body[1]"][k], rec["env.sun_body[2]"][k], rec["env.sun_body[3]"][k]};
        const double meas[3] = {rec["est.sun_meas[1]"][k], rec["est.sun_meas[2]"][k], rec["est.sun_meas[3]"][k]};
        errors.push_back(e2e::angle_deg(real, meas));
        if (rec["est.valid"][k] > 0.5) {
            const double qt[4] = {rec["env.q_true[1]"][k], rec["env.q_true[2]"][k], rec["env.q_true[3]"][k],
                                  rec["env.q_true[4]"][k]};
            const double qe[4] = {rec["est.q_est[1]"][k], rec["est.q_est[2]"][k], rec["est.q_est[3]"][k],
                                  rec["est.q_est[4]"][k]};
            attitude_errors.push_back(analysis::attitude_error_degrees(qt, qe));
        }
        if (rec["est.rate_valid"][k] > 0.5) {
            // Eq. 4 gives the mean rate over the attitudes it spans (est.rate_window_time up to the sample that
            // closed its last increment, up to a minute before this row), and the 3U's torques turn |ω| by about
            // 9 % a minute: the reference is the true |ω| averaged over that span (trapezoids on the 1 s rows).
            const double end = rec.time[closed];
            const double begin = end - rec["est.rate_window_time"][k];
            double area = 0.0;
            for (std::size_t j = 1; j <= closed; ++j) {
                if (rec.time[j - 1] < begin - 1e-9) continue;
                area += 0.5 * (spin[j - 1] + spin[j]) * (rec.time[j] - rec.time[j - 1]);
            }
            const double w = area / (end - begin);
            rate_errors.push_back(std::abs(rec["est.rate_mean"][k] - w) / w);
        }
    }
    score.attitude_median = median_of(attitude_errors);
    score.rate_error_median = median_of(rate_errors);
    score.rate_rows = static_cast<int>(rate_errors.size());
    std::sort(errors.begin(), errors.end());
    if (!errors.empty()) {
        score.median = errors[errors.size() / 2];
        score.p95 = errors[std::min(errors.size() - 1, errors.size() * 95 / 100)];
    }
    std::printf(
        "LEO 0-1800 s, sun_method %s: %d lit rows, %d valid; sun error median %.2f deg, p95 %.2f deg; "
        "attitude median %.2f deg; eq. 4 rate (60 s x 4) rows %d, median relative error %.1f %%\n",
        method.c_str(), score.lit, score.valid, score.median, score.p95, score.attitude_median, score.rate_rows,
        100.0 * score.rate_error_median);
    return score;
}

TEST(E2eLeoSunMethods, EverySunMethodRunsAndTheResponseInversionRemovesTheKellyBias) {
    const SunScore difference = run_leo("difference");
    const SunScore inverse = run_leo("inverse_response");
    const SunScore cones = run_leo("cones");
    const SunScore three = run_leo("three_faces");
    ASSERT_GT(difference.lit, 150);  // 180 rows, all before the eclipse
    // Albedo never reaches half of full sun on a face, so eq. 5's |s| and the face methods' norms stay
    // above min_sun_norm whenever the sun is up: (nearly) every lit row is valid.
    EXPECT_GE(difference.valid, difference.lit * 95 / 100);
    EXPECT_GE(inverse.valid, inverse.lit * 90 / 100);
    EXPECT_GE(cones.valid, cones.lit * 90 / 100);
    // three_faces needs one lit face on every axis: about two thirds of the sphere with Kelly panels
    // (the dark band of each axis removes about 3 × 11.7 % plus the overlaps), and with albedo it refuses
    // axes where both faces read light (the Monte-Carlo: 33 % valid), so only a fraction of the rows.
    EXPECT_GT(three.valid, three.lit / 10);
    // eq. 5 on Kelly panels errs by degrees (4.4° median over the sphere, docs/sun_methods.md); inverting the
    // response removes that bias, so its median must be well below eq. 5's.
    EXPECT_GT(difference.median, 2.0);
    EXPECT_LT(inverse.median, 0.75 * difference.median);
    EXPECT_LT(three.median, 0.75 * difference.median);
    // The cones method's Earth-albedo model removes most of the albedo error eq. 5 and the plain inversion
    // carry (the Monte-Carlo over random scenes: median 0.13° against 5.6° and 2.3°, docs/sun_methods.md).
    EXPECT_LT(cones.median, 0.25 * difference.median);
    EXPECT_LT(cones.median, inverse.median);
    // Their tails are set by the same few high-albedo rows (the p95 of 180 rows is the 9th worst): with the
    // bundled 3U pushed by its torques, cones 13.77° against difference 13.32° (torque-free: below it).
    EXPECT_LT(cones.p95, 1.1 * difference.p95);
    // 004 eq. 4 on the estimated attitudes a minute apart: the tumble (|ω| = 0.94 °/s) turns 56° per
    // increment, the attitude errors (leo_orbit as bundled, with the ground calibration: medians 5.6°, 2.9°,
    // 1.7°, partly common to successive estimates) enter as error/56°, averaged over 4 increments: within the
    // issue's 10 % of the mean |ω| over the span the increments cover. The bundled 3U's torques turn |ω| by
    // about 9 % a minute (2.5e-5 rad/s² rms), so against |ω| at the row (the former reference) eq. 4 on the
    // true attitudes themselves errs by 13.5 % (median; measured with 1 s rows). Measured against the span's
    // mean: 2.8 % (difference), 1.5 % (inverse_response), 1.0 % (cones); without the ground calibration
    // (est.mag_prior_offset_sigma=0, attitude medians 9.5–10.5°) 5.9 %, 5.5 %, 7.7 %.
    for (const SunScore* s : {&difference, &inverse, &cones}) {
        EXPECT_GT(s->rate_rows, 120);
        EXPECT_LT(s->rate_error_median, 0.10);
    }
    RecordProperty("difference_median_deg", std::to_string(difference.median));
    RecordProperty("inverse_response_median_deg", std::to_string(inverse.median));
    RecordProperty("cones_median_deg", std::to_string(cones.median));
    RecordProperty("three_faces_median_deg", std::to_string(three.median));
}

}  // namespace

namespace {

// Seed 000 §4 through the whole chain: the estimator's FFT of its own acquired sun vectors (eq. 5 on the
// plant's sample/holds, 12-bit converters) over a 256-sample window at 20 Hz recovers the two spin rates
// within one frequency bin (2π / 12.8 s = 0.49 rad/s). The averaged power system keeps the run short; its
// i_sh is the live differential current, the sun the same.
TEST(E2eSeedSpinRates, FftRecoversBothSpinRatesWithinOneBin) {
    cosim::SystemOptions options;
    options.fmu_dirs = {PVATT_FMU_DIR};
    options.settings = {"plant.fidelity=averaged", "est.spin_window=256"};
    cosim::System system(cosim::read_system_description(PVATT_SYSTEMS_DIR "/seed_spin.ssd"), options);
    cosim::ExecutionOptions ex;
    ex.stop_time = 13.0;
    ex.output_interval = 0.05;
    ex.relative_tolerance = 1e-6;
    e2e::Recorder rec(system, {"est.spin_theta_dot", "est.spin_phi_dot", "est.spin_bin_width", "est.spin_valid",
                               "est.spin_window_time"});
    cosim::Execution(system, ex).run({&rec});
    const std::size_t last = rec.time.size() - 1;
    // Not valid before the window holds 256 samples (the one at t = 12.75 s is the 256th).
    for (std::size_t k = 0; k < rec.time.size() && rec.time[k] < 12.7; ++k)
        EXPECT_LT(rec["est.spin_valid"][k], 0.5) << "t = " << rec.time[k];
    ASSERT_GT(rec["est.spin_valid"][last], 0.5);
    const double bin = rec["est.spin_bin_width"][last];
    EXPECT_NEAR(bin, 2.0 * std::numbers::pi / 12.8, 1e-9);
    EXPECT_NEAR(rec["est.spin_theta_dot"][last], 6.28, bin);
    EXPECT_NEAR(rec["est.spin_phi_dot"][last], 1.26, bin);
    std::printf("seed spin FFT (N = 256, 12.8 s): theta_dot %.4f rad/s, phi_dot %.4f rad/s, bin %.4f rad/s\n",
                rec["est.spin_theta_dot"][last], rec["est.spin_phi_dot"][last], bin);
}

}  // namespace

namespace {

// Issue 27: the cones method on today's faces. leo_orbit's first 1500 s with the panels at their datasheet
// 25 °C (the bundled system with its `thermal` component and that component's connections taken out, so the
// plant's panel temperatures keep their start value) at 1 Hz: albedo reaches the faces through the Kelly
// response, and the cones method's albedo model must see it the same way. The bound is relative to the floor
// of any one-sample method over the same samples: the true sun with its components inside the Kelly dark band
// (|s_k| ≤ cos 85°) set to 0. Measured: median 0.077°, p95 5.85° against a floor p95 of 4.33°; with the
// cosine-weighted model of before, 0.342° and 11.3°.
TEST(E2eLeoSunMethods, ConesNearTheOneSampleFloorWithPanelsAt25C) {
    auto description = cosim::read_system_description(PVATT_SYSTEMS_DIR "/leo_orbit.ssd");
    std::erase_if(description.components, [](const auto& c) { return c.name == "thermal"; });
    std::erase_if(description.connections,
                  [](const auto& c) { return c.start_element == "thermal" || c.end_element == "thermal"; });
    cosim::SystemOptions options;
    options.fmu_dirs = {PVATT_FMU_DIR};
    options.settings = {"est.sample_period=1", "mag.noise_sample_period=1", "est.sun_method=cones"};
    cosim::System system(description, options);
    cosim::ExecutionOptions ex;
    ex.stop_time = 1500.0;
    ex.output_interval = 1.0;
    auto cols = e2e::columns();
    cols.push_back("est.sun_valid");
    e2e::Recorder rec(system, cols);
    cosim::Execution(system, ex).run({&rec});

    const double dark = std::cos(85.0 * std::numbers::pi / 180.0);
    std::vector<double> errors, floor;
    int lit = 0;
    for (std::size_t k = 1; k < rec.time.size(); ++k) {
        if (rec["env.irradiance"][k] <= 0.0) continue;
        ++lit;
        const double real[3] = {rec["env.sun_body[1]"][k], rec["env.sun_body[2]"][k], rec["env.sun_body[3]"][k]};
        double seen[3];
        for (int i = 0; i < 3; ++i) seen[i] = std::abs(real[i]) > dark ? real[i] : 0.0;
        floor.push_back(e2e::angle_deg(real, seen));
        if (rec["est.sun_valid"][k] < 0.5) continue;
        const double meas[3] = {rec["est.sun_meas[1]"][k], rec["est.sun_meas[2]"][k], rec["est.sun_meas[3]"][k]};
        errors.push_back(e2e::angle_deg(real, meas));
    }
    ASSERT_GT(lit, 1400);
    ASSERT_GE(static_cast<int>(errors.size()), lit * 95 / 100);
    std::sort(errors.begin(), errors.end());
    std::sort(floor.begin(), floor.end());
    const auto p95 = [](const std::vector<double>& v) { return v[std::min(v.size() - 1, v.size() * 95 / 100)]; };
    const double median = errors[errors.size() / 2];
    std::printf(
        "LEO 0-1500 s, panels at 25 C, cones: sun error median %.3f deg, p95 %.2f deg; one-sample floor p95 "
        "%.2f deg\n",
        median, p95(errors), p95(floor));
    EXPECT_LT(median, 0.15);
    EXPECT_LT(p95(errors), p95(floor) + 2.5);
}

}  // namespace
