// A campaign's aims ([[aim]], aims.hpp): what the reader accepts and refuses, how a table's runs are judged
// (counts worked out by hand for a table written here), and a whole campaign that says them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "aims.hpp"
#include "campaign_command.hpp"
#include "campaign_error.hpp"
#include "campaign_spec.hpp"
#include "spec_texts.hpp"
#include "summary.hpp"

using namespace campaign;

namespace {

const std::string head = R"(system = "sys.ssd"
runs = 4
seed = 1
[[metric]]
name = "err"
kind = "quaternion_angle"
a = "env.q_true"
b = "est.q_est"
[[metric]]
name = "bound"
kind = "column"
column = "est.attitude_bound"
stats = ["max"]
)";

using campaign_test::error_of;

}  // namespace

TEST(Aims, ReadsEachKind) {
    const auto spec = parse_spec(head + R"(
[[aim]]
column = "err.p95"
below = 1.0
[[aim]]
column = "err.mean"
within = [0.5, 1.5]
skip_empty = true
[[aim]]
column = "bound.max"
at_least = 2
[[aim]]
column = "measure.filter.converged.sunlit.p95"
below = 1
)",
                                 "/specs/test.toml");
    ASSERT_EQ(spec.aims.size(), 4u);
    EXPECT_EQ(spec.aims[0].kind, AimKind::below);
    EXPECT_EQ(spec.aims[0].high, 1.0);
    EXPECT_FALSE(spec.aims[0].skip_empty);
    EXPECT_EQ(spec.aims[1].kind, AimKind::within);
    EXPECT_EQ(spec.aims[1].low, 0.5);
    EXPECT_EQ(spec.aims[1].high, 1.5);
    EXPECT_TRUE(spec.aims[1].skip_empty);
    EXPECT_EQ(spec.aims[2].kind, AimKind::at_least);
    EXPECT_EQ(spec.aims[2].low, 2.0);
    EXPECT_EQ(aim_text(spec.aims[0]), "err.p95 < 1");
    EXPECT_EQ(aim_text(spec.aims[1]), "err.mean in [0.5, 1.5]");
    EXPECT_EQ(aim_text(spec.aims[2]), "bound.max >= 2");
}

TEST(Aims, MistakesAreRefusedWithTheirPlace) {
    EXPECT_NE(error_of(head + "[[aim]]\ncolumn = \"err.p99\"\nbelow = 1\n").find("aim 1: 'err.p99' is not a metric's"),
              std::string::npos);
    EXPECT_NE(error_of(head + "[[aim]]\ncolumn = \"err.p95\"\nbelow = 1\nat_least = 0\n").find("exactly one of"),
              std::string::npos);
    EXPECT_NE(error_of(head + "[[aim]]\ncolumn = \"err.p95\"\n").find("exactly one of"), std::string::npos);
    EXPECT_NE(error_of(head + "[[aim]]\ncolumn = \"err.p95\"\nwithin = [2, 1]\n").find("low <= high"),
              std::string::npos);
    EXPECT_NE(error_of(head + "[[aim]]\ncolumn = \"err.p95\"\nwithin = [1]\n").find("[low, high]"), std::string::npos);
    EXPECT_NE(error_of(head + "[[aim]]\ncolumn = \"err.p95\"\nbelow = \"1\"\n").find("'below' must be a number"),
              std::string::npos);
    EXPECT_NE(error_of(head + "[[aim]]\ncolumn = \"err.p95\"\nbelow = 1\nskip_empty = 1\n").find("true or false"),
              std::string::npos);
    EXPECT_NE(error_of(head + "[[aim]]\ncolumn = \"err.p95\"\nbelow = 1\nabove = 0\n").find("unknown key 'above'"),
              std::string::npos);
    EXPECT_NE(
        error_of(head + "[[metric]]\nname = \"d\"\nkind = \"detection\"\nwords = [\"est.fault_face\"]\nperiod = 60\n"
                        "[[aim]]\ncolumn = \"d.which\"\nbelow = 1\n")
            .find("holds text"),
        std::string::npos);
    EXPECT_NE(error_of("aim = 3\n" + head).find("aims are written [[aim]]"), std::string::npos);
    // A line number names the entry at fault.
    EXPECT_NE(error_of(head + "[[aim]]\ncolumn = \"err.p95\"\nwithin = [2, 1]\n").find("test.toml:16:"),
              std::string::npos);
}

TEST(Aims, EachRunJudgedByEachAim) {
    auto spec = parse_spec(head + R"(
[[aim]]
column = "err.p95"
below = 1.0
[[aim]]
column = "err.mean"
within = [0.5, 1.5]
skip_empty = true
[[aim]]
column = "bound.max"
at_least = 2
)",
                           "/specs/test.toml");
    ResultRows table;
    table.header = {"run", "err.mean", "err.p95", "bound.max", "wall_time", "status", "message"};
    table.rows = {
        {"0", "0.5", "0.99", "2", "1", "ok", ""},        // meets all three (each bound included where it says so)
        {"1", "nan", "1", "3", "1", "ok", ""},           // p95 at the bound: misses; mean not judged
        {"2", "", "", "", "1", "failed", "boom"},        // not judged at all
        {"3", "1.6", "nan", "1.5", "1", "stopped", ""},  // misses all three: no p95 counts as a miss
        {"4", "1.5", "0.2", "7", "1", "ok", ""},         // meets all three
    };
    const AimsReport r = judge_aims(spec, table);
    EXPECT_EQ(r.finished, 4);
    EXPECT_EQ(r.failed, 1);
    ASSERT_EQ(r.per_aim.size(), 3u);
    EXPECT_EQ(r.per_aim[0].met, 2);
    EXPECT_EQ(r.per_aim[0].missed, 2);
    EXPECT_EQ(r.per_aim[0].missing_runs, (std::vector<std::string>{"1", "3"}));
    EXPECT_EQ(r.per_aim[1].met, 2);
    EXPECT_EQ(r.per_aim[1].missed, 1);
    EXPECT_EQ(r.per_aim[1].not_judged, 1);
    EXPECT_EQ(r.per_aim[2].met, 3);
    EXPECT_EQ(r.per_aim[2].missing_runs, (std::vector<std::string>{"3"}));
    EXPECT_EQ(r.every, 2);
    EXPECT_EQ(r.missing_any, (std::vector<std::string>{"1", "3"}));

    std::ostringstream md, out;
    write_aims(md, spec, r, {});
    print_aims(spec, r, {}, out);
    EXPECT_NE(md.str().find("| err.p95 < 1 | 2 | 2 | 0 | 1, 3 |"), std::string::npos) << md.str();
    EXPECT_NE(md.str().find("**Every aim: 2 of 4 finished runs.**"), std::string::npos) << md.str();
    EXPECT_NE(out.str().find("err.mean in [0.5, 1.5]: 2 met, 1 missed (run 3), 1 not judged (no value)"),
              std::string::npos)
        << out.str();
    EXPECT_NE(out.str().find("every aim: 2 of 4 runs"), std::string::npos) << out.str();
}

// Per kind of scene: the values of a drawn choice of names, each judged apart (a numeric choice is no kind).
TEST(Aims, EachKindOfSceneJudgedApart) {
    auto spec = parse_spec(head + R"(
[[draw]]
kind = "choice"
target = "env.orbit_class"
values = ["polar", "iss"]
[[draw]]
kind = "choice"
target = "est.rate"
values = [1, 2]
[[aim]]
column = "err.p95"
below = 1.0
[[aim]]
column = "bound.max"
at_least = 2
)",
                           "/specs/test.toml");
    ResultRows table;
    table.header = {"run", "env.orbit_class", "est.rate", "err.p95", "bound.max", "wall_time", "status", "message"};
    table.rows = {
        {"0", "polar", "1", "0.5", "3", "1", "ok", ""},  // both aims
        {"1", "iss", "2", "1.5", "3", "1", "ok", ""},    // misses the first
        {"2", "polar", "1", "0.5", "1", "1", "ok", ""},  // misses the second
        {"3", "iss", "1", "0.2", "2", "1", "ok", ""},    // both aims
        {"4", "iss", "2", "", "", "1", "failed", "x"},   // not judged
    };
    const auto by = judge_aims_by_category(spec, table);
    ASSERT_EQ(by.size(), 1u);
    EXPECT_EQ(by[0].column, "env.orbit_class");
    ASSERT_EQ(by[0].values.size(), 2u);
    const auto& [polar_name, polar] = by[0].values[0];
    const auto& [iss_name, iss] = by[0].values[1];
    EXPECT_EQ(polar_name, "polar");
    EXPECT_EQ(polar.finished, 2);
    EXPECT_EQ(polar.every, 1);
    EXPECT_EQ(polar.per_aim[0].met, 2);
    EXPECT_EQ(polar.per_aim[1].met, 1);
    EXPECT_EQ(iss_name, "iss");
    EXPECT_EQ(iss.finished, 2);
    EXPECT_EQ(iss.failed, 1);
    EXPECT_EQ(iss.every, 1);
    EXPECT_EQ(iss.per_aim[0].met, 1);
    EXPECT_EQ(iss.per_aim[1].met, 2);

    std::ostringstream md, out;
    write_aims(md, spec, judge_aims(spec, table), by);
    print_aims(spec, judge_aims(spec, table), by, out);
    EXPECT_NE(md.str().find("### Aims by env.orbit_class"), std::string::npos) << md.str();
    EXPECT_NE(md.str().find("| polar | 2 | 1 | 2/2 | 1/2 |"), std::string::npos) << md.str();
    EXPECT_NE(md.str().find("| iss | 2 | 1 | 1/2 | 2/2 |"), std::string::npos) << md.str();
    EXPECT_NE(out.str().find("every aim by env.orbit_class: polar 1 of 2, iss 1 of 2"), std::string::npos) << out.str();
}

// A table read back from its file (the C API's and Python's way to the aims) and judged as JSON: the same table as
// above, written as the campaign writes it (a message with a comma quoted); the counts worked out by hand.
TEST(Aims, AWrittenTableIsReadBackAndJudgedAsJson) {
    const auto dir = campaign_test::fresh_dir("aims_table");
    auto spec = parse_spec(head + R"(
[[draw]]
kind = "choice"
target = "env.orbit_class"
values = ["polar", "iss"]
[[aim]]
column = "err.p95"
below = 1.0
[[aim]]
column = "bound.max"
within = [2, 5]
skip_empty = true
)",
                           "/specs/test.toml");
    const std::string header = "run,env.orbit_class,err.p95,bound.max,wall_time,status,message\n";
    std::ofstream(dir / "results.csv") << header << "0,polar,0.5,3,1,ok,\n"
                                       << "1,iss,1.5,3,1,ok,\n"
                                       << "2,polar,0.5,,1,ok,\n"  // no bound: not judged by the second
                                       << "3,iss,0.2,6,1,ok,\n"
                                       << "4,iss,,,1,failed,\"boom, twice\"\n";
    const ResultRows table = read_table(dir / "results.csv");
    ASSERT_EQ(table.rows.size(), 5u);
    EXPECT_EQ(table.rows[4][6], "boom, twice");
    const std::string json = aims_json(spec, judge_aims(spec, table), judge_aims_by_category(spec, table));
    EXPECT_EQ(
        json,
        "{\"finished\": 4, \"failed\": 1, \"every\": 2, \"missing_any\": [1, 3], \"aims\": ["
        "{\"column\": \"err.p95\", \"condition\": \"err.p95 < 1\", \"kind\": \"below\", \"low\": null, "
        "\"high\": 1, \"skip_empty\": false, \"met\": 3, \"missed\": 1, \"not_judged\": 0, \"missing_runs\": [1]}, "
        "{\"column\": \"bound.max\", \"condition\": \"bound.max in [2, 5]\", \"kind\": \"within\", \"low\": 2, "
        "\"high\": 5, \"skip_empty\": true, \"met\": 2, \"missed\": 1, \"not_judged\": 1, \"missing_runs\": [3]}], "
        "\"by_category\": [{\"column\": \"env.orbit_class\", \"values\": ["
        "{\"value\": \"polar\", \"finished\": 2, \"failed\": 0, \"every\": 2, \"met\": [2, 1], \"judged\": [2, 1]}, "
        "{\"value\": \"iss\", \"finished\": 2, \"failed\": 1, \"every\": 0, \"met\": [1, 1], \"judged\": [2, 2]}]}]}");

    // What is refused, by name: no file, a row still being written, a row of another width, another kind of file,
    // a table without an aim's column.
    const auto refusal = [&](const std::string& text) {
        std::ofstream(dir / "bad.csv", std::ios::trunc) << text;
        try {
            judge_aims(spec, read_table(dir / "bad.csv"));
        } catch (const CampaignError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    try {
        read_table(dir / "none.csv");
        ADD_FAILURE() << "a missing table was read";
    } catch (const CampaignError& e) {
        EXPECT_NE(std::string(e.what()).find("cannot read the results table"), std::string::npos) << e.what();
    }
    EXPECT_NE(refusal(header + "0,polar,0.5,3,1,ok,").find("still running or was stopped"), std::string::npos);
    EXPECT_NE(refusal(header + "0,polar,0.5,3,1,ok\n").find("bad.csv:2: a row of 6 cells where the header has 7"),
              std::string::npos);
    EXPECT_NE(refusal("a,b\n1,2\n").find("not a campaign's results table"), std::string::npos);
    EXPECT_NE(refusal("").find("is empty"), std::string::npos);
    EXPECT_NE(refusal("run,err.p95,status,message\n0,1,ok,\n").find("no column 'bound.max'"), std::string::npos);
    std::filesystem::remove_all(dir);
}

// A whole campaign of two short runs with two aims no run can miss or meet: a state of charge is never negative.
TEST(Aims, ACampaignSaysThemAtItsEndAndInItsSummary) {
    const auto dir = campaign_test::fresh_dir("aims");
    std::string spec = campaign_test::leo_short_text() + R"(
[[aim]]
column = "soc.min"
at_least = 0
[[aim]]
column = "soc.min"
below = 0
)";
    std::ofstream(dir / "aims.toml") << spec;
    CampaignOptions o = campaign_test::quiet_options(dir / "aims.toml", dir / "out");
    o.runs = 2;
    o.stop_time = 4.0;
    std::ostringstream out;
    ASSERT_EQ(run_campaign(o, out), 0);
    EXPECT_NE(out.str().find("soc.min >= 0: 2 met, 0 missed\n"), std::string::npos) << out.str();
    EXPECT_NE(out.str().find("soc.min < 0: 0 met, 2 missed (runs 0, 1)"), std::string::npos) << out.str();
    EXPECT_NE(out.str().find("every aim: 0 of 2 runs"), std::string::npos) << out.str();
    std::ifstream summary(dir / "out" / "summary.md");
    std::stringstream s;
    s << summary.rdbuf();
    EXPECT_NE(s.str().find("## Aims"), std::string::npos) << s.str();
    EXPECT_NE(s.str().find("**Every aim: 0 of 2 finished runs.**"), std::string::npos) << s.str();
    // A measure column is checked once the system's measures are known: one it does not declare is refused.
    std::ofstream(dir / "bad.toml") << spec << "[[aim]]\ncolumn = \"measure.filter.nothing\"\nbelow = 1\n";
    o.spec = dir / "bad.toml";
    o.output = dir / "bad";
    try {
        run_campaign(o, out);
        ADD_FAILURE() << "an aim on a column the table does not have ran";
    } catch (const CampaignError& e) {
        EXPECT_NE(std::string(e.what()).find("aim 3: 'measure.filter.nothing' is not a column"), std::string::npos)
            << e.what();
    }
    std::filesystem::remove_all(dir);
}

// The bundled robustness campaign carries issue 39's eight aims and its own ninth.
TEST(Aims, TheRobustnessCampaignCarriesIssue39sAims) {
    const auto spec = read_spec(std::filesystem::path(CAMPAIGN_TEST_SPECS) / "../../../campaigns/robustness.toml");
    ASSERT_EQ(spec.aims.size(), 9u);
    EXPECT_EQ(aim_text(spec.aims[0]), "error_sunlit.p95 < 1");
    EXPECT_EQ(aim_text(spec.aims[2]), "nees_sunlit.per_dof in [0.5, 1.5]");
    EXPECT_EQ(aim_text(spec.aims[4]), "nees_sunlit.chi2_99 >= 95");
    EXPECT_EQ(aim_text(spec.aims[8]), "error_while_valid.max < 10");  // never valid while further off than 10 deg
    EXPECT_TRUE(spec.aims[1].skip_empty);
    EXPECT_FALSE(spec.aims[0].skip_empty);
}
