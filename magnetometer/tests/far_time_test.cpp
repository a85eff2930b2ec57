// Times far from the start (issue 14 case 1): the set/reset instants a host stepped over are counted at
// once, and a time beyond the count's limit is refused instead of looping. (The held noise has no
// instants: held_noise_test.cpp covers its interval index.)
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "fmu/errors.hpp"
#include "fmu/model_runner.hpp"
#include "fmu/testing/block_driver.hpp"
#include "magnetometer/magnetometer_block.hpp"

namespace magnetometer {
namespace {

// Driven without a solver's steps: the tests jump the runner's time to far instants.
using Runner = fmu::testing::BlockDriver<MagnetometerBlock>;

TEST(MagnetometerFarTime, SteppedOverPulsesAreCountedAtOnce) {
    Runner r;
    r.data().set_reset_source = SetResetSource::timer;
    r.data().set_reset_period = 1.0;
    r.start();
    ASSERT_TRUE(r.data().set_polarity);
    // Jump to 10.5 s: by hand, pulses at 1, 2, ..., 10 s were due (ten flips: set polarity again), the
    // next pulse is at 11 s.
    r.runner.set_time(10.5);
    r.runner.event_iteration();
    EXPECT_TRUE(r.data().set_polarity);
    EXPECT_NEAR(r.data().next_set_reset, 11.0, 1e-9);
    EXPECT_GT(r.runner.next_time_event(), 10.5);
    // 11.5 s: one more pulse (reset polarity).
    r.runner.set_time(11.5);
    r.runner.event_iteration();
    EXPECT_FALSE(r.data().set_polarity);
}

TEST(MagnetometerFarTime, TimeBeyondTheCountIsRefused) {
    Runner r;
    r.data().set_reset_source = SetResetSource::timer;
    r.start();
    r.runner.set_time(1e18);  // 1e18 set/reset periods of 1 s
    EXPECT_THROW(r.runner.event_iteration(), fmu::Error);
}

}  // namespace
}  // namespace magnetometer
