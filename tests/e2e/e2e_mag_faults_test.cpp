// Issue 28 end to end, the magnetometer side: the on-board computer's further magnetometer tests and
// recoveries (fault_detection_mag.cpp, onboard_computer.cpp) in the bundled leo_orbit with
// est.detect_faults, read at test time. Runs stop shortly after the fault (under an orbit each).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "fault_runs.hpp"

namespace {

std::vector<std::string> columns() {
    std::vector<std::string> c = e2e::vec("est.fault_mag_axis", 3);
    for (const auto& n : e2e::vec("est.fault_mag_spikes", 3)) c.push_back(n);
    c.push_back("est.fault_mag_strap_cleared_time");
    for (const auto& n : e2e::vec("est.fault_mag_axis_time", 3)) c.push_back(n);
    for (const auto& n : e2e::vec("est.fault_face", 6)) c.push_back(n);
    for (const auto& n : e2e::vec("env.q_true", 4)) c.push_back(n);
    for (const auto& n : e2e::vec("est.q_filt", 4)) c.push_back(n);
    c.push_back("env.irradiance");
    return c;
}

e2e::Recorder run(const std::vector<std::string>& settings, double stop_time) {
    return e2e::run_leo_detecting(settings, stop_time, columns());
}

// The filter's attitude error (deg) at each recorded point in [from, to), sunlit or in eclipse.
std::vector<double> errors(const e2e::Recorder& r, double from, double to, bool sunlit) {
    return e2e::filter_errors(r, [&](std::size_t i) {
        return r.time[i] >= from && r.time[i] < to && (r["env.irradiance"][i] > 0.0) == sunlit;
    });
}

using e2e::last;
using e2e::p95;

// Noise seed 5, y stuck at its last value at 4335 s: the field along y is then −3 … −0 µT for 70 s, below
// the flip test's 3 µT bar (the flip test declared it at 4407 s); the frozen test sees it within 10 s. The
// stuck reading, read in alternating polarities, also strays from the prediction by more than the spike
// gate on some samples: those are skipped, but the axis is not called spiking (its flip test is failing).
TEST(E2eLeoMagFaults, AnAxisStuckInAWeakFieldIsDeclaredFrozenAtOnce) {
    const double onset = 4335.0;
    const auto r = run({"mag.noise_seed=5", "mag.fault_stuck_axis=2", "mag.fault_stuck_mode=last",
                        "mag.fault_stuck_onset=" + std::to_string(onset)},
                       onset + 10.0);
    const int word = static_cast<int>(last(r, "est.fault_mag_axis", 2));
    EXPECT_EQ(word, 2);  // kFaultAxisNoFlip alone: excluded
    const double t = last(r, "est.fault_mag_axis_time", 2);
    std::printf("y stuck at %.0f s in a weak field: word %d, first declared %.1f s after\n", onset, word, t - onset);
    EXPECT_GE(t, onset);
    EXPECT_EQ(last(r, "est.fault_mag_axis", 1), 0.0);
    EXPECT_EQ(last(r, "est.fault_mag_axis", 3), 0.0);
    for (int k = 1; k <= 6; ++k) EXPECT_EQ(last(r, "est.fault_face", k), 0.0) << "face " << k;
}

// Spikes of 1 V (100 µT) on x, 50 ms long at 0.5 Hz from 3000 s (eclipse until 3934 s): a 50 ms slot
// holds one with probability 1 − e^(−0.5 × 0.05) = 0.0247, and each sample reads one slot: over 900 s
// (18,000 samples) 444.6 spikes expected, sd 20.8. The gate skips them; the same run without it (the gate
// out of reach) lets them into the filter.
TEST(E2eLeoMagFaults, SpikesAreSkippedCountedAndTheAxisDeclaredSpiking) {
    const std::vector<std::string> spikes{
        "mag.noise_seed=5",         "mag.fault_spike_axis=1",        "mag.fault_spike_rate=0.5",
        "mag.fault_spike_size=1.0", "mag.fault_spike_duration=0.05", "mag.fault_spike_onset=3000"};
    const auto r = run(spikes, 3900.0);
    const double n = last(r, "est.fault_mag_spikes", 1);
    EXPECT_GE(n, 444.6 - 5 * 20.8);
    EXPECT_LE(n, 444.6 + 5 * 20.8);
    EXPECT_EQ(last(r, "est.fault_mag_spikes", 2), 0.0);
    EXPECT_EQ(last(r, "est.fault_mag_spikes", 3), 0.0);
    EXPECT_EQ(last(r, "est.fault_mag_axis", 1), 8.0);  // kFaultAxisSpiking alone: not excluded
    EXPECT_GE(last(r, "est.fault_mag_axis_time", 1), 3000.0);
    EXPECT_LE(last(r, "est.fault_mag_axis_time", 1), 3060.0);
    EXPECT_EQ(last(r, "est.fault_mag_axis", 2) + last(r, "est.fault_mag_axis", 3), 0.0);
    std::vector<std::string> ungated = spikes;
    ungated.push_back("est.detect_spike_gate=1000");
    const auto u = run(ungated, 3900.0);
    EXPECT_EQ(last(u, "est.fault_mag_spikes", 1), 0.0);
    const double gated_p95 = p95(errors(r, 3100.0, 3900.0, false)), ungated_p95 = p95(errors(u, 3100.0, 3900.0, false));
    std::printf("spikes: %.0f skipped; eclipse p95 %.3f deg gated, %.3f deg without the gate\n", n, gated_p95,
                ungated_p95);
    EXPECT_LT(gated_p95, ungated_p95);
}

// A field of 10 µT appears at the sensor along z at 4300 s (after the calibration applies at about 3000 s):
// the bias-jump test (the mean innovation past 1 µT for 5 s) declares it on z alone within 60 s, and the
// calibration's offset takes it (nothing excluded).
TEST(E2eLeoMagFaults, ABiasJumpIsDeclaredOnItsAxisAndTakenByTheCalibration) {
    const double onset = 4300.0;
    const auto r =
        run({"mag.noise_seed=5", "mag.fault_bias_jump[3]=10e-6", "mag.fault_bias_onset=" + std::to_string(onset)},
            onset + 100.0);
    const double t = last(r, "est.fault_mag_axis_time", 3);
    std::printf("bias jump of 10 uT on z: declared %.1f s after the onset\n", t - onset);
    EXPECT_EQ(static_cast<int>(last(r, "est.fault_mag_axis", 3)) & 16, 16);  // kFaultAxisBias
    EXPECT_GE(t, onset);
    EXPECT_LE(t, onset + 60.0);
    EXPECT_EQ(last(r, "est.fault_mag_axis", 1) + last(r, "est.fault_mag_axis", 2), 0.0);
}

// Scene 0 of harness/campaigns/faults.toml's bias_jump case (its noise seed, field and onset as drawn): a
// field of 14.3 µT, (2.19, 12.49, −6.58) µT, appears at 4199.35 s. Along z it opposes the earth's field, so
// z's set/reset half difference falls below a quarter of the prediction; but it moved (the field at the
// sensor flips with the earth's), so z is not blamed for not flipping (the old flip test declared it "no
// flip" 5 s after the onset and excluded it for good). The bias test declares the jump; at the declaration
// the filter is taken back to its copy from before the jump.
TEST(E2eLeoMagFaults, ABiasJumpAgainstTheFieldIsNotTakenForAStuckAxis) {
    const double onset = 4199.348478050828;
    const auto r =
        run({"mag.noise_seed=290275967", "mag.fault_bias_jump[1]=2.187817870136897e-06",
             "mag.fault_bias_jump[2]=1.2485146569749137e-05", "mag.fault_bias_jump[3]=-6.580351235177146e-06",
             "mag.fault_bias_onset=" + std::to_string(onset)},
            onset + 400.0);
    int bias = 0;
    for (int k = 1; k <= 3; ++k) {
        const int word = static_cast<int>(last(r, "est.fault_mag_axis", k));
        EXPECT_EQ(word & 2, 0) << "axis " << k << " declared not flipping";
        bias |= word & 16;
    }
    EXPECT_EQ(bias, 16);
    const double after = p95(errors(r, onset + 60.0, onset + 400.0, true));
    std::printf("bias jump of 14.3 uT (campaign scene 0): sunlit p95 %.3f deg from 60 s to 400 s after\n", after);
    EXPECT_LT(after, 0.41);  // 1.5 × the campaign's fault-free sunlit p95 (0.271 deg); measured 0.279 deg
}

// The strap fails at 4300 s and works again at 4400 s: the failure is declared (bit 4 on the three axes)
// and its end noticed once the readings flip with the commanded polarity for the confirmation time (5 s).
TEST(E2eLeoMagFaults, AStrapThatWorksAgainIsNoticed) {
    const auto r = run(
        {"mag.noise_seed=5", "mag.fault_strap_failed=true", "mag.fault_strap_onset=4300", "mag.fault_strap_end=4400"},
        4420.0);
    for (int k = 1; k <= 3; ++k) EXPECT_EQ(static_cast<int>(last(r, "est.fault_mag_axis", k)) & 4, 4) << k;
    const double cleared = r["est.fault_mag_strap_cleared_time"].back();
    std::printf("strap failed 4300-4400 s: seen working again at %.1f s\n", cleared);
    EXPECT_GE(cleared, 4400.0);
    EXPECT_LE(cleared, 4410.0);
}

}  // namespace
