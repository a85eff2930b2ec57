// Issue 40: a parameter of the on-board computer that the chosen mode ignores is said when it is set (the
// runtime logs fmu::setting_notes as a warning when initialization ends): a cones parameter while another
// sun method runs, a filter_* parameter with the filter off, a calibration parameter with the calibration
// off, a Kelly table with the cosine response. Set where it applies, or left at its default, nothing is said.
#include <gtest/gtest.h>

#include <span>
#include <string>
#include <vector>

#include "attitude_estimator/estimator_block.hpp"
#include "fmu/testing/setting_notes_of.hpp"

using attitude_estimator::EstimatorData;

// The notes the runtime would log for these values.
constexpr auto notes_for = fmu::testing::setting_notes_of<attitude_estimator::EstimatorBlock>;

TEST(EstimatorSettingNotes, ParametersTheChosenModeIgnores) {
    EstimatorData d;
    ASSERT_EQ(d.sun_method, attitude_estimator::SunMethod::difference);
    ASSERT_EQ(d.filter, attitude_estimator::FilterKind::none);
    EXPECT_TRUE(notes_for(d).empty());

    d.cone_tolerance = 0.2;  // a cones parameter under the difference method
    ASSERT_EQ(notes_for(d).size(), 1u);
    EXPECT_EQ(notes_for(d)[0],
              "cone_tolerance = 0.2 has no effect: it applies when sun_method is cones, and sun_method is difference");
    d.sun_method = attitude_estimator::SunMethod::cones;  // now it applies
    EXPECT_TRUE(notes_for(d).empty());

    d.filter_watch_gate = 50.0;  // the filter is off
    ASSERT_EQ(notes_for(d).size(), 1u);
    EXPECT_NE(notes_for(d)[0].find("filter_watch_gate = 50 has no effect: it applies when filter is mekf"),
              std::string::npos);
    d.filter = attitude_estimator::FilterKind::mekf;
    EXPECT_TRUE(notes_for(d).empty());

    d.mag_calibration_every = 7.0;  // the calibration is off
    ASSERT_EQ(notes_for(d).size(), 1u);
    EXPECT_NE(notes_for(d)[0].find("mag_calibration_every = 7 has no effect: it applies when mag_calibration is true"),
              std::string::npos);
    d.mag_calibration = true;
    EXPECT_TRUE(notes_for(d).empty());

    d.kelly_value[2] = 0.6;  // the cosine response
    ASSERT_EQ(notes_for(d).size(), 1u);
    EXPECT_NE(notes_for(d)[0].find("has no effect: it applies when angular_response is kelly"), std::string::npos);
}
