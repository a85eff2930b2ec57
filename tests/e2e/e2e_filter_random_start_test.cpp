// Issue 28 end to end: the recursive filter knows how uncertain its start is, from any start attitude. The
// bundled leo_orbit (read at test time) from run 6 of harness/campaigns/faults_healthy.toml: its start attitude
// env.q0 and magnetometer noise seed, as that campaign's results table lists them. From there the
// single-frame attitude the filter starts from errs by 21° (the uncalibrated field carries the spacecraft's
// own 7.3 µT; 5° from the bundled attitude), and a filter that started with its fixed 2.9° σ held that error
// for half an hour: NEES/dof 5.4 over the first 10 minutes, 14° of error against a 2.5° σ at 1024 s, where
// the fault detection then declared a healthy magnetometer axis not flipping. The start covariance now maps
// the offset state's uncertainty into the start attitude (mekf.cpp, add_offset_to_start). Asked: NEES/dof at
// most 1.5 over the first 10 minutes of a running filter. Short on purpose (600 s of the orbit).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "engine/system_description.hpp"
#include "filter_nees.hpp"
#include "recorder.hpp"

namespace {

constexpr double kStop = 600.0;  // s: the first 10 minutes, the convergence from the start

TEST(E2eLeoFilterRandomStart, ConsistentWhileConvergingFromFaultsHealthyRunSix) {
    cosim::SystemOptions options;
    options.fmu_dirs = {PVATT_FMU_DIR};
    // faults_healthy.toml, run 6 (its results table, run_6.row.csv)
    options.settings = {"env.q0[1]=0.7131194155182998", "env.q0[2]=-0.10266026077850852",
                        "env.q0[3]=-0.3316014351356746", "env.q0[4]=0.6090665466791687", "mag.noise_seed=1881336628"};
    cosim::System system(cosim::read_system_description(PVATT_SYSTEMS_DIR "/leo_orbit.ssd"), options);
    cosim::ExecutionOptions ex;
    ex.stop_time = kStop;
    ex.output_interval = 1.0;
    std::vector<std::string> columns = e2e::nees_columns();
    e2e::Recorder r(system, columns);
    cosim::Execution(system, ex).run({&r});

    double nees_sum = 0.0, worst = 0.0;
    int rows = 0;
    for (std::size_t i = 0; i < r.time.size(); ++i) {
        double angle = 0.0;
        const std::optional<double> nees = e2e::recorded_nees_per_dof(r, i, &angle);
        if (!nees) continue;  // the filter not running yet
        nees_sum += *nees;
        worst = std::max(worst, angle * 180.0 / std::numbers::pi);
        ++rows;
    }
    const double nees = rows ? nees_sum / rows : NAN;
    std::printf(
        "leo_orbit from faults_healthy run 6: NEES/dof %.3f over the first %.0f s (%d rows), largest error %.2f deg\n",
        nees, kStop, rows, worst);
    RecordProperty("nees_first_10_min", std::to_string(nees));
    EXPECT_GT(rows, 590);  // the filter starts within the first seconds
    EXPECT_LE(nees, 1.5);
}

}  // namespace
