// FMU state (FMI 2.0.4 section 2.1.8): a run interrupted by get/serialize/free/deserialize/set must
// continue with the very bits of the uninterrupted run.
#include <cstring>

#include "conformance_fixture.hpp"

using namespace conformance;
using namespace fmi_loader;

CONFORMANCE_SUITE(ConformanceFmuState);

namespace {

using Trace = std::vector<std::vector<std::uint64_t>>;

}  // namespace

TEST_P(ConformanceFmuState, RestoredRunIsBitIdentical) {
    if (!md().co_simulation) GTEST_SKIP() << "needs CoSimulation";
    const auto& cs = *md().co_simulation;
    if (!cs.can_get_and_set_fmu_state) GTEST_SKIP() << "canGetAndSetFMUstate=false";
    const Experiment ex = experiment_of(md(), 2.0, 400);
    const std::size_t n = ex.steps(), half = n / 2;

    Instance a(fmu(), FmuKind::co_simulation, "original");
    ASSERT_TRUE(a.ok()) << a.log().dump();
    const auto& f = a.f();
    ASSERT_FMI_OK(a, a.initialize(ex.start, ex.stop));
    auto step = [&](Instance& inst, std::size_t i) {
        return inst.f().fmi2DoStep(inst.c(), ex.start + static_cast<double>(i) * ex.step, ex.step, fmi2True);
    };
    for (std::size_t i = 0; i < half; ++i) {
        ASSERT_FMI_OK(a, step(a, i));
    }

    fmi2FMUstate state = nullptr;
    ASSERT_FMI_OK(a, f.fmi2GetFMUstate(a.c(), &state));
    ASSERT_NE(state, nullptr);
    std::vector<fmi2Byte> bytes;
    if (cs.can_serialize_fmu_state) {
        std::size_t size = 0;
        ASSERT_FMI_OK(a, f.fmi2SerializedFMUstateSize(a.c(), state, &size));
        ASSERT_GT(size, 0u);
        bytes.resize(size);
        ASSERT_FMI_OK(a, f.fmi2SerializeFMUstate(a.c(), state, bytes.data(), size));
        ASSERT_FMI_OK(a, f.fmi2FreeFMUstate(a.c(), &state));
        EXPECT_EQ(state, nullptr) << "fmi2FreeFMUstate must set the pointer to NULL";
    }

    Trace uninterrupted;
    for (std::size_t i = half; i < n; ++i) {
        ASSERT_FMI_OK(a, step(a, i));
        uninterrupted.push_back(real_output_bits(a));
    }

    // Restore into a fresh instance from the bytes, or into the same one from the state handle.
    std::unique_ptr<Instance> fresh;
    Instance* target = &a;
    if (cs.can_serialize_fmu_state) {
        fresh = std::make_unique<Instance>(fmu(), FmuKind::co_simulation, "restored");
        target = fresh.get();
        ASSERT_TRUE(target->ok()) << target->log().dump();
        ASSERT_FMI_OK(*target, target->initialize(ex.start, ex.stop));
        ASSERT_FMI_OK(*target, f.fmi2DeSerializeFMUstate(target->c(), bytes.data(), bytes.size(), &state));
        ASSERT_NE(state, nullptr);
    }
    ASSERT_FMI_OK(*target, f.fmi2SetFMUstate(target->c(), state));
    ASSERT_FMI_OK(*target, f.fmi2FreeFMUstate(target->c(), &state));
    Trace resumed;
    for (std::size_t i = half; i < n; ++i) {
        ASSERT_FMI_OK(*target, step(*target, i));
        resumed.push_back(real_output_bits(*target));
    }
    EXPECT_EQ(resumed, uninterrupted) << "the restored run left the uninterrupted one";
    RecordProperty("serialized_bytes", static_cast<int>(bytes.size()));
}
