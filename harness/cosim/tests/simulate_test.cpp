// `cosim simulate`: one FMU through the engine's execution and CSV writer (issue 25), against the
// closed form of the test integrator (dx/dt = u / tau from x = 1).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <sstream>

#include "engine/csv_table.hpp"
#include "simulate_command.hpp"

namespace cosim {
namespace {

TEST(CosimSimulate, OneFmuRunsThroughTheExecutionWithItsOwnColumnNames) {
    const auto csv = std::filesystem::temp_directory_path() / ("cosim_simulate_" + std::to_string(::getpid()) + ".csv");
    SimulateOptions o;
    o.fmu = std::string(COSIM_TEST_FMU_DIR) + "/test_integrator.fmu";
    o.stop_time = 1.0;
    o.output_interval = 0.25;
    o.settings = {"u=2", "tau=4"};
    o.columns = {"y"};
    o.csv = csv;
    std::ostringstream out;
    simulate(o, out);
    const CsvTable table = read_csv(csv);
    ASSERT_EQ(table.names, (std::vector<std::string>{"time", "y"}));
    ASSERT_EQ(table.rows(), 5u);
    for (std::size_t r = 0; r < table.rows(); ++r) {
        const double t = 0.25 * static_cast<double>(r);
        EXPECT_DOUBLE_EQ(table.columns[0][r], t);
        EXPECT_NEAR(table.columns[1][r], 1.0 + 0.5 * t, 1e-6) << "t = " << t;  // x = 1 + u t / tau
    }
    std::filesystem::remove(csv);
    o.output_interval = 1e-9;  // 1e9 rows: past the limit every front end shares
    try {
        simulate(o, out);
        ADD_FAILURE() << "1e9 rows were simulated";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("more than the limit of"), std::string::npos) << e.what();
    }
}

// Issue 40: one rule with `cosim run`: a stop time shorter than the FMU's default step (test_integrator's
// 1 ms) runs with a row every hundredth of the run, said on stderr (it was refused).
TEST(CosimSimulate, AStopTimeShorterThanTheDefaultStepRunsWithItShortened) {
    const auto csv =
        std::filesystem::temp_directory_path() / ("cosim_simulate_short_" + std::to_string(::getpid()) + ".csv");
    SimulateOptions o;
    o.fmu = std::string(COSIM_TEST_FMU_DIR) + "/test_integrator.fmu";
    o.stop_time = 5e-4;
    o.columns = {"y"};
    o.csv = csv;
    std::ostringstream out;
    ::testing::internal::CaptureStderr();
    simulate(o, out);
    const std::string said = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(said.find("is longer than the run (5e-04 s): a row every 5e-06 s instead"), std::string::npos) << said;
    EXPECT_EQ(read_csv(csv).rows(), 101u);
    std::filesystem::remove(csv);
}

}  // namespace
}  // namespace cosim
