// The runner and the Co-Simulation solver on blocks with closed-form answers.
#include <gtest/gtest.h>

#include <cmath>

#include "fmu/cs_solver.hpp"
#include "fmu/model_runner.hpp"
#include "fmu/testing/block_driver.hpp"
#include "test_blocks.hpp"

namespace {

using fmu_test::Ball;
using fmu_test::BallData;

// The shared driver at the tolerance the closed forms below are checked to.
struct BallRun : fmu::testing::BlockDriver<Ball> {
    BallRun() : BlockDriver(1e-10) {}
};

TEST(RuntimeSolver, StateEventFoundAtTheClosedFormImpactTime) {
    BallRun run;
    run.start();
    const double t1 = std::sqrt(2.0 * 1.0 / 9.81);  // 0.4515 s
    run.solver->advance(t1 - 1e-3);
    EXPECT_EQ(run.data().bounces, 0);
    run.solver->advance(t1 + 1e-3);
    EXPECT_EQ(run.data().bounces, 1);
    EXPECT_EQ(run.solver->statistics().state_events, 1);
    // 1 ms after the impact: v = e g t1 − g·1e-3, h = e g t1·1e-3 − g/2·1e-6.
    const double v_after = 0.8 * 9.81 * t1;
    run.runner.ensure_evaluated();
    EXPECT_NEAR(run.data().v, v_after - 9.81e-3, 1e-6);
    EXPECT_NEAR(run.data().h, v_after * 1e-3 - 0.5 * 9.81e-6, 1e-7);
}

TEST(RuntimeSolver, TimeEventsHitExactlyAndCounted) {
    BallRun run;
    run.data().enabled = false;  // no bounces: only the 0.25 s ticks
    run.start();
    run.solver->advance(1.0);
    EXPECT_EQ(run.data().ticks, 4);  // 0.25, 0.5, 0.75 and 1.0 (an event at the end is handled)
    EXPECT_EQ(run.solver->statistics().time_events, 4);
    EXPECT_DOUBLE_EQ(run.runner.time(), 1.0);
}

TEST(RuntimeSolver, TerminateRequestStopsTheStep) {
    BallRun run;
    run.data().max_bounces = 1;
    run.start();
    EXPECT_EQ(run.solver->advance(5.0), fmu::CsSolver::Outcome::terminated);
    EXPECT_NEAR(run.runner.time(), std::sqrt(2.0 / 9.81), 1e-6);
}

TEST(RuntimeSolver, IndicatorsWithoutStatesAreLocatedByBisection) {
    fmu::ModelRunner runner{std::make_unique<fmu_test::Clock>()};
    fmu::CsSolver solver(runner, 1e-8);
    solver.advance(0.3);
    EXPECT_EQ(static_cast<fmu_test::Clock&>(runner.model()).data().crossings, 0);
    solver.advance(0.4);  // the event is located at 0.35 on the way, then the step goes on to 0.4
    EXPECT_EQ(static_cast<fmu_test::Clock&>(runner.model()).data().crossings, 1);
    EXPECT_EQ(solver.statistics().state_events, 1);
    EXPECT_DOUBLE_EQ(runner.time(), 0.4);
}

TEST(RuntimeSolver, InitializeRunsOnReadsDuringInitialization) {
    BallRun run;
    run.data().h0 = 2.5;
    run.enter_initialization();
    run.runner.ensure_evaluated();
    EXPECT_DOUBLE_EQ(run.data().h, 2.5);  // the calculated start follows the parameter
}

}  // namespace
