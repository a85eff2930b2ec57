// Fmi2Library: resolution of the FMI 2.0 names and the report of missing ones, against two fixture
// shared objects built from symbol_table_fixture.c (one complete for CS, one lacking two names).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "fmi_loader/fmi2_library.hpp"
#include "fmi_loader/loader_error.hpp"

using fmi_loader::Fmi2Library;
using fmi_loader::LoaderErrc;
using fmi_loader::LoaderError;

namespace {
bool contains(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}
}  // namespace

TEST(LoaderLibrary, ResolvesCoSimulationSetAndListsAbsentModelExchangeNames) {
    Fmi2Library lib(FIXTURE_COMPLETE, false, true);
    ASSERT_NE(lib->fmi2GetVersion, nullptr);
    EXPECT_STREQ(lib->fmi2GetVersion(), "2.0");
    EXPECT_STREQ(lib->fmi2GetTypesPlatform(), "default");
    EXPECT_NE(lib->fmi2DoStep, nullptr);
    EXPECT_NE(lib->fmi2Reset, nullptr);
    EXPECT_EQ(lib->fmi2GetDerivatives, nullptr);
    // The ten Model Exchange functions of section 3.2.
    EXPECT_EQ(lib.missing_symbols().size(), 10u);
    EXPECT_TRUE(contains(lib.missing_symbols(), "fmi2NewDiscreteStates"));
}

TEST(LoaderLibrary, RequiredModelExchangeNamesMissingAreAllReported) {
    try {
        Fmi2Library lib(FIXTURE_COMPLETE, true, true);
        FAIL() << "loaded without the Model Exchange functions";
    } catch (const LoaderError& e) {
        EXPECT_EQ(e.code(), LoaderErrc::missing_symbol);
        const std::string what = e.what();
        for (const char* name :
             {"fmi2EnterEventMode", "fmi2NewDiscreteStates", "fmi2EnterContinuousTimeMode",
              "fmi2CompletedIntegratorStep", "fmi2SetTime", "fmi2SetContinuousStates", "fmi2GetDerivatives",
              "fmi2GetEventIndicators", "fmi2GetContinuousStates", "fmi2GetNominalsOfContinuousStates"})
            EXPECT_NE(what.find(name), std::string::npos) << name << " not named in: " << what;
        EXPECT_NE(what.find(FIXTURE_COMPLETE), std::string::npos) << what;
    }
}

TEST(LoaderLibrary, MissingCommonNamesAreReported) {
    try {
        Fmi2Library lib(FIXTURE_PARTIAL, false, true);
        FAIL() << "loaded without fmi2Reset and fmi2GetString";
    } catch (const LoaderError& e) {
        EXPECT_EQ(e.code(), LoaderErrc::missing_symbol);
        const std::string what = e.what();
        EXPECT_NE(what.find("fmi2Reset"), std::string::npos) << what;
        EXPECT_NE(what.find("fmi2GetString"), std::string::npos) << what;
        EXPECT_EQ(what.find("fmi2DoStep"), std::string::npos) << what;
    }
}

TEST(LoaderLibrary, UnloadableFileIsDlOpenError) {
    try {
        Fmi2Library lib("/nonexistent/model.so", false, true);
        FAIL();
    } catch (const LoaderError& e) {
        EXPECT_EQ(e.code(), LoaderErrc::dl_open);
        EXPECT_NE(std::string(e.what()).find("/nonexistent/model.so"), std::string::npos);
    }
    EXPECT_EQ(Fmi2Library::binary_path("/x", "m"), std::filesystem::path("/x/binaries/linux64/m.so"));
}
