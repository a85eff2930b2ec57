// Issue 28 end to end: the on-board computer's fault detection (est.detect_faults) in the bundled
// leo_orbit (the 3U under its disturbance torques), read at test time. A healthy system declares nothing
// through the first eclipse, the magnetometer calibration (about 3780 s) and the sunlit part after it; a
// face's open string, a magnetometer axis stuck at its last value and a failed strap (the plant's and the
// magnetometer's own fault_* parameters, injected at 1500 s, first orbit, sunlit, the filter valid from
// about 1400 s) are declared on that face or axis alone within 60 s, and the filter rides through on what
// is left: its sunlit error after the fault within 1.5 times that of the same run without the fault.
// Short spans (issue 39): each test runs to 1650 s twice (with and without the fault).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "fault_runs.hpp"

namespace {

// s: first orbit, sunlit (the first eclipse starts at 1809 s), the filter valid (from about 1400 s), before the
// magnetometer calibration applies (about 3780 s: the flip and strap tests then use their 15 µT bar). -x is
// lit by more than half sun from 1512 s to 1692 s; the field along y is 37–41 µT from 1500 s to 1600 s.
constexpr double kOnset = 1500.0;
constexpr double kStop = 1650.0;
// The healthy run: through the first eclipse (1809–3934 s), the calibration (about 3780 s) and the sunlit
// part after it to 4500 s (the fault campaign's onsets are drawn in 3950–4500 s).
constexpr double kHealthyStop = 4500.0;

std::vector<std::string> fault_columns() {
    std::vector<std::string> c = e2e::vec("est.fault_face", 6);
    for (const auto& n : e2e::vec("est.fault_face_time", 6)) c.push_back(n);
    for (const auto& n : e2e::vec("est.fault_mag_axis", 3)) c.push_back(n);
    for (const auto& n : e2e::vec("est.fault_mag_axis_time", 3)) c.push_back(n);
    for (const auto& n : e2e::vec("env.q_true", 4)) c.push_back(n);
    for (const auto& n : e2e::vec("est.q_filt", 4)) c.push_back(n);
    c.push_back("est.fault_mag_norm");
    c.push_back("env.irradiance");
    return c;
}

e2e::Recorder run(const std::vector<std::string>& settings, double stop_time) {
    return e2e::run_leo_detecting(settings, stop_time, fault_columns());
}

// The filter's attitude error (deg) at each recorded point from `from` on, sunlit only.
std::vector<double> sunlit_errors(const e2e::Recorder& r, double from) {
    return e2e::filter_errors(r, [&](std::size_t i) { return r.time[i] >= from && r["env.irradiance"][i] > 0.0; });
}

using e2e::p95;

// The sunlit p95 of the filter's error from 50 s after the onset (the declarations come within 25 s) to the
// stop, with the fault (r) and in the same run without it (the control, same noise seed).
struct RideThrough {
    double with, without;
};
RideThrough ride_through(const e2e::Recorder& r) {
    const auto control = run({}, kStop);
    return {p95(sunlit_errors(r, kOnset + 50.0)), p95(sunlit_errors(control, kOnset + 50.0))};
}

// The ride-through aim of every fault here: the sunlit p95 after the fault within 1.5 times the control's;
// `what` and the declaration's delay after the onset are printed with both figures.
void expect_rides_through(const e2e::Recorder& r, const char* what, double declared_after) {
    const RideThrough e = ride_through(r);
    std::printf(
        "%s: declared %.1f s after the onset; filter sunlit p95 after it %.3f deg, without the fault %.3f deg\n", what,
        declared_after, e.with, e.without);
    EXPECT_LT(e.with, 1.5 * e.without) << what;
}

// Every fault word of the run at its last point (words are latched: the last point holds them all).
struct Declared {
    std::vector<int> faces, axes;
    std::vector<double> face_time, axis_time;
    int norm = 0;
};
Declared declared(const e2e::Recorder& r) {
    Declared d;
    for (int k = 1; k <= 6; ++k) {
        const std::string s = "[" + std::to_string(k) + "]";
        d.faces.push_back(static_cast<int>(r["est.fault_face" + s].back()));
        d.face_time.push_back(r["est.fault_face_time" + s].back());
    }
    for (int k = 1; k <= 3; ++k) {
        const std::string s = "[" + std::to_string(k) + "]";
        d.axes.push_back(static_cast<int>(r["est.fault_mag_axis" + s].back()));
        d.axis_time.push_back(r["est.fault_mag_axis_time" + s].back());
    }
    d.norm = static_cast<int>(r["est.fault_mag_norm"].back());
    return d;
}

class E2eLeoFaultDetectionHealthy : public ::testing::TestWithParam<int> {};

TEST_P(E2eLeoFaultDetectionHealthy, DeclaresNothingThroughTheCalibration) {
    const auto r = run({"mag.noise_seed=" + std::to_string(GetParam())}, kHealthyStop);
    ASSERT_NEAR(r.time.back(), kHealthyStop, 1e-6);
    const Declared d = declared(r);
    for (int k = 0; k < 6; ++k) {
        EXPECT_EQ(d.faces[k], 0) << "face " << k + 1 << " at " << d.face_time[k] << " s";
        EXPECT_EQ(d.face_time[k], -1.0);
    }
    for (int k = 0; k < 3; ++k) EXPECT_EQ(d.axes[k], 0) << "axis " << k + 1 << " at " << d.axis_time[k] << " s";
    EXPECT_EQ(d.norm, 0);
}

// One noise seed in the test suite (4500 s cost 15–19 s under the sanitizers); the fault-free orbits
// counted for the no-false-alarm figure are harness/campaigns/faults_healthy.toml's (17 random start
// attitudes, two orbits each) and the fault campaign's controls (docs/faults.md).
INSTANTIATE_TEST_SUITE_P(OneNoiseSeed, E2eLeoFaultDetectionHealthy, ::testing::Values(7));

TEST(E2eLeoFaultDetection, AnOpenStringIsDeclaredOnItsFaceAloneAndTheFilterRidesThrough) {
    const auto r =
        run({"plant.fault_string_open_face=2", "plant.fault_string_open_onset=" + std::to_string(kOnset)}, kStop);
    const Declared d = declared(r);
    EXPECT_EQ(d.faces[1], 1);  // kFaultFaceDeficit: reads below the prediction
    EXPECT_GE(d.face_time[1], kOnset);
    EXPECT_LE(d.face_time[1], kOnset + 60.0);
    for (int k : {0, 2, 3, 4, 5}) EXPECT_EQ(d.faces[k], 0) << "face " << k + 1;
    for (int k = 0; k < 3; ++k) EXPECT_EQ(d.axes[k], 0) << "axis " << k + 1;
    // Sunlit, after the exclusion, against the run without the fault.
    expect_rides_through(r, "open string on -x", d.face_time[1] - kOnset);
}

TEST(E2eLeoFaultDetection, AnAxisStuckAtItsLastValueIsDeclaredAloneAndTheFilterGoesOnWithTwo) {
    const auto r =
        run({"mag.fault_stuck_axis=2", "mag.fault_stuck_mode=last", "mag.fault_stuck_onset=" + std::to_string(kOnset)},
            kStop);
    const Declared d = declared(r);
    EXPECT_EQ(d.axes[1], 2);  // kFaultAxisNoFlip
    EXPECT_GE(d.axis_time[1], kOnset);
    EXPECT_LE(d.axis_time[1], kOnset + 60.0);
    EXPECT_EQ(d.axes[0], 0);
    EXPECT_EQ(d.axes[2], 0);
    for (int k = 0; k < 6; ++k) EXPECT_EQ(d.faces[k], 0) << "face " << k + 1;
    expect_rides_through(r, "y axis stuck", d.axis_time[1] - kOnset);
}

TEST(E2eLeoFaultDetection, AFailedStrapIsDeclaredAndTheFieldIsKept) {
    const auto r = run({"mag.fault_strap_failed=true", "mag.fault_strap_onset=" + std::to_string(kOnset)}, kStop);
    const Declared d = declared(r);
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(d.axes[k], 4) << "axis " << k + 1;  // kFaultAxisStrap alone: nothing excluded
        EXPECT_GE(d.axis_time[k], kOnset);
        EXPECT_LE(d.axis_time[k], kOnset + 60.0);
    }
    for (int k = 0; k < 6; ++k) EXPECT_EQ(d.faces[k], 0) << "face " << k + 1;
    // Read in the stuck polarity, the field keeps the filter where the no-fault run is (on the former
    // torque-free body: without the field, the three axes excluded, it was 4 deg against 0.35 deg).
    expect_rides_through(r, "strap failed", d.axis_time[0] - kOnset);
}

}  // namespace
