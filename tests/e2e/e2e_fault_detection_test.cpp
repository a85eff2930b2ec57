// Issue 28 end to end: the on-board computer's fault detection (est.detect_faults) in the bundled
// leo_orbit, read at test time. A healthy system declares nothing over three orbits (two noise seeds);
// a face's open string and a magnetometer axis stuck at its last value (the plant's and the
// magnetometer's own fault_* parameters, injected 6000 s in, second orbit, sunlit) are declared on that
// face or axis alone within 60 s, and the filter rides through on what is left.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "fault_runs.hpp"

namespace {

constexpr double kOrbit = 5764.0;  // s, leo_orbit's period
constexpr double kOnset = 6000.0;  // s: second orbit, sunlit (eclipse 7577–9703 s), calibration applied

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

TEST_P(E2eLeoFaultDetectionHealthy, ThreeOrbitsDeclareNothing) {
    const auto r = run({"mag.noise_seed=" + std::to_string(GetParam())}, 3.0 * kOrbit);
    ASSERT_NEAR(r.time.back(), 3.0 * kOrbit, 1e-6);
    const Declared d = declared(r);
    for (int k = 0; k < 6; ++k) {
        EXPECT_EQ(d.faces[k], 0) << "face " << k + 1 << " at " << d.face_time[k] << " s";
        EXPECT_EQ(d.face_time[k], -1.0);
    }
    for (int k = 0; k < 3; ++k) EXPECT_EQ(d.axes[k], 0) << "axis " << k + 1 << " at " << d.axis_time[k] << " s";
    EXPECT_EQ(d.norm, 0);
}

// One noise seed in the test suite (three orbits cost about 85 s under the sanitizers); the fault-free orbits
// counted for the no-false-alarm figure are the fault campaign's controls (docs/faults.md).
INSTANTIATE_TEST_SUITE_P(OneNoiseSeed, E2eLeoFaultDetectionHealthy, ::testing::Values(7));

TEST(E2eLeoFaultDetection, AnOpenStringIsDeclaredOnItsFaceAloneAndTheFilterRidesThrough) {
    const auto r =
        run({"plant.fault_string_open_face=1", "plant.fault_string_open_onset=" + std::to_string(kOnset)}, 6600.0);
    const Declared d = declared(r);
    EXPECT_EQ(d.faces[0], 1);  // kFaultFaceDeficit: reads below the prediction
    EXPECT_GE(d.face_time[0], kOnset);
    EXPECT_LE(d.face_time[0], kOnset + 60.0);
    for (int k = 1; k < 6; ++k) EXPECT_EQ(d.faces[k], 0) << "face " << k + 1;
    for (int k = 0; k < 3; ++k) EXPECT_EQ(d.axes[k], 0) << "axis " << k + 1;
    // Sunlit, after the exclusion: the bundled filter's sunlit p95 is 0.35° (README); 1° allows for the
    // sun lost while +x may be lit.
    const double e = p95(sunlit_errors(r, kOnset + 100.0));
    std::printf("open string on +x: declared %.0f s after the onset; filter sunlit p95 after it %.3f deg\n",
                d.face_time[0] - kOnset, e);
    EXPECT_LT(e, 1.0);
}

TEST(E2eLeoFaultDetection, AnAxisStuckAtItsLastValueIsDeclaredAloneAndTheFilterGoesOnWithTwo) {
    const auto r =
        run({"mag.fault_stuck_axis=2", "mag.fault_stuck_mode=last", "mag.fault_stuck_onset=" + std::to_string(kOnset)},
            6600.0);
    const Declared d = declared(r);
    EXPECT_EQ(d.axes[1], 2);  // kFaultAxisNoFlip
    EXPECT_GE(d.axis_time[1], kOnset);
    EXPECT_LE(d.axis_time[1], kOnset + 60.0);
    EXPECT_EQ(d.axes[0], 0);
    EXPECT_EQ(d.axes[2], 0);
    for (int k = 0; k < 6; ++k) EXPECT_EQ(d.faces[k], 0) << "face " << k + 1;
    const double e = p95(sunlit_errors(r, kOnset + 100.0));
    std::printf("y axis stuck: declared %.0f s after the onset; filter sunlit p95 after it %.3f deg\n",
                d.axis_time[1] - kOnset, e);
    EXPECT_LT(e, 1.0);
}

TEST(E2eLeoFaultDetection, AFailedStrapIsDeclaredAndTheFieldIsKept) {
    const auto r = run({"mag.fault_strap_failed=true", "mag.fault_strap_onset=" + std::to_string(kOnset)}, 6600.0);
    const Declared d = declared(r);
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(d.axes[k], 4) << "axis " << k + 1;  // kFaultAxisStrap alone: nothing excluded
        EXPECT_GE(d.axis_time[k], kOnset);
        EXPECT_LE(d.axis_time[k], kOnset + 60.0);
    }
    for (int k = 0; k < 6; ++k) EXPECT_EQ(d.faces[k], 0) << "face " << k + 1;
    // Read in the stuck polarity, the field keeps the filter where the no-fault run is (sunlit p95 0.35 deg
    // over these orbits' campaign runs); without the field (the three axes excluded) it was 4 deg.
    const double e = p95(sunlit_errors(r, kOnset + 100.0));
    std::printf("strap failed: declared %.0f s after the onset; filter sunlit p95 after it %.3f deg\n",
                d.axis_time[0] - kOnset, e);
    EXPECT_LT(e, 0.5);
}

}  // namespace
