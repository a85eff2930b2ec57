// End-to-end regression of the bundled systems through the master, against thresholds derived from
// the physics (stated beside each check), never against numbers an earlier run printed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "analysis/angle_error.hpp"
#include "engine/execution.hpp"
#include "engine/system.hpp"
#include "engine/system_description.hpp"
#include "recorder.hpp"

namespace {

using cosim::System;
using e2e::angle_deg;
using e2e::columns;
using e2e::Recorder;
using e2e::Run;

}  // namespace

// The seed scenario (paper 000 §4) over its first 2 s, sampled at the estimator's 20 Hz.
TEST(E2eSeedSpin, BusHeldSunAcquiredAttitudeEstimated) {
    cosim::SystemOptions options;
    options.fmu_dirs = {PVATT_FMU_DIR};
    System system(cosim::read_system_description(PVATT_SYSTEMS_DIR "/seed_spin.ssd"), options);
    cosim::ExecutionOptions ex;
    ex.stop_time = 2.0;
    ex.output_interval = 0.05;  // = the estimator's sample period: rows fall on sample instants
    ex.relative_tolerance = 1e-6;
    auto recorded = columns();
    recorded.push_back("plant.pwm_period");
    Recorder rec(system, recorded);
    cosim::Execution(system, ex).run({&rec});
    ASSERT_GE(rec.time.size(), 40u);

    // Bus: the seed's P controller of 300 per volt with the latched_natural modulator (ssr_plant's
    // default). Issue 19's independent re-computation of that circuit: 15.04 V with a 145 mV sub-harmonic
    // (15.00–15.15 V); the seed's "null error" is D/K = 2.8 mV. Rows at 20 Hz sample the swing.
    double v_sum = 0.0;
    for (std::size_t k = 2; k < rec.time.size(); ++k) {
        EXPECT_GT(rec["plant.v_bus"][k], 14.99) << "t = " << rec.time[k];
        EXPECT_LT(rec["plant.v_bus"][k], 15.17) << "t = " << rec.time[k];
        v_sum += rec["plant.v_bus"][k];
    }
    const double v_mean = v_sum / static_cast<double>(rec.time.size() - 2);
    EXPECT_NEAR(v_mean, 15.04, 0.04);
    RecordProperty("bus_mean_V", std::to_string(v_mean));
    std::printf("seed spin 2 s: bus mean %.4f V at the estimator's samples (latched_natural, 300 /V)\n", v_mean);
    // Sun vector: eq. 5 on sample/hold currents of cosine-law panels. Errors: the S/H is at most one
    // PWM period (200 us) old at a sample, during which the sun turns by at most |w| T = 6.4 rad/s x
    // 200 us = 0.07 deg; 12-bit quantization of +-1.2 A is 0.6 mA of 0.85 A, 0.04 deg per axis.
    double worst_sun = 0.0, worst_attitude = 0.0;
    int valid = 0;
    for (std::size_t k = 1; k < rec.time.size(); ++k) {
        const double real[3] = {rec["env.sun_body[1]"][k], rec["env.sun_body[2]"][k], rec["env.sun_body[3]"][k]};
        const double meas[3] = {rec["est.sun_meas[1]"][k], rec["est.sun_meas[2]"][k], rec["est.sun_meas[3]"][k]};
        if (rec["est.valid"][k] < 0.5) continue;
        ++valid;
        worst_sun = std::max(worst_sun, angle_deg(real, meas));
        const double qt[4] = {rec["env.q_true[1]"][k], rec["env.q_true[2]"][k], rec["env.q_true[3]"][k],
                              rec["env.q_true[4]"][k]};
        const double qe[4] = {rec["est.q_est[1]"][k], rec["est.q_est[2]"][k], rec["est.q_est[3]"][k],
                              rec["est.q_est[4]"][k]};
        worst_attitude = std::max(worst_attitude, analysis::attitude_error_degrees(qt, qe));
    }
    EXPECT_GE(valid, 35);  // the sun is always up in the seed scenario
    EXPECT_LT(worst_sun, 0.5);
    // Attitude: the sun error above plus the magnetometer's (noise 4 nT and 0.3 % cross-axis
    // coupling of a ~30 uT field: 0.2 deg, the bridge offset 0 in this system) — under 1 degree.
    EXPECT_LT(worst_attitude, 1.0);
    // The switching plant ran its 5 kHz PWM (inside its own solver, Co-Simulation in the bundled
    // system): the period starting at t = 2 s is the 10000th after the first.
    EXPECT_EQ(rec["plant.pwm_period"].back(), 10000.0);
    RecordProperty("worst_sun_error_deg", std::to_string(worst_sun));
    RecordProperty("worst_attitude_error_deg", std::to_string(worst_attitude));
}

// The LEO system (seed 004's orbit, tumbling, albedo, eclipse, averaged power system) over its first
// 2400 s, which include the eclipse entry near 1900 s. Shortened sampling (1 s estimator samples,
// 1 s magnetometer noise samples) keeps the test quick; the physics is unchanged.
TEST(E2eLeoOrbit, EclipseInvalidatesTheEstimateAndDrainsTheBattery) {
    cosim::SystemOptions options;
    options.fmu_dirs = {PVATT_FMU_DIR};
    options.settings = {"est.sample_period=1", "mag.noise_sample_period=1"};
    System system(cosim::read_system_description(PVATT_SYSTEMS_DIR "/leo_orbit.ssd"), options);
    cosim::ExecutionOptions ex;
    ex.stop_time = 2400.0;
    ex.output_interval = 10.0;
    ex.relative_tolerance = 1e-6;
    auto cols = columns();
    cols.push_back("plant.i_load");
    Recorder rec(system, cols);
    cosim::Execution(system, ex).run({&rec});

    int dark = 0, lit = 0, lit_valid = 0;
    std::vector<double> errors;
    double soc_enter = -1, t_enter = 0, soc_last = 0, t_last = 0, i_load = 0;
    for (std::size_t k = 1; k < rec.time.size(); ++k) {
        const bool eclipse = rec["env.irradiance"][k] == 0.0;
        const bool valid = rec["est.valid"][k] > 0.5;
        if (eclipse) {
            ++dark;
            EXPECT_FALSE(valid) << "estimate claimed valid in eclipse at t = " << rec.time[k];
            EXPECT_LT(rec["plant.v_bus"][k], 12.5);  // the battery through its diode carries the load
            if (soc_enter < 0 && rec.time[k] > 0) {
                soc_enter = rec["plant.soc"][k];
                t_enter = rec.time[k];
            }
            soc_last = rec["plant.soc"][k];
            t_last = rec.time[k];
            i_load = rec["plant.i_load"][k];
        } else {
            ++lit;
            EXPECT_GT(rec["plant.v_bus"][k], 14.8) << "t = " << rec.time[k];
            if (valid) {
                ++lit_valid;
                const double qt[4] = {rec["env.q_true[1]"][k], rec["env.q_true[2]"][k], rec["env.q_true[3]"][k],
                                      rec["env.q_true[4]"][k]};
                const double qe[4] = {rec["est.q_est[1]"][k], rec["est.q_est[2]"][k], rec["est.q_est[3]"][k],
                                      rec["est.q_est[4]"][k]};
                errors.push_back(analysis::attitude_error_degrees(qt, qe));
            }
        }
    }
    ASSERT_GT(dark, 20);                // eclipse was reached
    EXPECT_GT(lit_valid, lit * 3 / 4);  // lit and not parallel: mostly valid
    // soc falls at the rate the load predicts (the charge switch opens in eclipse; no self-discharge).
    const double rate = (soc_last - soc_enter) / (t_last - t_enter);
    EXPECT_NEAR(rate, -i_load / 7200.0, std::abs(i_load / 7200.0) * 0.05);
    // Attitude with eq. 5 on Kelly-responding panels under albedo: the literature reports errors up
    // to 20 degrees without albedo handling (issue 8); the median must stay below that.
    std::sort(errors.begin(), errors.end());
    ASSERT_FALSE(errors.empty());
    const double median = errors[errors.size() / 2];
    EXPECT_LT(median, 20.0);
    RecordProperty("median_attitude_error_deg", std::to_string(median));
    std::printf(
        "LEO: %d dark, %d lit (%d valid) samples; median attitude error %.2f deg, 90th pct %.2f deg; soc rate %.3e /s "
        "vs %.3e\n",
        dark, lit, lit_valid, median, errors[errors.size() * 9 / 10], rate, -i_load / 7200.0);
}
