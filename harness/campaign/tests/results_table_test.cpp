// The results table: cells that survive the round trip, and resume's reading of a killed campaign's table.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "campaign_error.hpp"
#include "results_table.hpp"
#include "spec_texts.hpp"

using namespace campaign;
using campaign_test::fresh_dir;

namespace {

std::string slurp(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

TEST(ResultsTable, CellsRoundTrip) {
    const std::vector<std::string> cells = {"3", "plain", "with, comma", "with \"quotes\"", "", "line\nend"};
    std::string line;
    for (std::size_t i = 0; i < cells.size(); ++i) line += (i ? "," : "") + csv_cell(cells[i]);
    EXPECT_EQ(line, "3,plain,\"with, comma\",\"with \"\"quotes\"\"\",,\"line end\"");
    auto back = split_csv_line(line);
    EXPECT_EQ(back[2], "with, comma");
    EXPECT_EQ(back[3], "with \"quotes\"");
    EXPECT_EQ(back[5], "line end");
    EXPECT_EQ(back.size(), cells.size());
}

TEST(ResultsTable, RowsHoldEveryPart) {
    RunResult r;
    r.index = 12;
    r.draw_cells = {"0.5", "cones"};
    r.metric_cells = {"1.25"};
    r.wall_time = 0.5;
    r.status = "failed";
    r.message = "bridge_offset: 1.5 out of [-1, 1]";
    EXPECT_EQ(format_row(r), "12,0.5,cones,1.25,0.5,failed,\"bridge_offset: 1.5 out of [-1, 1]\"");
}

// A table cut by a kill: rows 0, 2 and half of row 3. Resume keeps 0 and 2, cuts the half row off the file.
TEST(ResultsTable, ResumeReadsFinishedRowsAndDropsACutRow) {
    const auto dir = fresh_dir("resume");
    const auto file = dir / "results.csv";
    const std::vector<std::string> header = {"run", "x", "m.mean", "wall_time", "status", "message"};
    {
        ResultsWriter w(file, header, false);
        w.append("0,0.1,5,1.5,ok,");
        w.append("2,0.3,7,1.5,ok,");
    }
    { std::ofstream(file, std::ios::app) << "3,0.4,"; }
    const auto rows = read_results(file, header, 5);
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows.at(2), "2,0.3,7,1.5,ok,");
    EXPECT_EQ(slurp(file), "run,x,m.mean,wall_time,status,message\n0,0.1,5,1.5,ok,\n2,0.3,7,1.5,ok,\n");
    {
        ResultsWriter w(file, header, true);
        w.append("1,0.2,6,1.5,ok,");
    }
    auto all = read_results(file, header, 5);
    write_sorted(file, header, all);
    EXPECT_EQ(slurp(file),
              "run,x,m.mean,wall_time,status,message\n0,0.1,5,1.5,ok,\n1,0.2,6,1.5,ok,\n2,0.3,7,1.5,ok,\n");
    std::filesystem::remove_all(dir);
}

TEST(ResultsTable, ResumeRefusesAnotherCampaignsTable) {
    const auto dir = fresh_dir("refuse");
    const auto file = dir / "results.csv";
    const std::vector<std::string> header = {"run", "x", "wall_time", "status", "message"};
    { ResultsWriter(file, header, false).append("0,1,1,ok,"); }
    EXPECT_THROW(read_results(file, {"run", "y", "wall_time", "status", "message"}, 5), CampaignError);
    EXPECT_THROW(read_results(file, header, 0), CampaignError);  // run 0 beyond a campaign of 0 runs
    { std::ofstream(file, std::ios::app) << "0,2,1,ok,\n"; }
    EXPECT_THROW(read_results(file, header, 5), CampaignError);       // run 0 twice
    EXPECT_THROW(ResultsWriter(file, header, false), CampaignError);  // never replaced silently
    std::filesystem::remove_all(dir);
}
