// Cases (named alternatives with their own settings and draws, walked by the run index): what the spec
// reader accepts, each mistake refused by name, and how runs take cases and share their scene.
#include <gtest/gtest.h>

#include "campaign_error.hpp"
#include "campaign_spec.hpp"
#include "draws.hpp"
#include "spec_texts.hpp"

using campaign::CampaignError;
using campaign::draw_run;
using campaign::parse_spec;

namespace {

const std::string head = "system = \"s.ssd\"\nruns = 12\nseed = 5\n";

const std::string detection = R"(
[[metric]]
name = "det"
kind = "detection"
words = ["est.fault_face", "est.fault_mag_axis"]
times = ["est.fault_face_time", "est.fault_mag_axis_time"]
period = 5764.0
within = 30
)";

// Two faults and a control over a grid of two values and a shared noise seed; both faults draw their
// onset from one stream.
const std::string cases = R"(
[[draw]]
kind = "integer"
target = "mag.noise_seed"
min = 1
max = 1000000

[[draw]]
kind = "grid"
target = "est.sun_method"
values = ["difference", "cones"]

[[case]]
name = "control"
control = true

[[case]]
name = "open_string"
onset = "plant.fault_string_open_onset"
expect = { "est.fault_face" = "plant.fault_string_open_face" }
[[case.draw]]
kind = "integer"
target = "plant.fault_string_open_face"
min = 1
max = 6
[[case.draw]]
kind = "uniform"
target = "plant.fault_string_open_onset"
stream = "onset"
min = 100
max = 200

[[case]]
name = "strap"
onset = "mag.fault_strap_onset"
expect = { "est.fault_mag_axis" = [1, 2, 3] }
[case.set]
"mag.fault_strap_failed" = true
[[case.draw]]
kind = "uniform"
target = "mag.fault_strap_onset"
stream = "onset"
min = 100
max = 200
)";

using campaign_test::error_of;

}  // namespace

TEST(Cases, ReadWithTheirSettingsDrawsOnsetAndExpectations) {
    const auto spec = parse_spec(head + "paired = true\n" + cases + detection, "/specs/test.toml");
    ASSERT_EQ(spec.cases.size(), 3u);
    EXPECT_TRUE(spec.cases[0].control);
    EXPECT_EQ(spec.cases[1].name, "open_string");
    EXPECT_EQ(spec.cases[1].onset, "plant.fault_string_open_onset");
    ASSERT_EQ(spec.cases[1].expect.size(), 1u);
    EXPECT_EQ(spec.cases[1].expect[0].words, "est.fault_face");
    EXPECT_EQ(spec.cases[1].expect[0].variable, "plant.fault_string_open_face");
    EXPECT_EQ(spec.cases[1].draws.at(1).stream, "onset");
    EXPECT_EQ(spec.cases[2].settings, (std::vector<std::string>{"mag.fault_strap_failed=true"}));
    EXPECT_EQ(spec.cases[2].expect.at(0).elements, (std::vector<long>{1, 2, 3}));
    const auto& m = spec.metrics.at(0);
    EXPECT_EQ(m.kind, campaign::MetricKind::detection);
    EXPECT_EQ(m.times.at(1), "est.fault_mag_axis_time");
    EXPECT_EQ(m.period, 5764.0);
    EXPECT_EQ(m.within, 30.0);
}

// Runs cycle through the cases fastest, then the grid; paired, a scene (the shared draws, and the draws of
// one stream) is the same for every case and grid value.
TEST(Cases, RunsCycleThroughTheCasesAndPairedScenesAreShared) {
    const auto spec = parse_spec(head + "paired = true\n" + cases + detection, "/specs/test.toml");
    std::string names;
    for (const auto& c : campaign::draw_columns(spec)) names += c.name + " ";
    EXPECT_EQ(names,
              "case mag.noise_seed est.sun_method plant.fault_string_open_face plant.fault_string_open_onset "
              "mag.fault_strap_onset ");
    EXPECT_EQ(campaign::grid_size(spec), 6);
    const char* expected[][2] = {{"control", "difference"}, {"open_string", "difference"}, {"strap", "difference"},
                                 {"control", "cones"},      {"open_string", "cones"},      {"strap", "cones"},
                                 {"control", "difference"}};
    for (long i = 0; i < 7; ++i) {
        const auto run = draw_run(spec, i);
        ASSERT_EQ(run.cells.size(), 6u);
        EXPECT_EQ(run.cells[0], expected[i][0]) << i;
        EXPECT_EQ(run.cells[2], expected[i][1]) << i;
    }
    // Scene 0 is runs 0..5: one noise seed; the open string's and the strap's onsets are one stream.
    const auto control = draw_run(spec, 0), open = draw_run(spec, 1), strap = draw_run(spec, 2);
    for (long i = 1; i < 6; ++i) EXPECT_EQ(draw_run(spec, i).cells[1], control.cells[1]) << i;
    EXPECT_NE(draw_run(spec, 6).cells[1], control.cells[1]);
    EXPECT_EQ(open.cells[4], strap.cells[5]);
    EXPECT_EQ(open.cells[4], draw_run(spec, 4).cells[4]);  // the other grid value, the same scene
    // A case's columns are empty in the other cases' runs; its settings come before the draws.
    EXPECT_EQ(control.cells[3], "");
    EXPECT_EQ(control.cells[5], "");
    EXPECT_EQ(strap.cells[3], "");
    EXPECT_EQ(strap.settings.front(), "mag.fault_strap_failed=true");
    EXPECT_EQ(strap.settings.back(), "mag.fault_strap_onset=" + strap.cells[5]);
    EXPECT_EQ(control.settings.size(), 2u);  // the noise seed and the sun method
    // The paired control of a run: the control case of its scene and grid value.
    EXPECT_EQ(campaign::paired_control(spec, 5), 3);
    EXPECT_EQ(campaign::paired_control(spec, 7), 6);
    EXPECT_EQ(*campaign::case_of(spec, 5), 2u);
    // Unpaired: every run its own scene.
    auto unpaired = spec;
    unpaired.paired = false;
    EXPECT_NE(draw_run(unpaired, 1).cells[1], draw_run(unpaired, 0).cells[1]);
    EXPECT_FALSE(campaign::paired_control(unpaired, 5));
}

// Without cases nothing changes: the same columns and values as before cases existed.
TEST(Cases, ASpecWithoutCasesDrawsAsBefore) {
    const auto spec =
        parse_spec(head + "[[draw]]\nkind = \"grid\"\ntarget = \"a.g\"\nvalues = [1, 2]\n", "/specs/test.toml");
    EXPECT_EQ(campaign::draw_columns(spec).at(0).name, "a.g");
    EXPECT_FALSE(campaign::case_of(spec, 3));
    EXPECT_EQ(draw_run(spec, 3).cells, (std::vector<std::string>{"2"}));
}

TEST(Cases, MistakesAreRefusedByName) {
    const std::string a = "[[case]]\nname = \"a\"\n", b = "[[case]]\nname = \"b\"\n";
    const std::pair<std::string, std::string> bad[] = {
        {"[[case]]\ncontrol = true\n", "case 1: 'name' is missing"},
        {"[[case]]\nname = \"open string\"\n", "case 1: 'name' must be non-empty without commas"},
        {a + "colour = 1\n", "case 'a': unknown key 'colour'"},
        {a + "control = 1\n", "case 'a': 'control' must be true or false"},
        {a + "set = 3\n", "case 'a': [case.set] must be a table"},
        {a + "draw = 3\n", "case 'a': its draws are written [[case.draw]]"},
        {a + "[[case.draw]]\nkind = \"uniform\"\ntarget = \"a.x\"\nmin = 1\nmax = 0\n",
         "case 'a': draw 1: 'max' must be above 'min'"},
        {a + "[[case.draw]]\nkind = \"grid\"\ntarget = \"a.x\"\nvalues = [1]\n",
         "case 'a': draw 1: a case holds no grid"},
        {a + "onset = 3\n", "case 'a': 'onset' must be a string"},
        {a + "onset = \"x\"\n", "case 'a': 'onset': 'x' is not component.variable"},
        {a + "onset = \"a.t\"\nexpect = 2\n", "case 'a': 'expect' must be a table"},
        {a + "onset = \"a.t\"\nexpect = { \"est.fault_face\" = 0 }\n", "elements are integers from 1"},
        {a + "onset = \"a.t\"\nexpect = { \"est.fault_face\" = [] }\n",
         "must be a variable's name, an element number or a non-empty array"},
        {a + "onset = \"a.t\"\nexpect = { \"est.other\" = 1 }\n",
         "case 'a': 'expect' names 'est.other', which is no detection metric's 'words'"},
        {a + "expect = { \"est.fault_face\" = 1 }\n", "case 'a': 'expect' needs 'onset'"},
        {a + "control = true\nonset = \"a.t\"\n", "case 'a': the control expects no fault"},
        {a + a, "two cases named 'a'"},
        {a + "control = true\n" + b + "control = true\n", "cases 'a' and 'b' are both the control"},
        {"[[draw]]\nkind = \"uniform\"\ntarget = \"a.x\"\nmin = 0\nmax = 1\n" + a +
             "[[case.draw]]\nkind = \"uniform\"\ntarget = \"a.x\"\nmin = 0\nmax = 1\n",
         "case 'a': 'a.x' is also drawn for every run"},
        {a + "[[case.draw]]\nkind = \"uniform\"\ntarget = \"a.x\"\nmin = 0\nmax = 1\n" +
             "[[case.draw]]\nkind = \"integer\"\ntarget = \"a.x\"\nmin = 0\nmax = 1\n",
         "case 'a': 'a.x' is drawn twice"},
        {a + "[case.set]\n\"a.x\" = 1\n[[case.draw]]\nkind = \"uniform\"\ntarget = \"a.x\"\nmin = 0\nmax = 1\n",
         "case 'a': 'a.x' is both set by the case and drawn"},
        {"case = 1\n", "cases are written [[case]]"},
        {"[[draw]]\nkind = \"grid\"\ntarget = \"a.g\"\nvalues = [1]\nstream = \"s\"\n", "a grid draw is not random"},
        {"[[draw]]\nkind = \"uniform\"\ntarget = \"a.g\"\nmin = 0\nmax = 1\nstream = \"\"\n",
         "'stream' must not be empty"},
    };
    for (const auto& [text, message] : bad)
        EXPECT_NE(error_of(head + text + detection).find(message), std::string::npos)
            << text << "\n gave: " << error_of(head + text + detection);
}

TEST(Cases, DetectionMetricMistakesAreRefusedByName) {
    const std::string m = "[[metric]]\nname = \"d\"\nkind = \"detection\"\n";
    const std::pair<std::string, std::string> bad[] = {
        {m + "period = 1\n", "metric 1: 'words' is missing"},
        {m + "words = []\nperiod = 1\n", "'words' must be a string or a non-empty array"},
        {m + "words = [\"a.w\", \"a.w\"]\nperiod = 1\n", "'a.w' listed twice"},
        {m + "words = [\"a.w\", \"a.v\"]\ntimes = \"a.t\"\nperiod = 1\n", "'times' must name one column or group"},
        {m + "words = \"a.w\"\n", "metric 1: 'period' is missing"},
        {m + "words = \"a.w\"\nperiod = 0\n", "'period' must be positive"},
        {m + "words = \"a.w\"\nperiod = 1\nwithin = -1\n", "'within' must be positive"},
        {m + "words = \"a.w\"\nperiod = 1\nstats = [\"p95\"]\n", "metric 1: unknown key 'stats'"},
        {m + "words = \"a.w\"\nperiod = 1\nvalid = \"a.v\"\n", "metric 1: unknown key 'valid'"},
    };
    for (const auto& [text, message] : bad)
        EXPECT_NE(error_of(head + text).find(message), std::string::npos)
            << text << "\n gave: " << error_of(head + text);
}

// A case's observable: the column (braces holding variables of the run), above or below a threshold; every
// detection metric of the spec then has the two cells from it.
TEST(Cases, AnObservableIsReadAndAddsItsCellsToTheDetectionMetrics) {
    const std::string text = head + cases + detection;
    const auto plain = parse_spec(text, "/specs/test.toml");
    EXPECT_EQ(plain.metrics.at(0).stats, campaign::detection_cells);
    EXPECT_TRUE(plain.cases.at(1).observable.column.empty());
    const std::string line = "expect = { \"est.fault_face\" = \"plant.fault_string_open_face\" }\n";
    std::string with = text;
    with.replace(with.find(line), line.size(),
                 line + "observable = { column = \"env.sun_face[{plant.fault_string_open_face}]\", above = 136.1 }\n");
    const std::string strap = "onset = \"mag.fault_strap_onset\"\n";
    with.replace(with.find(strap), strap.size(),
                 strap + "observable = { column = \"env.f{a.i}_{b.j}\", below = -2 }\n");
    const auto spec = parse_spec(with, "/specs/test.toml");
    const auto& o = spec.cases.at(1).observable;
    EXPECT_EQ(o.column, "env.sun_face[{plant.fault_string_open_face}]");
    EXPECT_EQ(o.variables, (std::vector<std::string>{"plant.fault_string_open_face"}));
    EXPECT_TRUE(o.above);
    EXPECT_EQ(o.threshold, 136.1);
    const auto& two = spec.cases.at(2).observable;
    EXPECT_EQ(two.variables, (std::vector<std::string>{"a.i", "b.j"}));
    EXPECT_FALSE(two.above);
    EXPECT_EQ(two.threshold, -2.0);
    auto cells = campaign::detection_cells;
    cells.insert(cells.end(), {"observable", "time_observable"});
    EXPECT_EQ(spec.metrics.at(0).stats, cells);
}

TEST(Cases, ObservableMistakesAreRefusedByName) {
    const std::string a = "[[case]]\nname = \"a\"\nonset = \"a.t\"\n";
    const std::string obs = "observable = { column = \"env.g[{a.k}]\", ";
    const std::pair<std::string, std::string> bad[] = {
        {a + "observable = 3\n", "case 'a': 'observable' must be a table"},
        {a + obs + "above = 1, colour = 2 }\n", "case 'a': 'observable': unknown key 'colour'"},
        {a + "observable = { above = 1 }\n", "case 'a': 'observable': 'column' is missing"},
        {a + "observable = { column = 3, above = 1 }\n", "case 'a': 'observable': 'column' must be a string"},
        {a + "observable = { column = \"env.g[{a.k]\", above = 1 }\n", "'column' 'env.g[{a.k]' has unbalanced braces"},
        {a + "observable = { column = \"env.g[a.k}]\", above = 1 }\n", "'column' 'env.g[a.k}]' has unbalanced braces"},
        {a + "observable = { column = \"env.g[{{a.k}}]\", above = 1 }\n", "has unbalanced braces"},
        {a + "observable = { column = \"env.g[{k}]\", above = 1 }\n", "'column' {k}: 'k' is not component.variable"},
        {a + "observable = { column = \"{a.k}\", above = 1 }\n",
         "'observable': 'column': '1' is not component.variable"},
        {a + obs + "above = 1, below = 2 }\n", "case 'a': 'observable' takes one of 'above' and 'below'"},
        {a + "observable = { column = \"env.g[{a.k}]\" }\n", "case 'a': 'observable' takes one of 'above' and 'below'"},
        {a + obs + "above = \"high\" }\n", "case 'a': 'observable': 'above' must be a number"},
        {a + obs + "below = nan }\n", "case 'a': 'observable': 'below' must be finite"},
        {"[[case]]\nname = \"a\"\ncontrol = true\n" + obs + "above = 1 }\n",
         "case 'a': the control expects no fault: it takes no 'onset', 'expect' or 'observable'"},
        {"[[case]]\nname = \"a\"\n" + obs + "above = 1 }\n", "case 'a': 'observable' needs 'onset'"},
    };
    for (const auto& [text, message] : bad)
        EXPECT_NE(error_of(head + text + detection).find(message), std::string::npos)
            << text << "\n gave: " << error_of(head + text + detection);
}
