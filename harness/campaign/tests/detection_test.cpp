// A detection metric's arithmetic on small tables made by hand: declarations (a word turning nonzero, at
// its time column's value or else the output point), counted from the onset, against the expected element;
// and the summary's tables per case from a results table made by hand.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

#include "campaign_spec.hpp"
#include "detection.hpp"
#include "results_table.hpp"
#include "summary.hpp"

using campaign::DetectionTracker;

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// Three elements; w[1] has no time column (NaN: the output point is taken). Declarations:
// w[1] at 9.5 s (its time column), w[3] at 27.25 s (word 4), w[2] at 40 s (word 2, then 3 from 50 s),
// cleared at 60 s and declared again at 70 s (word 2).
DetectionTracker table() {
    DetectionTracker d({"w[1]", "w[2]", "w[3]"});
    const double rows[][7] = {
        // t, words 1..3, times 1..3
        {0, 0, 0, 0, -1, nan, -1},      {10, 1, 0, 0, 9.5, nan, -1},    {20, 1, 0, 0, 9.5, nan, -1},
        {30, 1, 0, 4, 9.5, nan, 27.25}, {40, 1, 2, 4, 9.5, nan, 27.25}, {50, 1, 3, 4, 9.5, nan, 27.25},
        {60, 1, 0, 4, 9.5, nan, 27.25}, {70, 1, 2, 4, 9.5, nan, 27.25},
    };
    for (const auto& r : rows) d.sample(r[0], {r[1], r[2], r[3]}, {r[4], r[5], r[6]});
    return d;
}

}  // namespace

TEST(Detection, CountsFromTheOnsetAndComparesTheElements) {
    const auto d = table();
    // Onset 20 s, w[3] expected: counted from 20 s are w[3] @ 27.25, w[2] @ 40 (word 3 by 50 s), w[2] @ 70;
    // w[1] @ 9.5 came before. Time to detect 27.25 - 20 = 7.25 s; w[2] too, so not isolated. Span 70 - 20
    // = 50 s = 2 periods of 25 s.
    auto o = d.outcome(20.0, {2}, 0.0, 25.0);
    EXPECT_EQ(o.detected, 1.0);
    EXPECT_EQ(o.time, 7.25);
    EXPECT_EQ(o.isolated, 0.0);
    EXPECT_EQ(o.declared, 3.0);
    EXPECT_EQ(o.before, 1.0);
    EXPECT_EQ(o.orbits, 2.0);
    EXPECT_EQ(o.which, "w[3]=4 w[2]=3 w[2]=2");
    // Expecting w[2] and w[3]: exactly what was declared after the onset.
    EXPECT_EQ(d.outcome(20.0, {1, 2}, 0.0, 25.0).isolated, 1.0);
    // Onset after everything but the re-declaration at 70 s: w[2] alone, 70 - 65 = 5 s.
    o = d.outcome(65.0, {1}, 0.0, 25.0);
    EXPECT_EQ(o.time, 5.0);
    EXPECT_EQ(o.isolated, 1.0);
    EXPECT_EQ(o.before, 3.0);
    EXPECT_EQ(o.orbits, 0.2);
}

// From the moment the fault became observable (the case's condition first held after the onset): the time
// to the first declaration from then, negative when declared before it; NaN without that moment or an onset.
TEST(Detection, CountsAlsoFromWhenTheFaultBecameObservable) {
    const auto d = table();
    // Onset 20 s, observable from 25 s: 5 s after the onset; the first declaration (27.25 s) 2.25 s after it.
    auto o = d.outcome(20.0, {2}, 0.0, 25.0, 25.0);
    EXPECT_EQ(o.time, 7.25);
    EXPECT_EQ(o.observable, 5.0);
    EXPECT_EQ(o.time_observable, 2.25);
    // Observable from 30 s: declared 2.75 s before it.
    EXPECT_EQ(d.outcome(20.0, {2}, 0.0, 25.0, 30.0).time_observable, -2.75);
    // Never observable, or no onset: nothing to count from.
    o = d.outcome(20.0, {2}, 0.0, 25.0);
    EXPECT_TRUE(std::isnan(o.observable));
    EXPECT_TRUE(std::isnan(o.time_observable));
    EXPECT_TRUE(std::isnan(d.outcome(std::nullopt, {}, 0.0, 25.0, 30.0).time_observable));
    // Observable but never declared: the moment, no time.
    DetectionTracker quiet({"f"});
    for (double t : {0.0, 5.0, 10.0}) quiet.sample(t, {0.0}, {});
    o = quiet.outcome(2.0, {0}, 0.0, 5.0, 5.0);
    EXPECT_EQ(o.observable, 3.0);
    EXPECT_TRUE(std::isnan(o.time_observable));
}

// No onset (a control): every declaration from `after` on counts (the false alarms), none is a detection
// time; declarations before `after` (a transient) are ignored altogether.
TEST(Detection, AControlCountsEveryDeclarationAfterItsTransient) {
    const auto o = table().outcome(std::nullopt, {}, 15.0, 25.0);
    EXPECT_EQ(o.declared, 3.0);  // 27.25, 40, 70; 9.5 is before 15 s
    EXPECT_EQ(o.before, 0.0);
    EXPECT_TRUE(std::isnan(o.time));
    EXPECT_EQ(o.detected, 1.0);
    EXPECT_EQ(o.isolated, 0.0);
    EXPECT_EQ(o.orbits, 2.2);  // (70 - 15) / 25
}

TEST(Detection, NothingDeclaredIsIsolatedOnlyWhenNothingWasExpected) {
    DetectionTracker d({"f"});
    for (double t : {0.0, 5.0, 10.0}) d.sample(t, {0.0}, {});
    auto o = d.outcome(std::nullopt, {}, 0.0, 5.0);
    EXPECT_EQ(o.detected, 0.0);
    EXPECT_EQ(o.declared, 0.0);
    EXPECT_EQ(o.isolated, 1.0);
    EXPECT_EQ(o.orbits, 2.0);
    EXPECT_EQ(o.which, "");
    o = d.outcome(2.0, {0}, 0.0, 5.0);  // a fault at 2 s that was missed
    EXPECT_EQ(o.detected, 0.0);
    EXPECT_EQ(o.isolated, 0.0);
    EXPECT_TRUE(std::isnan(o.time));
    // A run that sampled nothing has nothing to say.
    EXPECT_TRUE(std::isnan(DetectionTracker({"f"}).outcome(1.0, {}, 0.0, 5.0).declared));
}

// The summary's detection and paired tables from a table made by hand: two scenes of a control and a fault.
TEST(Detection, SummaryPerCaseFromAHandMadeTable) {
    campaign::CampaignSetup setup;
    setup.spec = campaign::parse_spec(R"(
system = "s.ssd"
runs = 4
seed = 1
paired = true
[[case]]
name = "control"
control = true
[[case]]
name = "fault"
onset = "a.onset"
expect = { "a.w" = 2 }
[[case.draw]]
kind = "uniform"
target = "a.onset"
min = 100
max = 101
[[metric]]
name = "err"
kind = "quaternion_angle"
a = "a.q"
b = "b.q"
stats = ["p95"]
[[metric]]
name = "det"
kind = "detection"
words = "a.w"
period = 5764
within = 60
)",
                                      "/t/spec.toml");
    // run, case, a.onset, err.p95, det.{detected,time,isolated,declared,before,orbits,which}, wall_time, status, message
    const std::map<long, std::string> rows = {
        {0, "0,control,,0.5,0,nan,1,0,0,1.5,,1,ok,"},
        {1, "1,fault,100,1,1,10,1,1,0,1,a.w[2]=1,1,ok,"},
        {2, "2,control,,0.25,1,nan,0,2,0,1.5,a.w[1]=4 a.w[1]=4,1,ok,"},
        {3, "3,fault,100,1,1,70,0,2,1,1,a.w[2]=2 a.w[1]=1,1,ok,"},
    };
    const auto table = campaign::split_rows(campaign::table_header(setup.spec), rows);
    const auto file = std::filesystem::temp_directory_path() / ("detection_summary_" + std::to_string(::getpid()));
    campaign::write_summary(file, setup, table, {}, {}, "");
    std::ifstream in(file);
    std::stringstream s;
    s << in.rdbuf();
    std::filesystem::remove(file);
    // Control: 2 false alarms in 1.5 + 1.5 periods = 0.6667 per period; word 4 in one run.
    EXPECT_NE(s.str().find("| control | 2 | 1 | – | – | 1 | 4: 1 | 0.6667 (2 in 3) | – |"), std::string::npos)
        << s.str();
    // Fault: times 10 and 70 s: median 40, p95 10 + 0.95 * 60 = 67, max 70; one within 60 s; run 1 isolated;
    // word 1 in both runs, word 2 in one; one declaration before the onset.
    EXPECT_NE(s.str().find("| fault | 2 | 2 | 40 / 67 / 70 | 1 | 1 | 1: 2, 2: 1 | – | 1 |"), std::string::npos)
        << s.str();
    // Pairs (1, 0) and (3, 2): p95 1 / 0.5 = 2 and 1 / 0.25 = 4: median 3, p95 2 + 0.95 * 2 = 3.9, max 4; the
    // controls' median (0.5 + 0.25) / 2 = 0.375.
    EXPECT_NE(s.str().find("| fault | 2 | 1 | 0.375 | 3 / 3.9 / 4 |"), std::string::npos) << s.str();
}

// The summary's detection table with a case that has an observable: its runs that became observable, the
// time from then (median / p95 / max) and the runs within `within` of it; "–" for the others.
TEST(Detection, SummaryFromWhenTheFaultBecameObservable) {
    campaign::CampaignSetup setup;
    setup.spec = campaign::parse_spec(R"(
system = "s.ssd"
runs = 6
seed = 1
paired = true
[[case]]
name = "control"
control = true
[[case]]
name = "fault"
onset = "a.onset"
expect = { "a.w" = 2 }
observable = { column = "a.lit[{a.face}]", above = 0.1 }
[[case.draw]]
kind = "uniform"
target = "a.onset"
min = 100
max = 101
[[metric]]
name = "det"
kind = "detection"
words = "a.w"
period = 5764
within = 60
)",
                                      "/t/spec.toml");
    // run, case, a.onset, det.{detected,time,isolated,declared,before,orbits,which,observable,time_observable},
    // wall_time, status, message. Fault runs: detected 70 s after the onset, observable 65 s after it (5 s);
    // detected 100 s after, observable 20 s after (80 s); never observable (detected 200 s after).
    const std::map<long, std::string> rows = {
        {0, "0,control,,0,nan,1,0,0,1.5,,nan,nan,1,ok,"}, {1, "1,fault,100,1,70,1,1,0,1,a.w[2]=1,65,5,1,ok,"},
        {2, "2,control,,0,nan,1,0,0,1.5,,nan,nan,1,ok,"}, {3, "3,fault,100,1,100,1,1,0,1,a.w[2]=1,20,80,1,ok,"},
        {4, "4,control,,0,nan,1,0,0,1.5,,nan,nan,1,ok,"}, {5, "5,fault,100,1,200,1,1,0,1,a.w[2]=1,nan,nan,1,ok,"},
    };
    const auto table = campaign::split_rows(campaign::table_header(setup.spec), rows);
    const auto file = std::filesystem::temp_directory_path() / ("observable_summary_" + std::to_string(::getpid()));
    campaign::write_summary(file, setup, table, {}, {}, "");
    std::ifstream in(file);
    std::stringstream s;
    s << in.rdbuf();
    std::filesystem::remove(file);
    EXPECT_NE(s.str().find("| observable | from observable median / p95 / max (s) | within 60 s of it |"),
              std::string::npos)
        << s.str();
    // Observable in 2 of 3 runs; from then 5 and 80 s: median 42.5, p95 5 + 0.95 × 75 = 76.25, max 80; one
    // within 60 s. From the onset 70, 100, 200: median 100, p95 100 + 0.9 × 100 = 190, none within 60 s.
    EXPECT_NE(s.str().find("| fault | 3 | 3 | 100 / 190 / 200 | 0 | 3 | 1: 3 | – | 0 | 2 | 42.5 / 76.25 / 80 | 1 |"),
              std::string::npos)
        << s.str();
    EXPECT_NE(s.str().find("| control | 3 | 0 | – | – | 3 | – | 0 (0 in 4.5) | – | – | – | – |"), std::string::npos)
        << s.str();
}
