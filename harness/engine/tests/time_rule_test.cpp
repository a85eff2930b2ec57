// The master's rule for a reached instant against the blocks' (fmu::reached): they must agree, or a
// master steps past a block's time event or hands it the same instant twice.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/time_rule.hpp"
#include "fmu/model.hpp"

namespace cosim {
namespace {

TEST(CosimTimeRule, TheMasterAndTheBlocksAgree) {
    for (const double event : {0.0, 1e-6, 0.05, 1.0, 3.7, 600.0, 86400.0, 1e9, -2.5}) {
        const double scale = std::max(1.0, std::abs(event));
        for (const double offset : {-3e-12, -1.01e-12, -0.99e-12, -1e-13, 0.0, 1e-13, 2e-12}) {
            const double t = event + offset * scale;
            EXPECT_EQ(reached(t, event), fmu::reached(t, event)) << "t = " << t << ", event at " << event;
        }
        // A time built as a sum of steps, as a host computes it: 0.05 s added twenty times is 1 s.
        double sum = 0.0;
        for (int k = 0; k < 20; ++k) sum += 0.05;
        EXPECT_EQ(reached(sum, 1.0), fmu::reached(sum, 1.0));
    }
    // By hand: within 1e-12 s of 1 s is 1 s; 2e-12 s before it is not.
    EXPECT_TRUE(reached(1.0 - 5e-13, 1.0));
    EXPECT_FALSE(reached(1.0 - 2e-12, 1.0));
    EXPECT_TRUE(reached(1e6 - 5e-7, 1e6));  // relative above 1 s
}

}  // namespace
}  // namespace cosim
