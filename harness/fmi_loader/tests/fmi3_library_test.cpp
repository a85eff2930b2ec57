// Fmi3Library: resolution of the FMI 3.0 names and the report of missing ones, against two fixture
// shared objects built from fmi3_symbol_fixture.c (common + Co-Simulation; one lacking two names).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "fmi_loader/fmi3_library.hpp"
#include "fmi_loader/loader_error.hpp"

using fmi_loader::Fmi3Library;
using fmi_loader::LoaderErrc;
using fmi_loader::LoaderError;

namespace {
bool contains(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}
}  // namespace

TEST(LoaderLibrary3, ResolvesCoSimulationAndLeavesOptionalNamesNull) {
    Fmi3Library lib(FIXTURE3_COMPLETE, false, true);
    ASSERT_NE(lib->fmi3GetVersion, nullptr);
    EXPECT_STREQ(lib->fmi3GetVersion(), "3.0");
    EXPECT_NE(lib->fmi3DoStep, nullptr);
    EXPECT_NE(lib->fmi3GetFMUState, nullptr);
    EXPECT_EQ(lib->fmi3GetClock, nullptr);  // optional: the fixture has no clocks
    EXPECT_EQ(lib->fmi3SetTime, nullptr);   // Model Exchange, not asked for
    EXPECT_TRUE(contains(lib.missing_symbols(), "fmi3GetClock"));
    EXPECT_TRUE(contains(lib.missing_symbols(), "fmi3GetContinuousStateDerivatives"));
}

TEST(LoaderLibrary3, RequiredModelExchangeNamesMissingAreAllReported) {
    try {
        Fmi3Library lib(FIXTURE3_COMPLETE, true, true);
        FAIL() << "loaded without the Model Exchange functions";
    } catch (const LoaderError& e) {
        EXPECT_EQ(e.code(), LoaderErrc::missing_symbol);
        const std::string what = e.what();
        for (const char* name :
             {"fmi3InstantiateModelExchange", "fmi3EnterContinuousTimeMode", "fmi3CompletedIntegratorStep",
              "fmi3SetTime", "fmi3SetContinuousStates", "fmi3GetContinuousStateDerivatives", "fmi3GetEventIndicators",
              "fmi3GetContinuousStates", "fmi3GetNominalsOfContinuousStates"})
            EXPECT_NE(what.find(name), std::string::npos) << name << " not named in: " << what;
        EXPECT_EQ(what.find("fmi3GetClock"), std::string::npos) << "an optional name reported: " << what;
    }
}

TEST(LoaderLibrary3, MissingCommonNamesAreReported) {
    try {
        Fmi3Library lib(FIXTURE3_PARTIAL, false, true);
        FAIL() << "loaded without fmi3Reset and fmi3GetBinary";
    } catch (const LoaderError& e) {
        EXPECT_EQ(e.code(), LoaderErrc::missing_symbol);
        const std::string what = e.what();
        EXPECT_NE(what.find("fmi3Reset"), std::string::npos) << what;
        EXPECT_NE(what.find("fmi3GetBinary"), std::string::npos) << what;
        EXPECT_EQ(what.find("fmi3DoStep"), std::string::npos) << what;
    }
    EXPECT_EQ(Fmi3Library::binary_path("/x", "m"), std::filesystem::path("/x/binaries/x86_64-linux/m.so"));
}
