// panel_thermal.fmu's block through the runtime's own path (fmu::testing::BlockDriver).
#include <gtest/gtest.h>

#include <cmath>

#include "fmu/testing/block_driver.hpp"
#include "panel_thermal/panel_thermal_block.hpp"

namespace panel_thermal {
namespace {

using Driver = fmu::testing::BlockDriver<PanelThermalBlock>;

// The +x face squarely to the sun, nothing else exchanged (no infrared, no body): it settles at the
// radiative equilibrium (α S / (ε σ))^(1/4) = 399.71 K (hand calculation, face_thermal_test.cpp), its
// heat input α S = 1230.3 W/m²; the −x face, dark and alone, cools toward 0 K.
TEST(PanelThermalBlock, SunlitFaceSettlesAtItsEquilibriumThroughTheFmuPath) {
    Driver run;
    auto& d = run.data();
    d.sun_body = {2.0, 0.0, 0.0};  // any length: normalized inside
    d.earth_infrared = 0.0;
    d.inner_conductance = 0.0;
    run.start();
    EXPECT_DOUBLE_EQ(d.heat_input[0], 0.9 * 1367.0);
    EXPECT_EQ(d.heat_input[1], 0.0);
    EXPECT_EQ(d.face_temperature[0], 298.15);  // the start: ssr_plant's datasheet temperature
    run.advance_to(30000.0);
    EXPECT_NEAR(d.face_temperature[0], 399.71, 0.02);
    EXPECT_LT(d.face_temperature[1], 150.0);
}

TEST(PanelThermalBlock, TableHasSixStatesAndTheFaceTemperatures) {
    const auto& table = PanelThermalBlock::static_table();
    EXPECT_EQ(table.states().size(), 6u);
    EXPECT_EQ(table.by_name("face_temperature[6]").causality, fmu::Causality::output);
    EXPECT_EQ(table.by_name("t_face[1]").unit, "K");
}

}  // namespace
}  // namespace panel_thermal
