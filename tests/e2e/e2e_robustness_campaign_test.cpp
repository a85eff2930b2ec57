// Issue 39 end to end: the bundled robustness campaign (harness/campaigns/robustness.toml, read at test time)
// runs as CI can afford it: two of its runs, shortened to the first 1800 s, through the campaign library itself
// (the spec's draws, settings and metrics; only the stop time and the metrics' start moved). The two fastest
// tumbles of the campaign (seed 39): run 19, ISS-like 420 km at 4.74 deg/s, and run 11, sun-synchronous
// (17.6 h ascending node) at 4.67 deg/s. What holds there over 600-1800 s (measured with the campaign's
// --run replay and attitude_estimator/study/scene_stats.py; docs/results.md, "Robustness"): the filter runs
// from the first seconds (its bound still above 10 deg: filter_valid comes later), is never reset, and is
// consistent or cautious while it converges — NEES/dof 1.24 and
// 0.40, chi2(3) 99 % coverage 100 % both, with the drag on board as tuned (0.61 and 0.36 with the drag branch's noise,
// 1.33 and 0.38 without the drag). Not held here: the accuracy and the NEES/dof's lower bound of
// the second orbit (issue 39's aims; before the in-flight calibration applies, about 3000 s, the field is
// weighed at 100 uT and run 11 is underconfident). The 3-sigma bound below 2 deg within 10 minutes: for a run that
// starts in eclipse counted from the first sunlight (EclipseStart... below). Each run costs 18 s of CPU over the
// campaign's two orbits; this test is about a sixth of that per run.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "campaign_cells.hpp"

namespace {

constexpr double kStop = 1800.0;  // s
constexpr double kFrom = 600.0;   // s: the metrics judge from 10 minutes on

// runs: the campaign drawn to that many runs (0: the spec's); the draws of the first runs do not change with it.
std::map<std::string, double> run_shortened(long index, double stop = kStop, double from = kFrom, long runs = 0) {
    campaign::CampaignSpec spec = campaign::read_spec(PVATT_SYSTEMS_DIR "/../campaigns/robustness.toml");
    spec.stop_time = stop;
    if (runs > 0) spec.runs = runs;
    for (auto& m : spec.metrics)
        if (m.after > from) m.after = from;
    return e2e::run_spec(spec, index, {});
}

void expect_consistent_while_converging(long index, const char* what) {
    std::map<std::string, double> m = run_shortened(index);
    std::printf(
        "robustness run %ld (%s), %.0f-%.0f s: NEES/dof %.3f, chi2(3) 99 %% coverage %.2f %%, resets %.0f, "
        "unconverged rows %.0f, declarations %.0f\n",
        index, what, kFrom, kStop, m["nees_sunlit.per_dof"], m["nees_sunlit.chi2_99"], m["filter_resets.final"],
        m["unconverged.count"], m["declarations.declared"]);
    // The shortened span is sunlit in both runs (no eclipse before 1800 s): the eclipse metrics have no sample.
    EXPECT_LE(m["nees_sunlit.per_dof"], 1.5) << what;
    EXPECT_GE(m["nees_sunlit.chi2_99"], 95.0) << what;
    EXPECT_EQ(m["filter_resets.final"], 0.0) << what;
    EXPECT_EQ(m["declarations.declared"], 0.0) << what;  // nothing is injected: a declaration is a false alarm
    EXPECT_TRUE(std::isfinite(m["nees_sunlit.per_dof"])) << what;  // the filter runs (its covariance is given)
}

// The campaign's worst ISS-like run (run 31: 420 km, 0.90 deg/s; over its second orbit 172 deg sunlit, NEES/dof 4740,
// 9 false declarations without the drag on board) over its first 1800 s: with the drag torque in the filter's
// propagation (docs/filter.md, "Drag") it is no longer lost while converging. Measured over 600-1800 s with the
// campaign's --run replay and study/scene_stats.py: sunlit p95 10.0 deg, NEES/dof 3.55, chi2(3) 99 % coverage 61.8 %
// without it; 3.7 deg, 0.23, 100 % with it at the drag branch's noise (density sigma 1); 3.30 deg, 0.41, 100 % as tuned.
TEST(E2eRobustnessCampaign, WorstIssLikeRunHoldsWithTheDragOnBoard) {
    std::map<std::string, double> m = run_shortened(31);
    std::printf(
        "robustness run 31 (ISS-like, 0.90 deg/s), %.0f-%.0f s: sunlit p95 %.2f deg, NEES/dof %.3f, chi2(3) 99 %% "
        "coverage %.2f %%, resets %.0f, declarations %.0f\n",
        kFrom, kStop, m["error_sunlit.p95"], m["nees_sunlit.per_dof"], m["nees_sunlit.chi2_99"],
        m["filter_resets.final"], m["declarations.declared"]);
    EXPECT_LE(m["nees_sunlit.per_dof"], 1.5);
    EXPECT_GE(m["nees_sunlit.chi2_99"], 95.0);
    EXPECT_LT(m["error_sunlit.p95"], 6.0);  // deg: converging (10 deg when lost)
    EXPECT_EQ(m["filter_resets.final"], 0.0);
}

// An eclipse entry the master's integrator could not step through (found 2026-12-06 drawing the campaign to 64 runs: 4 of
// the 32 further runs failed, none of the first 32): run 39 (20 deg inclination, 545 km, 3.29 deg/s) enters its first
// eclipse at 1000 s, the bus falls from 15 V towards the battery's diode, and at the campaign's relative tolerance
// 1e-6 CVODE's error test failed repeatedly at 1007 s (flag -3): the run was lost. CvodeIntegrator now starts
// afresh at its last successful step on such a failure (integrator/src/cvode_integrator.cpp): the run goes on.
TEST(E2eRobustnessCampaign, AnEclipseEntryTheIntegratorStumbledOnRunsThrough) {
    std::map<std::string, double> m = run_shortened(39, 1100.0, kFrom, 64);  // status ok, checked in run_shortened
    EXPECT_TRUE(std::isfinite(m["nees_sunlit.per_dof"]));
}

// A run that starts in eclipse has no second vector until the sun rises: the field alone leaves the turn about it
// unknown, and the filter starts from the first single-frame attitude. Run 25 (ISS-like, 420 km, 2.84 deg/s) is in
// eclipse until 1080 s: its 3-sigma bound cannot be below 2 deg 10 minutes after the start (over the campaign's two
// orbits 58.8 deg, the filter not yet running at 600 s), and is 10 minutes after the first sunlight (over the two
// orbits at most 1.13 deg; 2026-12-06, docs/results.md, "Anywhere, from any start"). The campaign's
// bound_from_sun_10min (after_first = "env.irradiance > 0") says so; here over 600-2400 s.
TEST(E2eRobustnessCampaign, EclipseStartIsValidTenMinutesAfterTheFirstSunlight) {
    std::map<std::string, double> m = run_shortened(25, 2400.0);
    const double aim = 2.0 * M_PI / 180.0;
    std::printf(
        "robustness run 25 (ISS-like, starts in eclipse), to 2400 s: 3-sigma bound after 600 s at most %.2f deg, "
        "after the first sunlight + 600 s at most %.2f deg\n",
        m["bound_from_10min.max"] * 180.0 / M_PI, m["bound_from_sun_10min.max"] * 180.0 / M_PI);
    EXPECT_GT(m["bound_from_10min.max"], aim);
    EXPECT_LT(m["bound_from_sun_10min.max"], aim);
}

// One run of the campaign drawn with `seed` to 64 runs, stopped at `stop`, with the --set `settings`: the spec's own
// metric cells (those judged after `stop` read NaN), among them the two judged while the filter is valid, from the
// start: the error (error_while_valid: max, count) and the normalized error (nees_while_valid: per_dof, chi2_99).
std::map<std::string, double> while_valid(long seed, long index, double stop, const std::vector<std::string>& settings,
                                          long runs = 64) {
    campaign::CampaignSpec spec = campaign::read_spec(PVATT_SYSTEMS_DIR "/../campaigns/robustness.toml");
    spec.seed = static_cast<std::uint64_t>(seed);
    spec.runs = runs;
    spec.stop_time = stop;
    std::map<std::string, double> cells = e2e::run_spec(spec, index, settings);
    std::string set;
    for (const std::string& s : settings) set += ", " + s;
    std::printf(
        "seed %ld run %ld to %.0f s%s: while valid (%.0f rows) largest error %.2f deg, NEES/dof %.2f, chi2(3) 99 %% "
        "coverage %.1f %%; resets %.0f, faults declared %.0f\n",
        seed, index, stop, set.c_str(), cells["error_while_valid.count"], cells["error_while_valid.max"],
        cells["nees_while_valid.per_dof"], cells["nees_while_valid.chi2_99"], cells["filter_resets.final"],
        cells["declarations.declared"]);
    return cells;
}

// A start with the sun near the field's line (attitude_estimator/docs/filter.md, "The axis about the field"): the
// campaign drawn with seed 40 to 64 runs, run 35 (ISS-like, 2.0 deg/s) starts with the sun 7 deg from the field and
// stays within 3-7 deg of it for 200 s; the single-frame attitude is 63 deg off about the field. Without the hold the
// filter was valid from 65 s while 44-60 deg off (until the watch reset it at 480 s); with it, as bundled, it is not
// valid before the sun has told the turn about the field (first valid 473 s, 1.0 deg off). Over the first 900 s,
// while valid (1 s rows, 2026-12-06): the largest error 0.95 deg, NEES/dof 0.17, chi2(3) 99 % coverage 100 % with
// the hold (428 rows valid); 60.9 deg, 83.6, 46 % without (783 rows).
std::map<std::string, double> sun_near_the_field(const std::vector<std::string>& settings) {
    return while_valid(40, 35, 900.0, settings);
}

TEST(E2eRobustnessCampaign, ASunNearTheFieldsLineIsNotValidBeforeTheSunHasToldTheTurnAboutTheField) {
    const std::map<std::string, double> held = sun_near_the_field({});
    EXPECT_GT(held.at("error_while_valid.count"), 300.0);  // valid for the last 400 s or so
    EXPECT_LT(held.at("error_while_valid.max"), 3.0);      // deg, as the campaign's angle metrics give it
    EXPECT_LE(held.at("nees_while_valid.per_dof"), 1.5);
    EXPECT_GE(held.at("nees_while_valid.chi2_99"), 95.0);
    const std::map<std::string, double> free = sun_near_the_field({"est.filter_hold_field_axis=false"});
    EXPECT_GT(free.at("error_while_valid.max"), 30.0);
    EXPECT_GT(free.at("nees_while_valid.per_dof"), 10.0);
}

// Lost about the field from the start (attitude_estimator/docs/filter.md, "The watch on the sun"; docs/faults.md, "A
// lost start"): the campaign drawn with seed 42 to 64 runs, run 23 (ISS-like, 420 km, 2.0 deg/s over the bright
// Earth) learns a rate 1.5-2.9 deg/s wrong from its start, keeps the field and turns away from the sun. Without the
// sun's watch it was valid from 345 s while 90-165 deg off; the face tests, judging the faces against that
// prediction, declared three healthy faces, and once the field's watch reset it (419 s) the faces left gave no sun
// to restart from: lost for good. As bundled the sun's watch restarts it at about 300 s, nothing is declared, and it
// is valid from 460 s. Measured (1 s rows, 2026-12-06, the reference's error derived for the orbit and weighed for
// the filter's memory): over the whole run, while valid (11,241 rows), the largest error 3.89 deg, in the first valid
// second (460 s, its 3-sigma bound 9.99 deg; 2.04 deg with the former 2.4 uT white equivalent), NEES/dof 0.74,
// coverage 99.3 %; the second orbit met the four aims (NEES/dof 0.72 sunlit, 1.10 eclipse, coverage 100 / 96.3 %,
// p95 0.29 / 0.22 deg). Since the reference's tilt is considered (the 24 h-old set's lag turns the field 0.06 deg
// about the orbit's normal at 420 km; attitude_estimator/docs/filter.md, "The reference's tilt") the covariance
// says more than this run's error: NEES/dof 0.46 / 0.51, coverage 100 / 100 % (0.49 and 100 % over the whole run
// while valid; 0.41 / 0.48 before the calibrated field's σ went to 1.1 / 0.75 uT), p95 0.30 / 0.22 deg; cautious, never
// overconfident, is what is asked of it here. To 1200 s without the sun's watch: while valid 109 deg, NEES/dof
// 3536, coverage 0 %, four faces declared. The test takes about 4 s in the release build, 36 s in CI's test build.
TEST(E2eRobustnessCampaign, AFilterLostAboutTheFieldIsFoundByTheSunsWatchBeforeAnyFaceIsJudged) {
    const campaign::CampaignSpec spec = campaign::read_spec(PVATT_SYSTEMS_DIR "/../campaigns/robustness.toml");
    const std::map<std::string, double> watched = while_valid(42, 23, spec.stop_time.value(), {});
    EXPECT_EQ(watched.at("declarations.declared"), 0.0);
    EXPECT_EQ(watched.at("filter_resets.final"), 1.0);
    EXPECT_LT(watched.at("error_while_valid.max"), 5.0);  // deg: within the first valid bound, not the 90-165 deg lost
    EXPECT_GE(watched.at("nees_while_valid.chi2_99"), 95.0);
    std::printf("  its second orbit: NEES/dof %.2f / %.2f, coverage %.1f / %.1f %%, p95 %.2f / %.2f deg\n",
                watched.at("nees_sunlit.per_dof"), watched.at("nees_eclipse.per_dof"),
                watched.at("nees_sunlit.chi2_99"), watched.at("nees_eclipse.chi2_99"), watched.at("error_sunlit.p95"),
                watched.at("error_eclipse.p95"));
    for (const char* phase : {"nees_sunlit", "nees_eclipse"}) {
        EXPECT_GE(watched.at(std::string(phase) + ".per_dof"), 0.3) << phase;
        EXPECT_LE(watched.at(std::string(phase) + ".per_dof"), 1.5) << phase;
        EXPECT_GE(watched.at(std::string(phase) + ".chi2_99"), 95.0) << phase;
    }
    EXPECT_LT(watched.at("error_sunlit.p95"), 1.0);
    EXPECT_LT(watched.at("error_eclipse.p95"), 2.0);
    const std::map<std::string, double> field_only = while_valid(42, 23, 1200.0, {"est.filter_watch_sun=false"});
    EXPECT_GT(field_only.at("declarations.declared"), 0.0);
    EXPECT_GT(field_only.at("error_while_valid.max"), 90.0);
}

// Run 151 of the campaign drawn to 320 runs (seed 39; ISS-like, 420 km, a start with the faces lit by the Earth at up
// to 0.23 of the sun): the filter is valid from 537 s while 20 deg off and turns further away (22-44 deg) while its
// bound comes down to 2.6 deg. With the watch's gate at 16 (before 2026-12-06's last change) nothing restarts it
// before 1050 s: the face tests, judging against it, declare the healthy -x face at 862 s, the one false
// declaration of those 320 fault-free runs. With leo_orbit's gate at 8 the watch restarts it at 661 s, before any face
// is judged; the whole 320 are otherwise the same to the digit (docs/faults.md, "A false declaration from a wrong
// start"). It is still valid while up to 53 deg off for those 124 s: the gate finds it, the start does not avoid it.
TEST(E2eRobustnessCampaign, AStartOverTheBrightEarthIsRestartedBeforeAFaceIsJudged) {
    const std::map<std::string, double> bundled = while_valid(39, 151, 1200.0, {}, 320);
    EXPECT_EQ(bundled.at("declarations.declared"), 0.0);
    EXPECT_EQ(bundled.at("filter_resets.final"), 1.0);
    const std::map<std::string, double> gate16 = while_valid(39, 151, 1200.0, {"est.filter_watch_gate=16"}, 320);
    EXPECT_EQ(gate16.at("declarations.declared"), 1.0);
}

TEST(E2eRobustnessCampaign, FastestTumblesConvergeConsistentlyWithoutReset) {
    expect_consistent_while_converging(19, "ISS-like, 4.74 deg/s");
    expect_consistent_while_converging(11, "sun-synchronous, 4.67 deg/s");
}

}  // namespace
