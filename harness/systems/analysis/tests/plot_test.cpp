// cosim plot: the errors are taken where the estimate changes, while it is valid.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "analysis/result_figures.hpp"
#include "engine/csv_table.hpp"

namespace analysis {
namespace {

// The truth turns about z at 1 rad/s; the estimate is exact at each sample (every 0.05 s) and held in
// between, as a sampled on-board computer's; the last sample is flagged invalid and off by 10°. Taken at
// the rows where the estimate changes and is valid (t = 0, 0.05, 0.10, 0.15), the error is exactly 0;
// drawn through every row it would reach 0.04 rad = 2.29° (the turn over 4 of the 0.01 s rows).
TEST(CosimPlot, ErrorsAtTheEstimateUpdatesWhileValid) {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("cosim_plot_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
    std::filesystem::create_directories(dir);
    const auto csv = dir / "run.csv";
    {
        std::ofstream out(csv);
        out << "time,env.q_true[1],env.q_true[2],env.q_true[3],env.q_true[4],est.q_est[1],est.q_est[2],est.q_est[3],"
               "est.q_est[4],est.valid\n";
        for (int k = 0; k <= 20; ++k) {
            const double t = 0.01 * k;
            const int sample = k / 5;
            const bool last = sample == 4;
            const double held = 0.05 * sample + (last ? 10.0 * M_PI / 180.0 : 0.0);
            out << t << ",0,0," << std::sin(t / 2) << "," << std::cos(t / 2) << ",0,0," << std::sin(held / 2) << ","
                << std::cos(held / 2) << "," << (last ? 0 : 1) << "\n";
        }
    }
    std::ostringstream notes;
    const auto written = plot_results(csv, dir, notes);
    EXPECT_TRUE(std::filesystem::exists(dir / "attitude_error.png"));
    std::ifstream in(dir / "index.html");
    const std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(html.find("<td>single-frame q_est</td><td>4</td><td>0</td><td>0</td>"), std::string::npos) << html;
    EXPECT_NE(html.find("attitude_error.png"), std::string::npos);
    EXPECT_NE(html.find("<a href=\"run.csv\">"), std::string::npos) << html;  // the page links its CSV
    std::filesystem::remove_all(dir);
}

TEST(CosimPlot, EveryEstimateWithItsOwnStatistics) {
    // The filter's q_filt beside the single-frame q_est: each measured at its own samples while its own
    // flag is valid. q_est is 2 deg off the truth (a rotation of 2 deg about z), q_filt 0.5 deg, the filter
    // valid from the third sample on: 4 and 2 samples.
    const auto dir = std::filesystem::temp_directory_path() /
                     ("cosim_plot_both_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
    std::filesystem::create_directories(dir);
    const auto csv = dir / "run.csv";
    {
        std::ofstream out(csv);
        out << "time,env.q_true[1],env.q_true[2],env.q_true[3],env.q_true[4],est.q_est[1],est.q_est[2],est.q_est[3],"
               "est.q_est[4],est.valid,est.q_filt[1],est.q_filt[2],est.q_filt[3],est.q_filt[4],est.filter_valid\n";
        for (int k = 0; k < 4; ++k) {
            const double t = 0.1 * k, truth = 0.1 * k, single = truth + 2.0 * M_PI / 180.0,
                         filter = truth + 0.5 * M_PI / 180.0;
            out << t << ",0,0," << std::sin(truth / 2) << "," << std::cos(truth / 2) << ",0,0," << std::sin(single / 2)
                << "," << std::cos(single / 2) << ",1,0,0," << std::sin(filter / 2) << "," << std::cos(filter / 2)
                << "," << (k >= 2 ? 1 : 0) << "\n";
        }
    }
    std::ostringstream notes;
    plot_results(csv, dir, notes);
    std::ifstream in(dir / "index.html");
    const std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(html.find("<td>single-frame q_est</td><td>4</td><td>2</td><td>2</td>"), std::string::npos) << html;
    EXPECT_NE(html.find("<td>filter q_filt</td><td>2</td><td>0.5</td><td>0.5</td>"), std::string::npos) << html;
    // Derived signals on request: the filter is 0.5 deg ahead about body z, so the truth is -0.5 deg of yaw
    // from it (to the CSV's 6 digits), at its valid samples only.
    PlotOptions options;
    options.derived = dir / "derived.csv";
    plot_results(csv, dir, notes, options);
    const auto derived = cosim::read_csv(dir / "derived.csv");
    const auto yaw = derived.find("q_filt_yaw_deg");
    ASSERT_TRUE(yaw.has_value());
    EXPECT_TRUE(std::isnan(derived.columns[*yaw][0]));
    EXPECT_NEAR(derived.columns[*yaw][3], -0.5, 1e-4);
    std::filesystem::remove_all(dir);
}

// A CSV with the attitude columns (drawn) and a battery column of no number (a figure gnuplot refuses).
void write_two_figure_csv(const std::filesystem::path& csv) {
    std::ofstream out(csv);
    out << "time,env.q_true[1],env.q_true[2],env.q_true[3],env.q_true[4],est.q_est[1],est.q_est[2],est.q_est[3],"
           "est.q_est[4],est.valid,bat.soc\n";
    for (int k = 0; k <= 20; ++k)
        out << 0.01 * k << ",0,0,0,1,0,0," << std::sin(0.001 * k) << "," << std::cos(0.001 * k) << ",1,nan\n";
}

// Issue 24: the output folder's name used to be pasted into gnuplot's script: a folder named
// x';system('touch pwned');' ran the shell command, an apostrophe broke every figure.
TEST(CosimPlot, AFolderNameIsNeverGnuplotCode) {
    const auto root = std::filesystem::temp_directory_path() /
                      ("cosim_plot_names_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
    const auto hostile = root / "x';system('touch pwned');'";
    const auto quoted = root / "it's here";
    std::filesystem::create_directories(hostile);
    std::filesystem::create_directories(quoted);
    const auto csv = root / "run.csv";
    write_two_figure_csv(csv);
    for (const auto& dir : {hostile, quoted}) {
        std::ostringstream notes;
        try {
            plot_results(csv, dir, notes);
        } catch (const std::exception&) {
            // the battery figure fails (see below); the attitude figure must be drawn
        }
        EXPECT_TRUE(std::filesystem::exists(dir / "attitude_error.png")) << dir << ": " << notes.str();
        EXPECT_FALSE(std::filesystem::exists(dir / "pwned"));
        EXPECT_FALSE(std::filesystem::exists("pwned")) << "a shell command ran from a folder's name";
        EXPECT_FALSE(std::filesystem::exists(root / "pwned"));
    }
    std::filesystem::remove_all(root);
}

// A figure gnuplot cannot draw fails alone, with its message, and leaves no (empty) PNG behind.
TEST(CosimPlot, AFailingFigureFailsAloneAndLeavesNoPng) {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("cosim_plot_fail_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
    std::filesystem::create_directories(dir);
    write_two_figure_csv(dir / "run.csv");
    std::ostringstream notes;
    try {
        plot_results(dir / "run.csv", dir, notes);
        ADD_FAILURE() << "a failed figure went unreported";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("failed"), std::string::npos) << e.what();
    }
    EXPECT_NE(notes.str().find("battery_soc.png"), std::string::npos) << notes.str();
    EXPECT_TRUE(std::filesystem::exists(dir / "attitude_error.png"));
    EXPECT_FALSE(std::filesystem::exists(dir / "battery_soc.png")) << "an empty PNG was left";
    std::filesystem::remove_all(dir);
}

// Issue 40: the page says what the run reached (per phase, the chi-square coverage) and marks each fault
// the on-board computer declared on the figures, and each injected fault's onset (the onset column `cosim
// run` writes) with the delay to the declaration; the battery's axis says what it is. The filter is 1 deg
// off about z with sigma 1 deg per axis (epsilon = 1 at every sample: coverage 100 %, NEES/dof 1/3), sunlit
// for the first half; the shadow falls on the plant at 0.3 s, face +y is declared at t = 0.5 s.
TEST(CosimPlot, ThePageSaysWhatTheRunReachedAndMarksTheFaults) {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("cosim_plot_measures_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
    std::filesystem::create_directories(dir);
    const auto csv = dir / "run.csv";
    {
        std::ofstream out(csv);
        out << "time,env.q_true[1],env.q_true[2],env.q_true[3],env.q_true[4],est.q_filt[1],est.q_filt[2],"
               "est.q_filt[3],est.q_filt[4],est.filter_valid,env.irradiance,plant.soc";
        for (int i = 1; i <= 6; ++i) out << ",est.attitude_cov_sqrt[" << i << "]";
        for (int i = 1; i <= 6; ++i) out << ",est.fault_face_time[" << i << "]";
        out << ",plant.fault_shadow_onset\n";
        const double s = M_PI / 180.0, h = 0.5 * s;
        for (int k = 0; k <= 10; ++k) {
            const double t = 0.1 * k, turn = 0.01 * k;  // the truth turns; the filter stays 1 deg behind
            out << t << ",0,0," << std::sin(turn / 2) << "," << std::cos(turn / 2) << ",0,0," << std::sin(turn / 2 - h)
                << "," << std::cos(turn / 2 - h) << ",1," << (k < 5 ? 1361 : 0) << "," << 0.9 + 0.001 * k << "," << s
                << ",0," << s << ",0,0," << s;
            for (int f = 1; f <= 6; ++f) out << "," << (f == 3 && k >= 5 ? 0.5 : -1.0);
            out << ",0.3\n";
        }
    }
    std::ostringstream notes;
    PlotOptions options;
    options.format = "svg";
    plot_results(csv, dir, notes, options);
    std::ifstream in(dir / "index.html");
    const std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(html.find("What the run reached"), std::string::npos) << html;
    EXPECT_NE(html.find("<td>filter q_filt</td><td>whole run</td><td>1 / 1</td><td>1 / 1</td><td>11</td><td>0.333</td>"
                        "<td>100.0 %</td>"),
              std::string::npos)
        << html;
    EXPECT_NE(html.find("<li>fault injected: plant shadow from 0.3 s</li>"), std::string::npos) << html;
    EXPECT_NE(html.find("<li>fault declared: panel face +y at 0.5 s, 0.2 s after the onset of plant shadow</li>"),
              std::string::npos)
        << html;
    const auto read = [&](const char* name) {
        std::ifstream f(dir / name);
        return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    };
    EXPECT_NE(read("attitude_error.svg").find("declared: panel face +y"), std::string::npos);
    EXPECT_NE(read("attitude_error.svg").find("onset: plant shadow"), std::string::npos);
    EXPECT_NE(read("battery_soc.svg").find("state of charge (0 to 1)"), std::string::npos);
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace analysis
