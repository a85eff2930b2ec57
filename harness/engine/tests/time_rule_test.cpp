// The reached-time rule (time_rule/time_rule.hpp) that the master, the runtime and the blocks' cores share:
// its values by hand, and that the runtime's name for it is the same function (a second copy could drift,
// and a master and a block that disagree step past a time event or take it twice).
#include <gtest/gtest.h>

#include "fmu/model.hpp"
#include "time_rule/time_rule.hpp"

namespace {

TEST(CosimTimeRule, OneRuleForTheMasterAndTheBlocks) {
    // fmu::reached names the ground floor's rule; no copy of its own.
    EXPECT_EQ(&fmu::reached, &time_rule::reached);
    static_assert(time_rule::reached(1.0 - 5e-13, 1.0));  // usable in constant expressions (cores' tables)
}

TEST(CosimTimeRule, WithinOnePartInATrillionByHand) {
    using time_rule::reached;
    // Absolute 1e-12 s below 1 s: within it is reached, outside it is not.
    EXPECT_TRUE(reached(1.0 - 5e-13, 1.0));
    EXPECT_FALSE(reached(1.0 - 2e-12, 1.0));
    EXPECT_TRUE(reached(0.0 - 5e-13, 0.0));
    EXPECT_FALSE(reached(-2e-12, 0.0));
    EXPECT_TRUE(reached(-2.5 - 2e-12, -2.5));  // 1e-12 of 2.5 s is 2.5e-12 s
    EXPECT_FALSE(reached(-2.5 - 3e-12, -2.5));
    // Relative above 1 s: 1e-12 of 1e6 s is 1e-6 s.
    EXPECT_TRUE(reached(1e6 - 5e-7, 1e6));
    EXPECT_FALSE(reached(1e6 - 2e-6, 1e6));
    EXPECT_DOUBLE_EQ(time_rule::resolution(86400.0), 86400e-12);
    EXPECT_DOUBLE_EQ(time_rule::resolution(-0.5), 1e-12);
    // A time built as a sum of steps, as a host computes it: 0.1 s added ten times is 1 - 1.1e-16 s.
    double sum = 0.0;
    for (int k = 0; k < 10; ++k) sum += 0.1;
    ASSERT_LT(sum, 1.0);
    EXPECT_TRUE(reached(sum, 1.0));
    EXPECT_TRUE(reached(2.0, 1.0));
}

}  // namespace
