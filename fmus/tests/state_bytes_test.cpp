// fmi2DeSerializeFMUstate against payloads nobody serialized (issue 14 case 8): a corrupted byte
// fails the checksum; an edited payload with a recomputed checksum fails the block's invariants
// (NaN, a value beyond its declared range, a bool byte that is not 0/1, an unterminated string, a
// string that is not one of its allowed values). Each is fmi2Error with a message, never accepted.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdarg>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "fmi2/fmi2Functions.h"
#include "fmu/description.hpp"
#include "test_blocks.hpp"

namespace {

std::string last_message;
void capture(fmi2ComponentEnvironment, fmi2String, fmi2Status status, fmi2String, fmi2String message, ...) {
    va_list args;
    va_start(args, message);
    if (status >= fmi2Error) last_message = va_arg(args, const char*);
    va_end(args);
}

// The layout (fmus/src/instance.cpp): magic 8, data size 8, time 8, last time 8, terminate 1, GUID 40,
// then the block's bytes, then FNV-1a 64 of all that. FNV-1a written again here from its definition
// (offset basis 0xcbf29ce484222325, prime 0x100000001b3) so that the test can forge a valid checksum.
constexpr std::size_t header = 8 + 8 + 8 + 8 + 1 + 40;
std::uint64_t fnv1a(const std::vector<fmi2Byte>& b, std::size_t n) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (std::size_t i = 0; i < n; ++i) {
        h ^= static_cast<unsigned char>(b[i]);
        h *= 0x100000001b3ull;
    }
    return h;
}
void reseal(std::vector<fmi2Byte>& b) {
    const std::uint64_t h = fnv1a(b, b.size() - 8);
    std::memcpy(b.data() + b.size() - 8, &h, 8);
}
std::size_t offset_of(const char* name) {
    return header + fmu_test::Ball::static_table().by_name(name).offset;
}

class StateBytes : public ::testing::Test {
protected:
    fmi2CallbackFunctions callbacks{capture, nullptr, nullptr, nullptr, nullptr};
    fmi2Component c = nullptr;
    std::vector<fmi2Byte> bytes;

    void SetUp() override {
        const std::string guid = fmu::description_guid(*fmu::make_model());
        c = fmi2Instantiate("ball", fmi2CoSimulation, guid.c_str(), nullptr, &callbacks, fmi2False, fmi2False);
        ASSERT_NE(c, nullptr);
        ASSERT_EQ(fmi2EnterInitializationMode(c), fmi2OK);
        ASSERT_EQ(fmi2ExitInitializationMode(c), fmi2OK);
        fmi2FMUstate state = nullptr;
        ASSERT_EQ(fmi2GetFMUstate(c, &state), fmi2OK);
        size_t size = 0;
        ASSERT_EQ(fmi2SerializedFMUstateSize(c, state, &size), fmi2OK);
        bytes.resize(size);
        ASSERT_EQ(fmi2SerializeFMUstate(c, state, bytes.data(), size), fmi2OK);
        fmi2FreeFMUstate(c, &state);
    }
    void TearDown() override { fmi2FreeInstance(c); }

    // Refused, with a message containing `says`.
    void expect_refused(const std::vector<fmi2Byte>& b, const std::string& says) {
        last_message.clear();
        fmi2FMUstate out = nullptr;
        EXPECT_EQ(fmi2DeSerializeFMUstate(c, b.data(), b.size(), &out), fmi2Error);
        EXPECT_NE(last_message.find(says), std::string::npos) << last_message;
        if (out) fmi2FreeFMUstate(c, &out);
    }
    template <class T>
    std::vector<fmi2Byte> edited(const char* name, const T& value) {
        auto b = bytes;
        std::memcpy(b.data() + offset_of(name), &value, sizeof value);
        reseal(b);
        return b;
    }
};

TEST_F(StateBytes, UntouchedStateIsAccepted) {
    fmi2FMUstate out = nullptr;
    EXPECT_EQ(fmi2DeSerializeFMUstate(c, bytes.data(), bytes.size(), &out), fmi2OK) << last_message;
    fmi2FreeFMUstate(c, &out);
}

TEST_F(StateBytes, AnyChangedByteFailsTheChecksum) {
    auto b = bytes;
    b[offset_of("h")] ^= 0x40;
    expect_refused(b, "checksum");
}

TEST_F(StateBytes, NaNIsRefused) {
    expect_refused(edited("h", std::numeric_limits<double>::quiet_NaN()), "h is NaN");
}

TEST_F(StateBytes, ValueBeyondItsDeclaredRangeIsRefused) {
    expect_refused(edited("e", 2.26e6), "e = ");
    expect_refused(edited("max_bounces", std::int32_t{0}), "max_bounces");
}

TEST_F(StateBytes, BoolByteOtherThanZeroOrOneIsRefused) {
    expect_refused(edited("enabled", static_cast<unsigned char>(7)), "enabled is not a boolean");
}

TEST_F(StateBytes, StringsMustBeTerminated) {
    char unterminated[16];
    std::memset(unterminated, 'x', sizeof unterminated);
    expect_refused(edited("label", unterminated), "not terminated");
}

TEST_F(StateBytes, ChoiceMustBeOneOfItsItems) {
    expect_refused(edited("material", std::int32_t{3}), "material = 3 is not an item of Material");
}

}  // namespace
