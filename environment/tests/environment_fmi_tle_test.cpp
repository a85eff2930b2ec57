// The TLE parameters through the FMI 2.0 C API of environment.fmu's own code (the runtime's objects linked
// with the block, as the .fmu is): a set with a wrong checksum is refused at exit of initialization with
// fmi2Error and a logged message naming the parameter, line, column and reason; a good one runs.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdarg>
#include <string>
#include <vector>

#include "environment/environment_block.hpp"
#include "fmi2/fmi2Functions.h"
#include "fmu/description.hpp"

namespace {

struct Log {
    std::vector<std::string> errors;
};

void logger(fmi2ComponentEnvironment env, fmi2String, fmi2Status status, fmi2String, fmi2String message, ...) {
    va_list args;
    va_start(args, message);
    const char* text = va_arg(args, const char*);  // the runtime passes the text through "%s"
    va_end(args);
    if (status >= fmi2Discard) static_cast<Log*>(env)->errors.emplace_back(text);
}

fmi2ValueReference vr(const char* name) {
    return environment::EnvironmentBlock::static_table().by_name(name).value_reference;
}

class EnvironmentFmiTle : public ::testing::Test {
protected:
    Log log;
    fmi2CallbackFunctions callbacks{logger, nullptr, nullptr, nullptr, &log};
    std::string guid = fmu::description_guid(*fmu::make_model());
    fmi2Component c = nullptr;

    void SetUp() override {
        c = fmi2Instantiate("env", fmi2CoSimulation, guid.c_str(), nullptr, &callbacks, fmi2False, fmi2False);
        ASSERT_NE(c, nullptr);
        ASSERT_EQ(fmi2SetupExperiment(c, fmi2False, 0.0, 0.0, fmi2False, 0.0), fmi2OK);
        ASSERT_EQ(fmi2EnterInitializationMode(c), fmi2OK);
        const fmi2ValueReference model = vr("orbit_model");
        const fmi2Integer tle = static_cast<fmi2Integer>(environment::OrbitModel::tle);
        ASSERT_EQ(fmi2SetInteger(c, &model, 1, &tle), fmi2OK);
    }
    void TearDown() override { fmi2FreeInstance(c); }

    // The bundled set's line 1 with the given line 2 (the block's default set is numbers, its lines empty).
    fmi2Status set_line2(const char* text) {
        const fmi2ValueReference refs[2] = {vr("tle_line1"), vr("tle_line2")};
        const fmi2String lines[2] = {"1 90001U          26079.00000000  .00002000  00000-0  15000-3 0  9995", text};
        return fmi2SetString(c, refs, 2, lines);
    }
};

TEST_F(EnvironmentFmiTle, WrongChecksumIsRefusedAtExitOfInitialization) {
    // The bundled set's line 2 with its checksum 1 turned into 2.
    ASSERT_EQ(set_line2("2 90001  64.9000   0.0000 0012000  90.0000 270.0000 14.98524078  1002"), fmi2OK);
    EXPECT_EQ(fmi2ExitInitializationMode(c), fmi2Error);
    ASSERT_FALSE(log.errors.empty());
    const std::string& message = log.errors.back();
    for (const char* part : {"tle_line1, tle_line2", "TLE line 2, column 69", "checksum 2", "modulo-10 sum 1"}) {
        EXPECT_NE(message.find(part), std::string::npos) << message;
    }
}

TEST_F(EnvironmentFmiTle, GoodSetRunsAndGivesAPositionAtTheOrbitsRadius) {
    ASSERT_EQ(set_line2("2 90001  64.9000   0.0000 0012000  90.0000 270.0000 14.98524078  1001"), fmi2OK);
    ASSERT_EQ(fmi2ExitInitializationMode(c), fmi2OK) << (log.errors.empty() ? "" : log.errors.back());
    ASSERT_EQ(fmi2DoStep(c, 0.0, 1.0, fmi2True), fmi2OK);
    const fmi2ValueReference refs[3] = {vr("r_eci[1]"), vr("r_eci[2]"), vr("r_eci[3]")};
    fmi2Real r[3];
    ASSERT_EQ(fmi2GetReal(c, refs, 3, r), fmi2OK);
    const double radius = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    EXPECT_NEAR(radius, 6378137.0 + 570e3, 20e3);  // 570 km mean altitude, e = 0.0012 and J2's terms
}

}  // namespace
