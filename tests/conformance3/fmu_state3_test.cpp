// FMU state of the FMI 3.0 archives: a state taken, kept in memory or serialized to bytes and read
// back, brings the instance back so that the same steps give the same outputs, bit for bit.
#include <cstring>

#include "fixture3.hpp"

namespace {

using conformance3::Instance3;

CONFORMANCE3_SUITE(Conformance3FmuState);

std::vector<double> steps(Instance3& inst, double t, int n) {
    const double h = inst.md().step_size;
    for (int k = 0; k < n; ++k) {
        fmi3Boolean event = false, terminate = false, early = false;
        double last = 0.0;
        EXPECT_EQ(inst.f().do_step(inst.c(), t + k * h, h, false, &event, &terminate, &early, &last), fmi3OK)
            << inst.log().dump();
    }
    return inst.outputs();
}

TEST_P(Conformance3FmuState, RoundTripRepeatsTheSteps) {
    Instance3 inst(fmu3(), Instance3::Kind::co_simulation);
    ASSERT_EQ(inst.initialize(), fmi3OK);
    const double h = md().step_size, t0 = md().start_time;
    steps(inst, t0, 5);
    fmi3FMUState state = nullptr;
    ASSERT_EQ(inst.f().get_fmu_state(inst.c(), &state), fmi3OK);
    const auto first = steps(inst, t0 + 5 * h, 10);

    ASSERT_EQ(inst.f().set_fmu_state(inst.c(), state), fmi3OK);
    const auto again = steps(inst, t0 + 5 * h, 10);
    ASSERT_EQ(first.size(), again.size());
    EXPECT_EQ(std::memcmp(first.data(), again.data(), first.size() * sizeof(double)), 0);

    size_t size = 0;
    ASSERT_EQ(inst.f().serialized_size(inst.c(), state, &size), fmi3OK);
    std::vector<fmi3Byte> bytes(size);
    ASSERT_EQ(inst.f().serialize(inst.c(), state, bytes.data(), size), fmi3OK);
    fmi3FMUState restored = nullptr;
    ASSERT_EQ(inst.f().deserialize(inst.c(), bytes.data(), size, &restored), fmi3OK) << inst.log().dump();
    ASSERT_EQ(inst.f().set_fmu_state(inst.c(), restored), fmi3OK);
    const auto third = steps(inst, t0 + 5 * h, 10);
    EXPECT_EQ(std::memcmp(first.data(), third.data(), first.size() * sizeof(double)), 0);

    bytes[bytes.size() / 2] ^= 0x5a;  // a corrupted state is refused, not restored
    fmi3FMUState bad = nullptr;
    EXPECT_EQ(inst.f().deserialize(inst.c(), bytes.data(), size, &bad), fmi3Error);
    EXPECT_EQ(inst.f().free_fmu_state(inst.c(), &restored), fmi3OK);
    EXPECT_EQ(inst.f().free_fmu_state(inst.c(), &state), fmi3OK);
}

}  // namespace
