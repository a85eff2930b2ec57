// The estimator's board emulator against request times a host or a corrupted link may send (issue 14
// case 1): a well-formed frame at t >= 1e18 used to keep the board at 100 % CPU forever; it must be
// refused with a reason and the next frame answered.
#include <gtest/gtest.h>

#include <string>

#include "attitude_estimator/estimator_block.hpp"
#include "bridge/board_emulator.hpp"

namespace {

bridge::Frame request(std::uint32_t sequence, double time, std::size_t inputs) {
    bridge::Frame f;
    f.sequence = sequence;
    f.time = time;
    f.values.assign(inputs, 0.0);
    return f;
}

TEST(EstimatorBoard, FrameAtAHugeTimeIsRefusedAndTheNextAnswered) {
    bridge::BoardEmulator board(std::make_unique<attitude_estimator::EstimatorBlock>());
    const std::size_t n = board.input_count();
    EXPECT_EQ(board.answer(request(1, 0.0, n)).sequence, 1u);
    try {
        board.answer(request(2, 1e18, n));
        FAIL() << "a request at t = 1e18 s was answered";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("periods"), std::string::npos) << e.what();
    }
    EXPECT_EQ(board.answer(request(3, 0.05, n)).sequence, 3u);
}

// An Enumeration takes its items' values exactly (issue 24): 1.4 used to be rounded to item 1, 1e300
// converted out of range.
TEST(EstimatorBoard, EnumerationValuesThatAreNoExactItemAreRefused) {
    for (const char* setting : {"solver=1.4", "solver=1e300", "solver=-0.5"}) {
        try {
            bridge::BoardEmulator board(std::make_unique<attitude_estimator::EstimatorBlock>(), {setting});
            ADD_FAILURE() << setting << " was taken";
        } catch (const std::exception& e) {
            EXPECT_NE(std::string(e.what()).find("solver"), std::string::npos) << e.what();
        }
    }
    EXPECT_NO_THROW(
        bridge::BoardEmulator(std::make_unique<attitude_estimator::EstimatorBlock>(), {"solver=1"}));  // fast
}

}  // namespace
