// Issue 28 end to end, the magnetometer side: the on-board computer's further magnetometer tests and
// recoveries (fault_detection_mag.cpp, onboard_computer.cpp) in the bundled leo_orbit with
// est.detect_faults, read at test time, on the 3U as bundled. Runs stop shortly after the fault: the tests
// that need the in-flight calibration (frozen, spike and bias tests; it applies at about 3780 s) inject
// just after it, the strap's recovery in the first orbit.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "analysis/run_measures.hpp"
#include "fault_runs.hpp"
#include "filter_nees.hpp"

namespace {

std::vector<std::string> columns() {
    std::vector<std::string> c = e2e::vec("est.fault_mag_axis", 3);
    for (const auto& n : e2e::vec("est.fault_mag_spikes", 3)) c.push_back(n);
    c.push_back("est.fault_mag_strap_cleared_time");
    for (const auto& n : e2e::vec("est.fault_mag_axis_time", 3)) c.push_back(n);
    for (const auto& n : e2e::vec("est.fault_face", 6)) c.push_back(n);
    return c;
}

e2e::Recorder run(const std::vector<std::string>& settings, double stop_time) {
    return e2e::run_leo_detecting(settings, stop_time, columns());
}

using e2e::last;

// x stuck at its last value at 3866 s: the field along x is then −3.1 µT and crosses zero at about 3876 s
// (2.1 µT at 3885 s), below the flip test's 3 µT bar throughout; the frozen test sees it within 20 s
// (measured: 16 s, once the field is clear of zero by its bar). The stuck reading, read in alternating polarities, also
// strays from the prediction by more than the spike gate on some samples: those are skipped, but the axis
// is not called spiking (its flip test is failing).
TEST(E2eLeoMagFaults, AnAxisStuckInAWeakFieldIsDeclaredFrozenAtOnce) {
    const double onset = 3866.0;
    const auto r = run({"mag.noise_seed=5", "mag.fault_stuck_axis=1", "mag.fault_stuck_mode=last",
                        "mag.fault_stuck_onset=" + std::to_string(onset)},
                       onset + 20.0);
    const int word = static_cast<int>(last(r, "est.fault_mag_axis", 1));
    EXPECT_EQ(word, 2);  // kFaultAxisNoFlip alone: excluded
    const double t = last(r, "est.fault_mag_axis_time", 1);
    std::printf("x stuck at %.0f s in a weak field: word %d, first declared %.1f s after\n", onset, word, t - onset);
    EXPECT_GE(t, onset);
    EXPECT_EQ(last(r, "est.fault_mag_axis", 2), 0.0);
    EXPECT_EQ(last(r, "est.fault_mag_axis", 3), 0.0);
    for (int k = 1; k <= 6; ++k) EXPECT_EQ(last(r, "est.fault_face", k), 0.0) << "face " << k;
}

// Spikes of 1 V (100 µT) on x, 50 ms long at 2 Hz from 3820 s (just after the calibration applies; eclipse
// until 3934 s): a 50 ms slot holds one with probability 1 − e^(−2 × 0.05) = 0.0952, and each sample reads
// one slot: over 100 s (2,000 samples) 190.3 spikes expected, sd 13.1. The gate skips and counts them; the
// axis is declared spiking and stays in use.
TEST(E2eLeoMagFaults, SpikesAreSkippedCountedAndTheAxisDeclaredSpiking) {
    const double onset = 3820.0;
    const auto r =
        run({"mag.noise_seed=5", "mag.fault_spike_axis=1", "mag.fault_spike_rate=2", "mag.fault_spike_size=1.0",
             "mag.fault_spike_duration=0.05", "mag.fault_spike_onset=" + std::to_string(onset)},
            onset + 100.0);
    const double n = last(r, "est.fault_mag_spikes", 1);
    EXPECT_GE(n, 190.3 - 5 * 13.1);
    EXPECT_LE(n, 190.3 + 5 * 13.1);
    EXPECT_EQ(last(r, "est.fault_mag_spikes", 2), 0.0);
    EXPECT_EQ(last(r, "est.fault_mag_spikes", 3), 0.0);
    EXPECT_EQ(last(r, "est.fault_mag_axis", 1), 8.0);  // kFaultAxisSpiking alone: not excluded
    EXPECT_GE(last(r, "est.fault_mag_axis_time", 1), onset);
    EXPECT_LE(last(r, "est.fault_mag_axis_time", 1), onset + 60.0);
    EXPECT_EQ(last(r, "est.fault_mag_axis", 2) + last(r, "est.fault_mag_axis", 3), 0.0);
    std::printf("spikes: %.0f skipped, declared %.1f s after the onset\n", n,
                last(r, "est.fault_mag_axis_time", 1) - onset);
}

// A field of 10 µT appears at the sensor along z at 3850 s (after the calibration applies at about 3780 s):
// the bias-jump test (the mean innovation past 1 µT for 5 s) declares it on z alone within 60 s, and the
// calibration's offset takes it (nothing excluded).
TEST(E2eLeoMagFaults, ABiasJumpIsDeclaredOnItsAxisAndTakenByTheCalibration) {
    const double onset = 3850.0;
    const auto r =
        run({"mag.noise_seed=5", "mag.fault_bias_jump[3]=10e-6", "mag.fault_bias_onset=" + std::to_string(onset)},
            onset + 60.0);
    const double t = last(r, "est.fault_mag_axis_time", 3);
    std::printf("bias jump of 10 uT on z: declared %.1f s after the onset\n", t - onset);
    EXPECT_EQ(static_cast<int>(last(r, "est.fault_mag_axis", 3)) & 16, 16);  // kFaultAxisBias
    EXPECT_GE(t, onset);
    EXPECT_LE(t, onset + 60.0);
    EXPECT_EQ(last(r, "est.fault_mag_axis", 1) + last(r, "est.fault_mag_axis", 2), 0.0);
}

// The field of scene 0 of harness/campaigns/faults.toml's bias_jump case on the former body (its noise seed and
// field as drawn): 14.3 µT, (2.19, 12.49, −6.58) µT, here at 3850 s. Where a component opposes the earth's
// field, that axis' set/reset half difference falls below a quarter of the prediction; but it moved (the
// field at the sensor flips with the earth's), so the axis is not blamed for not flipping (the old flip test
// declared such an axis "no flip" 5 s after the onset and excluded it for good). The bias test declares the
// jump. The error after it against the control is the fault campaign's (docs/faults.md).
TEST(E2eLeoMagFaults, ABiasJumpAgainstTheFieldIsNotTakenForAStuckAxis) {
    const double onset = 3850.0;
    const auto r =
        run({"mag.noise_seed=290275967", "mag.fault_bias_jump[1]=2.187817870136897e-06",
             "mag.fault_bias_jump[2]=1.2485146569749137e-05", "mag.fault_bias_jump[3]=-6.580351235177146e-06",
             "mag.fault_bias_onset=" + std::to_string(onset)},
            onset + 60.0);
    int bias = 0;
    for (int k = 1; k <= 3; ++k) {
        const int word = static_cast<int>(last(r, "est.fault_mag_axis", k));
        EXPECT_EQ(word & 2, 0) << "axis " << k << " declared not flipping";
        bias |= word & 16;
    }
    EXPECT_EQ(bias, 16);
}

// A large bias jump after the calibration applies, paired with its control (the same run without it), as
// harness/campaigns/faults.toml measures it: the filter's error from 4600 s to the eclipse and in the eclipse
// (7650–8200 s, the bundled epoch's second eclipse), its p95 within the 1.5× the control's and its
// χ²(3) 99 % coverage at least 95 %.
struct AfterJump {
    double sunlit_p95 = 0, eclipse_p95 = 0, sunlit_covered = 0, eclipse_covered = 0;
};

AfterJump after_jump(const std::vector<std::string>& settings) {
    const e2e::Recorder r = e2e::run_leo_detecting(settings, 8200.0, e2e::nees_columns());
    AfterJump a;
    for (const bool eclipse : {false, true}) {
        std::vector<double> errors;
        double covered = 0;
        for (std::size_t i = 0; i < r.time.size(); ++i) {
            const double t = r.time[i];
            if (eclipse ? t < 7650.0 : (t < 4600.0 || t >= 7577.0)) continue;
            double angle = 0;
            const auto nees = e2e::recorded_nees_per_dof(r, i, &angle);
            errors.push_back(angle * 180.0 / M_PI);
            if (nees && 3.0 * *nees <= analysis::chi2_3dof_99) ++covered;
        }
        const double share = errors.empty() ? 0.0 : covered / static_cast<double>(errors.size());
        (eclipse ? a.eclipse_p95 : a.sunlit_p95) = e2e::p95(errors);
        (eclipse ? a.eclipse_covered : a.sunlit_covered) = share;
    }
    return a;
}

// The jump (T, sensor axes) at onset against the same run without it, noise seed `seed`.
void expect_within_aims(const std::string& seed, const std::array<const char*, 3>& jump, const char* onset,
                        bool check_sunlit) {
    const std::string noise = std::string("mag.noise_seed=") + seed;
    const AfterJump control = after_jump({noise});
    std::vector<std::string> settings = {noise, std::string("mag.fault_bias_onset=") + onset};
    for (int k = 0; k < 3; ++k)
        settings.push_back("mag.fault_bias_jump[" + std::to_string(k + 1) + "]=" + jump[static_cast<std::size_t>(k)]);
    const AfterJump fault = after_jump(settings);
    std::printf(
        "sunlit p95 %.3f deg (control %.3f), covered %.1f %%; eclipse p95 %.3f deg (control %.3f), covered %.1f %%\n",
        fault.sunlit_p95, control.sunlit_p95, 100 * fault.sunlit_covered, fault.eclipse_p95, control.eclipse_p95,
        100 * fault.eclipse_covered);
    if (check_sunlit) {
        EXPECT_LE(fault.sunlit_p95, 1.5 * control.sunlit_p95);
    }
    EXPECT_LE(fault.eclipse_p95, 1.5 * control.eclipse_p95);
    EXPECT_GE(fault.eclipse_covered, 0.95);
}

// faults.toml's run 318: 38.5 µT at 4101 s. The shift the calibration took was 3.3 µT short (the jump's
// mean over 3 s had caught up 90 % at the declaration, 6.8 s after the onset); the bias test, judging the
// innovation without the filter's estimate of that residual, declared the jump again twelve times, each
// shift dropping the calibration's new equations: no new solution until the end, 19.4° in the eclipse with
// filter_valid still 1 (coverage 9 %). Now one declaration, the re-learnt offset at 4619 s, 0.85°. Its sunlit
// p95 (1.52° against the control's 1.05°, 1.45×) is not held here: it sits too near the bound for a test that
// CI builds with another compiler (what is left of it: docs/faults.md).
TEST(E2eLeoMagFaults, ALargeBiasJumpIsTakenOnceAndTheEclipseHolds) {
    expect_within_aims("1703250470", {"3.5742199020672424e-05", "6.756707844068007e-06", "1.24748748842392e-05"},
                       "4101.292879432528", false);
}

// faults.toml's run 206: 43.8 µT, mostly along −z, at 3990 s. The six equations the calibration took between
// the onset and the declaration (6.3 s) hold the jump with the old offset; reopening the offset kept what they
// said about the scale, and the re-learnt solution had z's scale 1.9 % off: 0.4–0.9 µT of field error
// following the field, eclipse p95 1.68° and NEES/dof 11 (coverage 8 %). The reopening now starts from the
// calibration held 30–60 s before the declaration: 0.69°, coverage 100 %.
TEST(E2eLeoMagFaults, ABiasJumpsEquationsDoNotReachTheCalibrationsScale) {
    expect_within_aims("946646817", {"-9.882950940015816e-06", "-4.767207727806682e-06", "-4.241563059084082e-05"},
                       "3990.285428441091", true);
}

// The strap fails at 1500 s and works again at 1550 s (first orbit, sunlit, before the calibration): the failure is declared (bit 4 on the three axes)
// and its end noticed once the readings flip with the commanded polarity for the confirmation time (5 s).
TEST(E2eLeoMagFaults, AStrapThatWorksAgainIsNoticed) {
    const auto r = run(
        {"mag.noise_seed=5", "mag.fault_strap_failed=true", "mag.fault_strap_onset=1500", "mag.fault_strap_end=1550"},
        1570.0);
    for (int k = 1; k <= 3; ++k) EXPECT_EQ(static_cast<int>(last(r, "est.fault_mag_axis", k)) & 4, 4) << k;
    const double cleared = r["est.fault_mag_strap_cleared_time"].back();
    std::printf("strap failed 1500-1550 s: seen working again at %.1f s\n", cleared);
    EXPECT_GE(cleared, 1550.0);
    EXPECT_LE(cleared, 1560.0);
}

}  // namespace
