// Issue 40: a plant parameter the chosen mode ignores is said when it is set: the PWM modulator in averaged
// fidelity (no PWM edges), the Hall offset of a Hall channel that is stuck instead.
#include <gtest/gtest.h>

#include <span>
#include <string>
#include <vector>

#include "fmu/testing/setting_notes_of.hpp"
#include "ssr_plant/ssr_plant_block.hpp"

using ssr_plant::SsrPlantData;

// The notes the runtime would log for these values.
constexpr auto notes_for = fmu::testing::setting_notes_of<ssr_plant::SsrPlantBlock>;

TEST(SsrPlantSettingNotes, ModulatorInAveragedFidelityAndOffsetOfAStuckHall) {
    SsrPlantData d;
    d.fidelity = ssr_plant::Fidelity::averaged;
    EXPECT_TRUE(notes_for(d).empty());
    d.modulation = d.modulation == ssr_plant::Modulation::regular ? ssr_plant::Modulation::latched_natural
                                                                  : ssr_plant::Modulation::regular;
    ASSERT_EQ(notes_for(d).size(), 1u);
    EXPECT_NE(notes_for(d)[0].find("has no effect: it applies when fidelity is switching, and fidelity is averaged"),
              std::string::npos);
    d.fidelity = ssr_plant::Fidelity::switching;
    EXPECT_TRUE(notes_for(d).empty());

    d.fault_hall_mode = ssr_plant::HallFault::stuck;
    d.fault_hall_offset = 0.05;
    ASSERT_EQ(notes_for(d).size(), 1u);
    EXPECT_EQ(notes_for(d)[0],
              "fault_hall_offset = 0.05 A has no effect: it applies when fault_hall_mode is offset, and "
              "fault_hall_mode is stuck");
    d.fault_hall_mode = ssr_plant::HallFault::offset;
    EXPECT_TRUE(notes_for(d).empty());
}
