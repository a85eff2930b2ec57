// The estimator's board emulator against request times a host or a corrupted link may send (issue 14
// case 1): a well-formed frame at t >= 1e18 used to keep the board at 100 % CPU forever; it must be
// refused with a reason and the next frame answered.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "attitude_estimator/estimator_block.hpp"
#include "emulator/board_emulator.hpp"

namespace {

// Inputs at zero, or at their minimum where zero is below it (the board checks them as the FMU does).
bridge::Frame request(std::uint32_t sequence, double time) {
    bridge::Frame f;
    f.sequence = sequence;
    f.time = time;
    const attitude_estimator::EstimatorBlock block;
    std::vector<const fmu::Variable*> inputs;
    for (const auto& v : block.table().variables())
        if (v.causality == fmu::Causality::input) inputs.push_back(&v);
    std::sort(inputs.begin(), inputs.end(), [](auto* a, auto* b) { return a->value_reference < b->value_reference; });
    for (const auto* v : inputs) f.values.push_back(std::max(0.0, v->min.value_or(0.0)));
    return f;
}

TEST(EstimatorBoard, FrameAtAHugeTimeIsRefusedAndTheNextAnswered) {
    bridge::BoardEmulator board(std::make_unique<attitude_estimator::EstimatorBlock>());
    EXPECT_EQ(board.answer(request(1, 0.0)).sequence, 1u);
    try {
        board.answer(request(2, 1e18));
        FAIL() << "a request at t = 1e18 s was answered";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("periods"), std::string::npos) << e.what();
    }
    EXPECT_EQ(board.answer(request(3, 0.05)).sequence, 3u);
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

// The board's own settings pass the same checks as the FMU's setters (issue 25): a value below a
// parameter's declared minimum, a number with trailing text, a Boolean that is neither true nor false
// and a variable that is no parameter are refused, naming the variable (std::stod took the first two).
TEST(EstimatorBoard, SettingsPassTheRuntimesChecks) {
    for (const char* setting : {"min_field=-1", "min_field=1e-6x", "min_field=nan", "sample_period=0"}) {
        try {
            bridge::BoardEmulator board(std::make_unique<attitude_estimator::EstimatorBlock>(), {setting});
            ADD_FAILURE() << setting << " was taken";
        } catch (const std::exception& e) {
            const std::string name = std::string(setting).substr(0, std::string(setting).find('='));
            EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
        }
    }
    EXPECT_NO_THROW(bridge::BoardEmulator(std::make_unique<attitude_estimator::EstimatorBlock>(), {"min_field=2e-6"}));
    EXPECT_NO_THROW(bridge::BoardEmulator(std::make_unique<attitude_estimator::EstimatorBlock>(), {"solver=fast"}));
}

}  // namespace
