// Times far from the start (issue 14 case 1): the set/reset and noise instants a host stepped over are
// counted at once, and a time beyond the count's limit is refused instead of looping.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "fmu/errors.hpp"
#include "fmu/model_runner.hpp"
#include "magnetometer/magnetometer_block.hpp"

namespace magnetometer {
namespace {

struct Runner {
    fmu::ModelRunner runner{std::make_unique<MagnetometerBlock>()};
    MagnetometerData& data() { return static_cast<MagnetometerBlock&>(runner.model()).data(); }
    void start() {
        runner.set_initializing(true);
        runner.ensure_evaluated();
        runner.set_initializing(false);
        runner.event_iteration();
    }
};

TEST(MagnetometerFarTime, SteppedOverPulsesAreCountedAtOnce) {
    Runner r;
    r.data().set_reset_period = 1.0;
    r.data().noise_sample_period = 0.01;
    r.start();
    ASSERT_TRUE(r.data().set_polarity);
    // Jump to 10.5 s: by hand, pulses at 1, 2, ..., 10 s were due (ten flips: set polarity again), the
    // next pulse is at 11 s; noise instants 0.01 ... 10.50 s were due, the next is at 10.51 s.
    r.runner.set_time(10.5);
    r.runner.event_iteration();
    EXPECT_TRUE(r.data().set_polarity);
    EXPECT_NEAR(r.data().next_set_reset, 11.0, 1e-9);
    EXPECT_NEAR(r.data().next_noise, 10.51, 1e-9);
    EXPECT_GT(r.runner.next_time_event(), 10.5);
    // 11.5 s: one more pulse (reset polarity).
    r.runner.set_time(11.5);
    r.runner.event_iteration();
    EXPECT_FALSE(r.data().set_polarity);
}

TEST(MagnetometerFarTime, TimeBeyondTheCountIsRefused) {
    Runner r;
    r.start();
    r.runner.set_time(1e18);  // 1e20 noise periods of 0.01 s
    EXPECT_THROW(r.runner.event_iteration(), fmu::Error);
}

}  // namespace
}  // namespace magnetometer
