// Times a host may pass that are far from the start: the sample count must jump, not loop, and a time
// past the count's limit (fmu::max_instant_index periods) is refused instead of hanging (issue 14 case 1).
#include <gtest/gtest.h>

#include <string>

#include "block_simulation.hpp"
#include "fmu/errors.hpp"
#include "fmu/instant_clock.hpp"

namespace attitude_estimator {
namespace {

using test::Simulation;

TEST(EstimatorFmuFarTime, SteppedOverInstantsGiveTheNextOneAfterTheTime) {
    Simulation sim;
    sim.start(0.0);
    // A Model Exchange host jumps to t = 1e5 s. By hand: the last instant reached is 1e5/0.05 = 2e6,
    // so the next is k = 2000001 at 100000.05 s; one sample is taken at the jump, not two million.
    sim.runner.set_time(1e5);
    sim.runner.event_iteration();
    EXPECT_EQ(sim.data().samples, 2);
    EXPECT_EQ(sim.data().next_index, 2000001);
    EXPECT_DOUBLE_EQ(sim.runner.next_time_event(), 100000.05);
}

TEST(EstimatorFmuFarTime, TimeBeyondTheCountIsRefusedNotAHang) {
    Simulation sim;
    sim.start(0.0);
    // 1e18 s at 0.05 s is 2e19 periods: past int64 and past max_instant_index (1e11).
    sim.runner.set_time(1e18);
    try {
        sim.runner.event_iteration();
        FAIL() << "a time 2e19 periods after the start was accepted";
    } catch (const fmu::Error& e) {
        EXPECT_NE(std::string(e.what()).find(std::to_string(fmu::max_instant_index)), std::string::npos) << e.what();
    }
}

TEST(EstimatorFmuFarTime, JustInsideTheLimitStillSamples) {
    Simulation sim;
    sim.start(0.0);
    // 4e9 s = 8e10 periods of 0.05 s, below the 1e11 limit: sampled, next instant 8e10 + 1.
    sim.runner.set_time(4e9);
    sim.runner.event_iteration();
    EXPECT_EQ(sim.data().next_index, 80000000001);
}

}  // namespace
}  // namespace attitude_estimator
