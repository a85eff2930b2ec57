// Every declared parameter of the plant reaches its core (issue 25): SsrPlantBlock::parameters() copies the
// table's parameters into the core's Parameters by hand, and a parameter it forgot would be accepted,
// documented and ignored. Table-driven: each parameter of the block's variable table is changed through the
// table (fmu/testing/changed_value.hpp) and the core's parameters must differ from the unchanged block's.
#include <gtest/gtest.h>

#include "fmu/testing/block_driver.hpp"
#include "fmu/testing/changed_value.hpp"
#include "ssr_plant/ssr_plant_block.hpp"

namespace ssr_plant {
namespace {

TEST(PlantParameters, EveryDeclaredParameterReachesTheCore) {
    const SsrPlantBlock block;
    std::size_t checked = 0;
    for (const fmu::Variable& v : block.table().variables()) {
        if (v.causality != fmu::Causality::parameter) continue;
        fmu::testing::BlockDriver<SsrPlantBlock> driver;
        const Parameters before = driver.block().parameters();
        ASSERT_TRUE(fmu::testing::write_changed_value(driver.runner.model().bytes(), v)) << v.name;
        EXPECT_FALSE(driver.block().parameters() == before) << v.name << " changed, the core's parameters did not";
        ++checked;
    }
    EXPECT_GE(checked, 25u);  // the loop went over the table (29 parameters today)
}

}  // namespace
}  // namespace ssr_plant
