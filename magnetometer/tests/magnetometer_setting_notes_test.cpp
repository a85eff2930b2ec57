// Issue 40: set_reset_period is said to have no effect when it is set while the sensor's set/reset pulses
// come from elsewhere (set_reset_source input or none): only the timer uses it.
#include <gtest/gtest.h>

#include <span>
#include <string>
#include <vector>

#include "fmu/value_check.hpp"
#include "magnetometer/magnetometer_block.hpp"

using magnetometer::MagnetometerData;

namespace {

std::vector<std::string> notes_for(const MagnetometerData& d) {
    fmu::Table<MagnetometerData> t;
    magnetometer::MagnetometerBlock::declare(t);
    const MagnetometerData defaults;
    return fmu::setting_notes(t.variables(), std::as_bytes(std::span(&d, 1)), std::as_bytes(std::span(&defaults, 1)));
}

}  // namespace

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
