// Whole campaigns of the bundled LEO and seed systems, kept to seconds: the replay of one run is
// bit-identical to its row in the campaign and its full CSV gives the same metrics when they are
// recomputed here from the CSV; a failing run is recorded and the campaign goes on.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/file.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "analysis/run_measures.hpp"
#include "campaign_command.hpp"
#include "campaign_error.hpp"
#include "campaign_run.hpp"
#include "campaign_spec.hpp"
#include "draws.hpp"
#include "engine/csv_table.hpp"
#include "engine/execution.hpp"
#include "engine/system.hpp"
#include "engine/value_text.hpp"
#include "results_table.hpp"
#include "spec_texts.hpp"

using namespace campaign;

namespace {

// The campaign makes its output folder itself.
std::filesystem::path fresh_dir(const std::string& name) {
    return campaign_test::fresh_dir(name, false);
}

std::vector<std::string> lines_of(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::vector<std::string> out;
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

CampaignOptions options_for(const std::string& spec, const std::filesystem::path& output) {
    CampaignOptions o;
    o.spec = std::string(CAMPAIGN_TEST_SPECS) + "/" + spec;
    o.output = output;
    o.fmu_dirs = {PVATT_FMU_DIR};
    o.progress = false;
    return o;
}

// Two runs of leo_short.toml, 5 s each, no figures: a campaign to resume or refuse quickly.
CampaignOptions short_campaign(const std::filesystem::path& output) {
    auto o = options_for("leo_short.toml", output);
    o.runs = 2;
    o.stop_time = 5.0;
    o.figures = false;
    return o;
}

// What the campaign was refused with ("ran" when it was not).
std::string refusal(const CampaignOptions& o) {
    std::ostringstream out;
    try {
        run_campaign(o, out);
    } catch (const std::exception& e) {
        return e.what();
    }
    return "ran";
}

// Every cell but the wall time (header order: ..., wall_time, status, message).
std::vector<std::string> without_wall_time(const std::string& row) {
    auto cells = split_csv_line(row);
    cells.erase(cells.end() - 3);
    return cells;
}

}  // namespace

TEST(Campaign, ReplayIsBitIdenticalAndItsCsvGivesTheSameMetrics) {
    const auto dir = fresh_dir("replay");
    auto o = options_for("leo_short.toml", dir);
    o.runs = 4;
    o.stop_time = 60.0;
    o.figures = false;
    std::ostringstream out;
    ASSERT_EQ(run_campaign(o, out), 0);
    const auto table = lines_of(dir / "results.csv");
    ASSERT_EQ(table.size(), 5u);

    o.replay = 3;
    ASSERT_EQ(run_campaign(o, out), 0);
    const auto replay = lines_of(dir / "run_3.row.csv");
    ASSERT_EQ(replay.size(), 2u);
    EXPECT_EQ(replay[0], table[0]);
    EXPECT_EQ(without_wall_time(replay[1]), without_wall_time(table[4]));

    // The attitude error recomputed from the full CSV: rows where est.samples changed and est.valid,
    // angle 2 atan2(|vector part of conj(q_true) q_est|, |scalar part|) in degrees (another formula
    // than the observer's 2 acos|q_true . q_est|).
    const auto csv = cosim::read_csv(dir / "run_3.csv");
    auto col = [&](const std::string& n) { return csv.columns.at(*csv.find(n)); };
    const auto samples = col("est.samples"), valid = col("est.valid");
    std::vector<double> errors;
    double last = NAN;
    for (std::size_t r = 0; r < csv.rows(); ++r) {
        const bool changed = !(samples[r] == last);
        last = samples[r];
        if (!changed || valid[r] == 0.0) continue;
        const double a[4] = {col("env.q_true[1]")[r], col("env.q_true[2]")[r], col("env.q_true[3]")[r],
                             col("env.q_true[4]")[r]};
        const double b[4] = {col("est.q_est[1]")[r], col("est.q_est[2]")[r], col("est.q_est[3]")[r],
                             col("est.q_est[4]")[r]};
        // conj(a) * b, scalar-last: vector part aw bv - bw av - av x bv, scalar part aw bw + av . bv.
        const double v[3] = {a[3] * b[0] - b[3] * a[0] - (a[1] * b[2] - a[2] * b[1]),
                             a[3] * b[1] - b[3] * a[1] - (a[2] * b[0] - a[0] * b[2]),
                             a[3] * b[2] - b[3] * a[2] - (a[0] * b[1] - a[1] * b[0])};
        const double w = a[3] * b[3] + a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        errors.push_back(2.0 * std::atan2(std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]), std::abs(w)) * 180.0 /
                         M_PI);
    }
    ASSERT_GT(errors.size(), 20u);
    double mean = 0.0, max = 0.0;
    for (double e : errors) {
        mean += e / static_cast<double>(errors.size());
        max = std::max(max, e);
    }
    const auto header = split_csv_line(table[0]);
    const auto row = split_csv_line(table[4]);
    auto cell = [&](const std::string& n) {
        return std::stod(row.at(std::find(header.begin(), header.end(), n) - header.begin()));
    };
    EXPECT_EQ(cell("attitude_error.count"), static_cast<double>(errors.size()));
    EXPECT_NEAR(cell("attitude_error.mean"), mean, 1e-9);
    EXPECT_NEAR(cell("attitude_error.max"), max, 1e-9);
    // The replay's draws reached the FMUs: the environment started from the drawn attitude.
    EXPECT_NEAR(std::abs(col("env.q_true[4]")[0]), std::abs(cell("env.q0[4]")), 1e-9);
    std::filesystem::remove_all(dir);
}

// A metric's after_first (issue 39: the 10 minutes counted from the first sunlight for a run that starts in
// eclipse): `after` counts from the first output point where it held. Checked against the replay's CSV: the
// first row where est.samples >= 3, its time plus 2 s, and the rows from there; a run where it never holds
// samples nothing.
TEST(Campaign, AfterFirstCountsFromWhereItsConditionFirstHeld) {
    const auto dir = fresh_dir("after_first");
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "spec.toml")
        << "system = \"" << CAMPAIGN_TEST_SPECS
        << "/../../../systems/leo_orbit.ssd\"\nstop_time = 8.0\noutput_interval = 0.5\n"
           "runs = 1\nseed = 3\n[set]\n\"est.sample_period\" = 1.0\n"
           "[[metric]]\nname = \"later\"\nkind = \"column\"\ncolumn = \"est.samples\"\n"
           "after = 2.0\nafter_first = \"est.samples >= 3\"\nstats = [\"min\", \"count\"]\n"
           "[[metric]]\nname = \"from_zero\"\nkind = \"column\"\ncolumn = \"est.samples\"\n"
           "after = 2.0\nstats = [\"min\", \"count\"]\n"
           "[[metric]]\nname = \"never\"\nkind = \"column\"\ncolumn = \"est.samples\"\n"
           "after_first = \"env.irradiance < 0\"\nstats = [\"count\"]\n";
    CampaignOptions o = campaign_test::quiet_options(dir / "spec.toml", dir / "out");
    o.replay = 0;  // the run's row and its full CSV, from one run
    std::ostringstream out;
    ASSERT_EQ(run_campaign(o, out), 0);
    const auto table = lines_of(dir / "out" / "run_0.row.csv");
    ASSERT_EQ(table.size(), 2u);
    const auto header = split_csv_line(table[0]);
    const auto row = split_csv_line(table[1]);
    auto cell = [&](const std::string& n) {
        return std::stod(row.at(std::find(header.begin(), header.end(), n) - header.begin()));
    };
    const auto csv = cosim::read_csv(dir / "out" / "run_0.csv");
    const auto time = csv.columns.at(*csv.find("time"));
    const auto samples = csv.columns.at(*csv.find("est.samples"));
    std::size_t first = 0;
    while (first < csv.rows() && samples[first] < 3.0) ++first;
    ASSERT_LT(first, csv.rows());
    ASSERT_GT(time[first], 0.0);  // it first holds later than the start: the two metrics differ
    double min_later = INFINITY, min_zero = INFINITY, count_later = 0.0, count_zero = 0.0;
    for (std::size_t r = 0; r < csv.rows(); ++r) {
        if (time[r] >= time[first] + 2.0) {
            min_later = std::min(min_later, samples[r]);
            ++count_later;
        }
        if (time[r] >= 2.0) {
            min_zero = std::min(min_zero, samples[r]);
            ++count_zero;
        }
    }
    EXPECT_EQ(cell("later.min"), min_later);
    EXPECT_EQ(cell("later.count"), count_later);
    EXPECT_EQ(cell("from_zero.min"), min_zero);
    EXPECT_EQ(cell("from_zero.count"), count_zero);
    EXPECT_LT(count_later, count_zero);
    EXPECT_EQ(cell("never.count"), 0.0);
    std::filesystem::remove_all(dir);
}

TEST(Campaign, AFailingRunIsRecordedAndTheCampaignGoesOn) {
    const auto dir = fresh_dir("failing");
    std::ostringstream out;
    ASSERT_EQ(run_campaign(options_for("seed_spin_failing.toml", dir), out), 0);
    const auto table = lines_of(dir / "results.csv");
    ASSERT_EQ(table.size(), 9u);
    const auto header = split_csv_line(table[0]);
    int failed = 0, ok = 0;
    for (std::size_t i = 1; i < table.size(); ++i) {
        const auto row = split_csv_line(table[i]);
        EXPECT_EQ(row[0], std::to_string(i - 1));  // run order
        const double offset = std::stod(row[1]);
        // The FMU accepts [-1, 1] V: outside, the run fails with a message naming the variable.
        if (std::abs(offset) > 1.0) {
            ++failed;
            EXPECT_EQ(row[row.size() - 2], "failed") << table[i];
            EXPECT_NE(row.back().find("bridge_offset"), std::string::npos) << row.back();
        } else {
            ++ok;
            EXPECT_EQ(row[row.size() - 2], "ok") << table[i];
            EXPECT_GT(std::stod(row[2]), -1.0);  // attitude_error.mean is a number
        }
    }
    EXPECT_GT(failed, 0);
    EXPECT_GT(ok, 0);
    std::ifstream summary(dir / "summary.md");
    std::stringstream text;
    text << summary.rdbuf();
    EXPECT_NE(text.str().find(std::to_string(failed) + " failed"), std::string::npos) << text.str();
    EXPECT_NE(text.str().find("## Failed runs"), std::string::npos);
    EXPECT_TRUE(std::filesystem::exists(dir / "cdf_attitude_error.png"));
    EXPECT_TRUE(std::filesystem::exists(dir / "attitude_error_vs_mag_bridge_offset.png"));
    // --run K of a failed run is a failed command (issue 24): it used to exit 0.
    for (std::size_t i = 1; i < table.size(); ++i) {
        const auto row = split_csv_line(table[i]);
        auto o = options_for("seed_spin_failing.toml", dir);
        o.replay = static_cast<long>(i - 1);
        std::ostringstream replay_out;
        EXPECT_EQ(run_campaign(o, replay_out), row[row.size() - 2] == "failed" ? 1 : 0) << table[i];
    }
    std::filesystem::remove_all(dir);
}

TEST(Campaign, UnknownVariablesFailTheCampaignAtOnce) {
    const auto dir = fresh_dir("unknown");
    auto o = options_for("seed_spin_failing.toml", dir);
    o.settings = {"mag.no_such_parameter=1"};
    std::ostringstream out;
    EXPECT_THROW(run_campaign(o, out), std::exception);
    o.settings = {"mag.bridge_offset=0.1"};  // drawn by the spec
    EXPECT_THROW(run_campaign(o, out), std::exception);
    EXPECT_FALSE(std::filesystem::exists(dir / "results.csv"));
}

// --resume continues only the same campaign: another stop time (or seed, setting, draw) is refused
// before any run, more runs extend it.
TEST(Campaign, ResumeRefusesAnotherCampaignAndExtendsThisOne) {
    const auto dir = fresh_dir("identity");
    auto o = short_campaign(dir);
    std::ostringstream out;
    ASSERT_EQ(run_campaign(o, out), 0);
    o.resume = true;
    o.runs = 3;
    o.stop_time = 6.0;
    EXPECT_NE(refusal(o).find("was run with other settings"), std::string::npos);
    o.stop_time = 5.0;
    o.settings = {"est.weight_mag=2"};
    EXPECT_NE(refusal(o).find("was run with other settings"), std::string::npos);
    o.settings.clear();
    ASSERT_EQ(run_campaign(o, out), 0);
    EXPECT_NE(out.str().find("resuming: 2 runs"), std::string::npos) << out.str();
    EXPECT_EQ(lines_of(dir / "results.csv").size(), 4u);
    std::filesystem::remove_all(dir);
}

// Two campaigns on one table (issue 24): while one holds the folder's lock, a --resume of the same
// campaign is refused with a message instead of writing rows into the same table.
TEST(Campaign, ASecondCampaignOnTheSameFolderIsRefused) {
    const auto dir = fresh_dir("locked");
    auto o = short_campaign(dir);
    std::ostringstream out;
    ASSERT_EQ(run_campaign(o, out), 0);
    const auto table = lines_of(dir / "results.csv");
    const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
    ASSERT_GE(fd, 0);
    ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);  // the first campaign, still running
    o.resume = true;
    o.runs = 3;
    const std::string refused = refusal(o);
    EXPECT_NE(refused.find("in use by another campaign"), std::string::npos) << refused;
    ::close(fd);
    EXPECT_EQ(lines_of(dir / "results.csv"), table);
    std::filesystem::remove_all(dir);
}

// A table whose campaign.txt is gone is not resumed (under whatever seed this invocation has).
TEST(Campaign, ATableWithoutItsIdentityIsNotResumed) {
    const auto dir = fresh_dir("anonymous");
    auto o = short_campaign(dir);
    std::ostringstream out;
    ASSERT_EQ(run_campaign(o, out), 0);
    std::filesystem::remove(dir / "campaign.txt");
    const auto table = lines_of(dir / "results.csv");
    o.resume = true;
    o.runs = 3;
    const std::string refused = refusal(o);
    EXPECT_NE(refused.find("campaign.txt"), std::string::npos) << refused;
    EXPECT_EQ(lines_of(dir / "results.csv"), table);
    std::filesystem::remove_all(dir);
}

// A spec is bounded before it is read: a huge file, or a device that never ends.
TEST(Campaign, OversizedOrNonRegularSpecsAreRefused) {
    const auto dir = fresh_dir("bigspec");
    std::filesystem::create_directories(dir);
    const auto spec = dir / "big.toml";
    {
        std::ifstream in(std::string(CAMPAIGN_TEST_SPECS) + "/leo_short.toml");
        std::ofstream big(spec);
        big << in.rdbuf() << "\n" << std::string(max_spec_bytes, '#') << "\n";
    }
    for (const std::filesystem::path& file : {spec, std::filesystem::path("/dev/zero")}) {
        try {
            read_spec(file);
            ADD_FAILURE() << file << " was read";
        } catch (const CampaignError& e) {
            EXPECT_TRUE(std::string(e.what()).find("max_spec_bytes") != std::string::npos ||
                        std::string(e.what()).find("not a regular file") != std::string::npos)
                << e.what();
        }
    }
    std::filesystem::remove_all(dir);
}

// A value of the wrong type (a text where a Real is, 1.5 where an Integer is) fails the campaign
// before any run (issue 24): it used to fail every run, one after the other, and exit 0.
TEST(Campaign, ValuesOfTheWrongTypeAreRefusedBeforeAnyRun) {
    const auto dir = fresh_dir("types");
    for (const char* setting : {"est.sample_period=fast", "est.solver=no_such_item"}) {
        auto o = short_campaign(dir);
        o.settings = {setting};
        const std::string refused = refusal(o);
        EXPECT_NE(refused.find("[set]"), std::string::npos) << refused;
        EXPECT_FALSE(std::filesystem::exists(dir / "results.csv"));
    }
    std::filesystem::remove_all(dir);
}

// The summary keeps apart what a grid separates and says which runs had nothing to measure (issue 31):
// one table per sun method, and a metric whose condition never holds (irradiance is never negative)
// counted as having no valid sample in every run.
TEST(Campaign, SummaryPerGridValueAndRunsWithoutAValidSample) {
    const auto dir = fresh_dir("per_grid");
    std::filesystem::create_directories(dir);
    std::string spec = campaign_test::leo_short_text() + R"(
[[metric]]
name = "never"
kind = "quaternion_angle"
a = "env.q_true"
b = "est.q_est"
valid = "est.valid"
condition = "env.irradiance < 0"
)";
    const auto spec_file = dir / "per_grid.toml";
    std::ofstream(spec_file) << spec;
    CampaignOptions o = campaign_test::quiet_options(spec_file, dir / "out");
    o.runs = 4;
    o.stop_time = 4.0;
    std::ostringstream out;
    ASSERT_EQ(run_campaign(o, out), 0);
    std::ifstream summary(dir / "out" / "summary.md");
    std::stringstream s;
    s << summary.rdbuf();
    EXPECT_NE(s.str().find("### est.sun_method = difference (2 runs)"), std::string::npos) << s.str();
    EXPECT_NE(s.str().find("### est.sun_method = cones (2 runs)"), std::string::npos) << s.str();
    EXPECT_NE(s.str().find("- never: 4 of 4 finished runs had no valid sample"), std::string::npos) << s.str();
    std::filesystem::remove_all(dir);
}

// Cases and a detection metric (issue 28): a control and a magnetometer axis stuck at its rail on a
// drawn axis, paired. The rail test confirms in 5 s (5 samples at 1 Hz): the fault is declared on the
// drawn axis alone, 4 to 6 s after the onset (the first sample after the onset starts the count); the
// control declares nothing. The summary has a row per case and the pair's ratio.
TEST(Campaign, CasesWithADetectionMetric) {
    const auto dir = fresh_dir("cases");
    auto o = options_for("leo_fault_cases.toml", dir);
    o.figures = false;
    std::ostringstream out;
    ASSERT_EQ(run_campaign(o, out), 0);
    const auto lines = lines_of(dir / "results.csv");
    ASSERT_EQ(lines.size(), 5u);
    const auto header = split_csv_line(lines[0]);
    auto cell = [&](std::size_t row, const std::string& name) {
        const auto at = std::find(header.begin(), header.end(), name);
        EXPECT_NE(at, header.end()) << name;
        return split_csv_line(lines.at(row + 1)).at(static_cast<std::size_t>(at - header.begin()));
    };
    for (std::size_t r = 0; r < 4; ++r) {
        EXPECT_EQ(cell(r, "status"), "ok") << cell(r, "message");
        EXPECT_EQ(cell(r, "case"), r % 2 == 0 ? "control" : "rail");
        EXPECT_EQ(cell(r, "mag.noise_seed"), cell(r - r % 2, "mag.noise_seed"));  // the pair's scene
    }
    for (std::size_t r : {0u, 2u}) {
        EXPECT_EQ(cell(r, "detect.declared"), "0");
        EXPECT_EQ(cell(r, "detect.observable"), "nan");  // the control has none
        EXPECT_EQ(cell(r, "detect.isolated"), "1");
        EXPECT_EQ(cell(r, "mag.fault_stuck_axis"), "");
        EXPECT_EQ(std::stod(cell(r, "detect.orbits")), 40.0 / 5764.0);
    }
    for (std::size_t r : {1u, 3u}) {
        EXPECT_EQ(cell(r, "detect.detected"), "1");
        EXPECT_EQ(cell(r, "detect.isolated"), "1");
        EXPECT_EQ(cell(r, "detect.which"), "est.fault_mag_axis[" + cell(r, "mag.fault_stuck_axis") + "]=1");
        const double time = std::stod(cell(r, "detect.time"));
        EXPECT_GT(time, 4.0);
        EXPECT_LE(time, 6.0);
        // Observable at the first output point (whole seconds) from the onset on; the time counted from it.
        const double onset = std::stod(cell(r, "mag.fault_stuck_onset"));
        EXPECT_NEAR(std::stod(cell(r, "detect.observable")), std::ceil(onset) - onset, 1e-9);
        EXPECT_NEAR(std::stod(cell(r, "detect.time_observable")), time - (std::ceil(onset) - onset), 1e-9);
    }
    std::ifstream summary(dir / "summary.md");
    std::stringstream s;
    s << summary.rdbuf();
    EXPECT_NE(s.str().find("### case = rail (2 runs)"), std::string::npos) << s.str();
    EXPECT_NE(s.str().find("| control | 2 | 0 | – | – | 2 | – | 0 (0 in 0.01388) | – |"), std::string::npos) << s.str();
    EXPECT_NE(s.str().find("| rail | 2 | 2 | "), std::string::npos) << s.str();
    EXPECT_NE(s.str().find(" | 2 | 2 | 1: 2 | – | 0 |"), std::string::npos) << s.str();
    EXPECT_NE(s.str().find("## Against the paired control"), std::string::npos) << s.str();
    std::filesystem::remove_all(dir);
}

// Every bundled campaign (harness/campaigns) is prepared as `cosim campaign` would before its first run:
// the system loaded, every set and drawn variable, value and metric column checked, each case's too.
// A renamed output or parameter breaks the spec here, not after hours of runs.
TEST(Campaign, BundledSpecsArePrepared) {
    const auto folder = std::filesystem::path(CAMPAIGN_TEST_SPECS) / "../../../campaigns";
    long specs = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        if (entry.path().extension() != ".toml") continue;
        ++specs;
        SCOPED_TRACE(entry.path().string());
        EXPECT_NO_THROW({
            const CampaignSetup setup = prepare(read_spec(entry.path()), {PVATT_FMU_DIR}, {});
            for (long k = 0; k < setup.spec.runs; ++k) (void)draw_run(setup.spec, k);
        });
    }
    EXPECT_GE(specs, 4);
}

// A case's own settings and draws come after --set and would silently override it: refused by name.
TEST(Campaign, SetOfAVariableACaseSetsOrDrawsIsRefused) {
    auto o = options_for("leo_fault_cases.toml", fresh_dir("case_set"));
    o.settings = {"mag.fault_stuck_mode=last"};
    EXPECT_NE(refusal(o).find("'mag.fault_stuck_mode' is set by case 'rail'"), std::string::npos) << refusal(o);
    o.settings = {"mag.fault_stuck_axis=2"};
    EXPECT_NE(refusal(o).find("'mag.fault_stuck_axis' is drawn by case 'rail'"), std::string::npos) << refusal(o);
}

// A spec's parameter files reach every run: the ISS-like set's orbit, whose radius over the Earth's
// equatorial 6378.137 km follows from its mean motion alone (Kepler: a = (mu / n^2)^(1/3), 15.5 rev/day:
// 1.0653; SGP4's mean a differs by its J2 and Kozai terms, well under 0.003), not the bundled set's
// (14.985 rev/day: 1.0883).
TEST(Campaign, ParameterFilesOfTheSpecReachEveryRun) {
    const auto dir = fresh_dir("parameters");
    auto o = options_for("leo_parameters.toml", dir);
    o.figures = false;
    std::ostringstream out;
    ASSERT_EQ(run_campaign(o, out), 0) << out.str();
    const auto rows = lines_of(dir / "results.csv");
    ASSERT_EQ(rows.size(), 2u);
    const auto header = split_csv_line(rows[0]), cells = split_csv_line(rows[1]);
    const auto at = std::find(header.begin(), header.end(), "radius.mean") - header.begin();
    ASSERT_LT(static_cast<std::size_t>(at), header.size()) << rows[0];
    const double mu = 398600.4418e9, n = 15.5 * 2.0 * M_PI / 86400.0;
    const double kepler = std::cbrt(mu / (n * n)) / 6378137.0;
    EXPECT_NEAR(std::stod(cells[static_cast<std::size_t>(at)]), kepler, 0.003);
    std::filesystem::remove_all(dir);
}

// A draw may target a system parameter of the .ssd, set as `--set NAME=VALUE` sets it: it feeds every
// component it is connected to (leo_orbit's epoch_month feeds env.epoch_month and est.clock_epoch_month).
// An unknown name is refused before any run with the closest system parameter.
TEST(Campaign, DrawsOnSystemParameters) {
    const auto write_spec = [](const std::string& name, const std::string& target) {
        const auto file = fresh_dir(name + "_spec");
        std::filesystem::create_directories(file);
        std::ofstream out(file / "spec.toml");
        out << "system = \"" << CAMPAIGN_TEST_SPECS << "/../../../systems/leo_orbit.ssd\"\nstop_time = 2.0\n"
            << "output_interval = 1.0\nruns = 2\nseed = 7\n[[draw]]\nkind = \"integer\"\ntarget = \"" << target
            << "\"\nmin = 3\nmax = 3\n[[metric]]\nname = \"light\"\nkind = \"column\"\ncolumn = "
            << "\"env.irradiance\"\nstats = [\"final\"]\n";
        return file / "spec.toml";
    };
    const CampaignSetup setup = prepare(read_spec(write_spec("sysparam", "epoch_month")), {PVATT_FMU_DIR}, {});
    const auto drawn = draw_run(setup.spec, 0).settings;
    EXPECT_EQ(drawn, std::vector<std::string>{"epoch_month=3"});
    auto options = setup.options;
    options.settings.insert(options.settings.end(), drawn.begin(), drawn.end());
    const cosim::System system(setup.description, options);  // the run's system: both blocks get the month
    EXPECT_EQ(system.initial_value(system.component_index("env"), "epoch_month"), "3");
    EXPECT_EQ(system.initial_value(system.component_index("est"), "clock_epoch_month"), "3");
    std::string refused;
    try {
        (void)prepare(read_spec(write_spec("sysparam_typo", "epoch_mnth")), {PVATT_FMU_DIR}, {});
    } catch (const std::exception& e) {
        refused = e.what();
    }
    EXPECT_NE(refused.find("'epoch_mnth' is no system parameter of leo_orbit.ssd (did you mean 'epoch_month'?)"),
              std::string::npos)
        << refused;
    std::filesystem::remove_all(fresh_dir("sysparam_spec"));
    std::filesystem::remove_all(fresh_dir("sysparam_typo_spec"));
}

// A campaign over a system that declares its measures (seed_spin: the sun vector and the single-frame
// attitude) records them per run, from the same code as the end of `cosim run`: the run's cells equal
// analysis::measure_run on the same run made directly, and the end of the campaign says them over runs.
TEST(Campaign, DeclaredMeasuresPerRunAndOverRuns) {
    const auto dir = fresh_dir("measures");
    std::filesystem::create_directories(dir);
    const std::string ssd = std::string(CAMPAIGN_TEST_SPECS) + "/../../../systems/seed_spin.ssd";
    {
        std::ofstream spec(dir / "spec.toml");
        spec << "system = \"" << ssd << "\"\nstop_time = 0.5\noutput_interval = 0.05\nruns = 1\nseed = 3\n"
             << "[[metric]]\nname = \"bus\"\nkind = \"column\"\ncolumn = \"plant.v_bus\"\nstats = [\"final\"]\n";
    }
    auto o = options_for("leo_short.toml", dir / "out");
    o.spec = dir / "spec.toml";
    o.figures = false;
    std::ostringstream out;
    ASSERT_EQ(run_campaign(o, out), 0) << out.str();
    EXPECT_NE(out.str().find("measure.sun_vector.run.all.p50: median "), std::string::npos) << out.str();
    const auto rows = lines_of(dir / "out" / "results.csv");
    ASSERT_EQ(rows.size(), 2u);
    const auto header = split_csv_line(rows[0]), cells = split_csv_line(rows[1]);
    const auto cell = [&](const std::string& name) {
        const auto at = std::find(header.begin(), header.end(), name) - header.begin();
        return static_cast<std::size_t>(at) < header.size() ? cells[static_cast<std::size_t>(at)] : "absent";
    };
    // The same run made directly.
    cosim::SystemOptions options;
    options.fmu_dirs = {PVATT_FMU_DIR};
    const auto description = cosim::read_system_description(ssd);
    ASSERT_TRUE(description.measures);
    cosim::System system(description, options);
    analysis::MeasureRecorder recorder(system);
    cosim::ExecutionOptions ex;
    ex.stop_time = 0.5;
    ex.output_interval = 0.05;
    std::vector<cosim::Observer*> observers{&recorder};
    (void)cosim::Execution(system, ex).run(observers);
    const auto m = analysis::measure_run(recorder.table());
    ASSERT_EQ(m.sun_vectors.size(), 1u);
    ASSERT_EQ(m.estimates.size(), 1u);
    EXPECT_EQ(cell("measure.sun_vector.run.all.p50"), cosim::format_real(m.sun_vectors[0].overall.all.median));
    EXPECT_EQ(cell("measure.sun_vector.run.all.p95"), cosim::format_real(m.sun_vectors[0].overall.all.p95));
    EXPECT_EQ(cell("measure.single_frame.run.all.p95"), cosim::format_real(m.estimates[0].overall.all.p95));
    EXPECT_EQ(cell("measure.single_frame.first_valid"), "0");
    EXPECT_EQ(cell("measure.filter.run.all.p50"), "nan");  // the seed runs no filter
    std::filesystem::remove_all(dir);
}
