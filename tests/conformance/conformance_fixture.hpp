// The per-FMU test fixture: each TEST_P gets one freshly unpacked FMU.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>

#include "fmi_loader/fmu.hpp"
#include "fmi_loader/loader_error.hpp"
#include "fmi_session.hpp"
#include "fmu_catalog.hpp"

namespace conformance {

class FmuTest : public ::testing::TestWithParam<std::filesystem::path> {
protected:
    void SetUp() override {
        try {
            fmu_ = std::make_unique<fmi_loader::Fmu>(GetParam());
        } catch (const fmi_loader::LoaderError& e) {
            FAIL() << "cannot open " << GetParam() << ": " << e.what();
        }
    }
    fmi_loader::Fmu& fmu() { return *fmu_; }
    const fmi_loader::ModelDescription& md() { return fmu_->description(); }
    // Co-Simulation when declared (the kind most checks are about), else Model Exchange.
    fmi_loader::FmuKind preferred_kind() {
        return md().co_simulation ? fmi_loader::FmuKind::co_simulation : fmi_loader::FmuKind::model_exchange;
    }

    std::unique_ptr<fmi_loader::Fmu> fmu_;
};

}  // namespace conformance

// Declares a fixture `Name` and runs it over every FMU of the catalog.
#define CONFORMANCE_SUITE(Name)                    \
    class Name : public ::conformance::FmuTest {}; \
    INSTANTIATE_TEST_SUITE_P(Fmus, Name, ::testing::ValuesIn(::conformance::fmu_files()), ::conformance::fmu_param_name)

namespace conformance {
// fmi2OK or fmi2Warning passes; anything else fails with the call, the status and the FMU's log.
inline ::testing::AssertionResult fmi_ok(fmi2Status status, const char* call, Instance& inst) {
    if (status <= fmi2Warning) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << call << " returned " << status_name(status) << "\nFMU log:\n"
                                         << inst.log().dump();
}
}  // namespace conformance

// Asserts an FMI call returned fmi2OK or fmi2Warning; more context can be streamed in with <<.
#define ASSERT_FMI_OK(inst, call) ASSERT_TRUE(::conformance::fmi_ok((call), #call, (inst)))
