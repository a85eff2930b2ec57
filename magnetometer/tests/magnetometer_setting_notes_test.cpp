// Issue 40: set_reset_period is said to have no effect when it is set while the sensor's set/reset pulses
// come from elsewhere (set_reset_source input or none): only the timer uses it.
#include <gtest/gtest.h>

#include <span>
#include <string>
#include <vector>

#include "fmu/testing/setting_notes_of.hpp"
#include "magnetometer/magnetometer_block.hpp"

using magnetometer::MagnetometerData;

// The notes the runtime would log for these values.
constexpr auto notes_for = fmu::testing::setting_notes_of<magnetometer::MagnetometerBlock>;

TEST(MagnetometerSettingNotes, SetResetPeriodWithoutTheTimer) {
    MagnetometerData d;
    ASSERT_EQ(d.set_reset_source, magnetometer::SetResetSource::input);
    EXPECT_TRUE(notes_for(d).empty());
    d.set_reset_period = 0.5;
    ASSERT_EQ(notes_for(d).size(), 1u);
    EXPECT_EQ(notes_for(d)[0],
              "set_reset_period = 0.5 s has no effect: it applies when set_reset_source is timer, and "
              "set_reset_source is input");
    d.set_reset_source = magnetometer::SetResetSource::timer;
    EXPECT_TRUE(notes_for(d).empty());
}
