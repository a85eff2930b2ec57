// Issue 28 end to end, the panel side: the plant's soft faults in the bundled leo_orbit (est.detect_faults),
// read at test time, on the 3U as bundled. Short runs in the first orbit (the filter runs from about 1400 s;
// the first eclipse starts at 1809 s; -x is lit by more than half sun from 1512 s to 1692 s): a half-shadowed
// face is given its scale and kept, a Hall channel offset shows in the umbra, a Hall channel stuck at a lit
// value is declared when the light on its face moves.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "campaign_cells.hpp"
#include "fault_runs.hpp"

namespace {

constexpr double kEclipseStart = 1809.0;  // s: leo_orbit's first eclipse (docs/faults.md)

std::vector<std::string> columns() {
    std::vector<std::string> c = e2e::vec("est.fault_face", 6);
    for (const auto& n : e2e::vec("est.fault_face_time", 6)) c.push_back(n);
    for (const auto& n : e2e::vec("est.fault_face_scale", 6)) c.push_back(n);
    for (const auto& n : e2e::vec("est.fault_mag_axis", 3)) c.push_back(n);
    for (const auto& n : e2e::vec("env.q_true", 4)) c.push_back(n);
    for (const auto& n : e2e::vec("est.q_filt", 4)) c.push_back(n);
    c.push_back("env.irradiance");
    return c;
}

e2e::Recorder run(const std::vector<std::string>& settings, double stop_time) {
    return e2e::run_leo_detecting(settings, stop_time, columns());
}

// p95 of the filter's attitude error (deg) over the sunlit points in [from, to].
double sunlit_p95(const e2e::Recorder& r, double from, double to) {
    return e2e::p95(e2e::filter_errors(
        r, [&](std::size_t i) { return r.time[i] >= from && r.time[i] <= to && r["env.irradiance"][i] > 0.0; }));
}

using e2e::last;

TEST(E2eLeoPanelFaults, AShadowIsCompensatedAndTheFilterKeepsItsError) {
    // Half of -x shadowed from 1400 s.
    const double lit_from = 1512.0, stop = 1692.0;  // -x lit by more than half sun
    const auto r =
        run({"plant.fault_shadow_face=2", "plant.fault_shadow_fraction=0.5", "plant.fault_shadow_onset=1400"}, stop);
    // -x: bit 8 (a steady fraction of its light) with the direct sun's half (albedo, not shadowed, adds a
    // little), kept in; declared once -x faces the sun (from 1512 s; measured 1560 s).
    EXPECT_EQ(last(r, "est.fault_face", 2), 8.0);
    EXPECT_NEAR(last(r, "est.fault_face_scale", 2), 0.5, 0.05);
    EXPECT_GE(last(r, "est.fault_face_time", 2), 1400.0);
    for (int k : {1, 3, 4, 5, 6}) EXPECT_EQ(last(r, "est.fault_face", k), 0.0) << "face " << k;
    for (int k = 1; k <= 3; ++k) EXPECT_EQ(last(r, "est.fault_mag_axis", k), 0.0) << "axis " << k;
    // Against the same scene without the fault, while -x is lit: the compensated face keeps the sunlit error
    // where it was (before the magnetometer calibration applies).
    const auto healthy = run({}, stop);
    for (int k = 1; k <= 6; ++k) EXPECT_EQ(last(healthy, "est.fault_face", k), 0.0) << "face " << k;
    const double with = sunlit_p95(r, lit_from, stop), without = sunlit_p95(healthy, lit_from, stop);
    std::printf("shadow on -x declared at %.1f s, scale %.3f; sunlit p95 %.2f / %.2f deg\n",
                last(r, "est.fault_face_time", 2), last(r, "est.fault_face_scale", 2), with, without);
    EXPECT_LT(with, 1.5 * without);
}

TEST(E2eLeoPanelFaults, AHallOffsetIsDeclaredInTheUmbra) {
    // +y's Hall channel 50 mA off (0.06 of full sun) from 1400 s: bit 16 (current in the umbra), after the
    // eclipse starts and within the 100 km margin (~15 s at 7.6 km/s) plus 5 s of confirmation and a few
    // seconds to spare.
    const auto r = run({"plant.fault_hall_face=3", "plant.fault_hall_mode=offset", "plant.fault_hall_offset=0.05",
                        "plant.fault_hall_onset=1400"},
                       kEclipseStart + 40.0);
    EXPECT_EQ(last(r, "est.fault_face", 3), 16.0);
    EXPECT_GE(last(r, "est.fault_face_time", 3), kEclipseStart);
    EXPECT_LE(last(r, "est.fault_face_time", 3), kEclipseStart + 40.0);
    for (int k : {1, 2, 4, 5, 6}) EXPECT_EQ(last(r, "est.fault_face", k), 0.0) << "face " << k;
    for (int k = 1; k <= 3; ++k) EXPECT_EQ(last(r, "est.fault_mag_axis", k), 0.0) << "axis " << k;
    std::printf("Hall offset on +y declared at %.1f s\n", last(r, "est.fault_face_time", 3));
}

TEST(E2eLeoPanelFaults, AHallChannelStuckAtALitValueIsDeclaredWhenItsLightMoves) {
    // -x's Hall channel sticks at 1600 s, -x lit (from 1512 s to 1692 s); the light on it then moves.
    const auto r =
        run({"plant.fault_hall_face=2", "plant.fault_hall_mode=stuck", "plant.fault_hall_onset=1600"}, 1720.0);
    EXPECT_EQ(last(r, "est.fault_face", 2), 32.0);
    EXPECT_GE(last(r, "est.fault_face_time", 2), 1600.0);
    EXPECT_LE(last(r, "est.fault_face_time", 2), 1720.0);
    for (int k : {1, 3, 4, 5, 6}) EXPECT_EQ(last(r, "est.fault_face", k), 0.0) << "face " << k;
    std::printf("Hall channel of -x stuck at 1600 s: declared at %.1f s\n", last(r, "est.fault_face_time", 2));
}

// The sun after a Hall channel is excluded: the panels form each axis' current from its two face channels
// (ssr_plant: i_sh[k] = i_face[2k] - i_face[2k+1]), so a stuck channel is in the axis' current too, and the
// difference method's sun (leo_orbit's) must be formed without it. faults.toml's run 105 (the bundled campaign, read
// at test time): +y's channel stuck at 0.64 A (about 0.75 of full sun), declared at 4339 s. While the sun is used
// after it (only while +y is predicted dark), its error against the truth to 5000 s (1 s rows, 2026-12-06): median
// 6.51 deg, p95 14.27 deg over 386 rows; with the stuck channel left in the axis' current it was 42-49 deg (the
// filter, weighing the sun as correlated noise, kept to the field, and the sun's watch, before it stopped once
// the filter had been valid for its 300 s, restarted the filter into a sun it could not use).
TEST(E2eLeoPanelFaults, AfterAStuckHallChannelIsExcludedTheSunIsFormedWithoutIt) {
    campaign::CampaignSpec spec = campaign::read_spec(PVATT_SYSTEMS_DIR "/../campaigns/faults.toml");
    spec.stop_time = 5000.0;
    campaign::Metric sun = e2e::angle_metric("sun_error", campaign::MetricKind::vector_angle, "est.sun_meas",
                                             "env.sun_body", "est.sun_valid", {"p50", "p95", "count"});
    sun.after = 4340.0;
    spec.metrics = {sun};
    const std::map<std::string, double> cells = e2e::run_spec(spec, 105, {});
    std::printf(
        "faults.toml run 105, +y's Hall channel stuck: the sun after its exclusion (%.0f rows) median %.2f deg, "
        "p95 %.2f deg\n",
        cells.at("sun_error.count"), cells.at("sun_error.p50"), cells.at("sun_error.p95"));
    EXPECT_GT(cells.at("sun_error.count"), 200.0);
    EXPECT_LT(cells.at("sun_error.p50"), 10.0);
    EXPECT_LT(cells.at("sun_error.p95"), 20.0);
}

// faults.toml's run 149: an appendage on +x (a 0.33 m plate at its top end) from 4433 s, whose shadow moves with the
// sun. Scaled 0.30 at 4763 s and, 9 s later, 0.26 again: +x would read 0.079 of its light, below the 0.2 bar, so it is
// excluded (it had been kept, reading 12 times its light when the appendage left it). Excluded, its string's field is
// counted from the lesser of its reading and the predicted light (counted as nothing, it left 0.4 µT following the
// sun on +x in the field, and the sunlit p95 went from 0.39 deg to 0.75 deg). Against the paired control (run 144,
// the same scene without the fault), issue 39's 1.5 times, over the campaign's sunlit span after the fault (4600 s
// to the eclipse at 7577 s). About 2 s a run in the release build.
TEST(E2eLeoPanelFaults, AnAppendagesShadowScaledTwiceExcludesItsFaceAndTheFieldKeepsItsString) {
    campaign::CampaignSpec spec = campaign::read_spec(PVATT_SYSTEMS_DIR "/../campaigns/faults.toml");
    spec.stop_time = 7577.0;
    campaign::Metric word;
    word.name = "plus_x";
    word.kind = campaign::MetricKind::column;
    word.a = "est.fault_face[1]";
    word.stats = {"final"};
    campaign::Metric scale = word;
    scale.name = "plus_x_scale";
    scale.a = "est.fault_face_scale[1]";
    std::vector<campaign::Metric> metrics;
    for (const auto& m : spec.metrics)
        if (m.name == "error_sunlit") metrics.push_back(m);
    ASSERT_EQ(metrics.size(), 1u);
    metrics.push_back(word);
    metrics.push_back(scale);
    spec.metrics = metrics;
    const std::map<std::string, double> fault = e2e::run_spec(spec, 149, {});
    const std::map<std::string, double> control = e2e::run_spec(spec, 144, {});
    std::printf(
        "faults.toml run 149 (appendage on +x): +x word %.0f, scale %.3f; sunlit p95 after the fault %.3f deg, "
        "control (run 144) %.3f deg\n",
        fault.at("plus_x.final"), fault.at("plus_x_scale.final"), fault.at("error_sunlit.p95"),
        control.at("error_sunlit.p95"));
    EXPECT_EQ(fault.at("plus_x.final"), 9.0);  // scaled (8), then excluded (1)
    EXPECT_EQ(control.at("plus_x.final"), 0.0);
    EXPECT_GT(fault.at("error_sunlit.count"), 1000.0);
    EXPECT_LE(fault.at("error_sunlit.p95"), 1.5 * control.at("error_sunlit.p95"));
}

}  // namespace
