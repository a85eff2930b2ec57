// The runner and the Co-Simulation solver on blocks with closed-form answers.
#include <gtest/gtest.h>

#include <array>
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

// A host that sets again the time and states it set last (a Model Exchange host stops at the instant it
// just checked its indicators at) gets the outputs already computed there: evaluating again would give the
// same bits. Any other time or state, or the block's own trial times (set_time), evaluates again.
struct CountedData {
    double x = 0.0, der_x = 0.0, y = 0.0;
};
class Counted : public fmu::Block<Counted, CountedData> {
public:
    static void declare(fmu::Table<CountedData>& t) {
        t.state("x", &CountedData::x, &CountedData::der_x, "1", "A state");
        t.output("y", &CountedData::y, "1", "x plus time").depends_on({"x"});
    }
    static fmu::ModelInfo describe() {
        fmu::ModelInfo info;
        info.model_identifier = "counted";
        info.model_name = "counted";
        info.description = "Counts its evaluations";
        return info;
    }
    void evaluate(double t) override {
        ++evaluations;
        data().der_x = -data().x;
        data().y = data().x + t;
    }
    int evaluations = 0;
};

TEST(RuntimeSolver, TheSameTimeAndStatesAgainKeepTheOutputs) {
    fmu::ModelRunner runner{std::make_unique<Counted>()};
    auto& block = static_cast<Counted&>(runner.model());
    const std::array<double, 1> x{2.0};
    runner.set_time_from_host(1.0);
    runner.set_states(x);
    runner.ensure_evaluated();
    ASSERT_EQ(block.evaluations, 1);
    runner.set_time_from_host(1.0);
    runner.set_states(x);
    runner.ensure_evaluated();
    EXPECT_EQ(block.evaluations, 1);
    EXPECT_EQ(block.data().y, 3.0);

    runner.set_states(std::array<double, 1>{-0.0});  // another state, if only in its sign bit
    runner.ensure_evaluated();
    EXPECT_EQ(block.evaluations, 2);
    runner.set_time_from_host(1.5);
    runner.ensure_evaluated();
    EXPECT_EQ(block.evaluations, 3);
    EXPECT_EQ(block.data().y, 1.5);
    runner.set_time(1.5);  // the block's own step between events marks every trial time, repeated or not
    runner.ensure_evaluated();
    EXPECT_EQ(block.evaluations, 4);
}

}  // namespace
