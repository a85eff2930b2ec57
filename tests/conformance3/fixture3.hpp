// The per-archive fixture of the FMI 3.0 suite: each TEST_P gets one FMI 3.0 archive unpacked and
// loaded, and the same block's FMI 2.0 archive (the reference the 3.0 layer must agree with: it has
// its own suite, tests/conformance).
#pragma once

#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <memory>

#include "fmi_loader/fmu.hpp"
#include "fmi_session.hpp"
#include "fmu3_under_test.hpp"

namespace conformance3 {

class Fmu3Test : public ::testing::TestWithParam<std::filesystem::path> {
protected:
    void SetUp() override {
        try {
            fmu3_ = std::make_unique<Fmu3>(GetParam());
            fmu2_ = std::make_unique<fmi_loader::Fmu>(fmi2_archive_of(GetParam()));
        } catch (const std::exception& e) {
            FAIL() << "cannot open " << GetParam() << " or its FMI 2.0 archive: " << e.what();
        }
    }
    Fmu3& fmu3() { return *fmu3_; }
    const Description3& md() { return fmu3_->md(); }
    fmi_loader::Fmu& fmu2() { return *fmu2_; }

    std::unique_ptr<Fmu3> fmu3_;
    std::unique_ptr<fmi_loader::Fmu> fmu2_;
};

inline std::string param_name(const ::testing::TestParamInfo<std::filesystem::path>& info) {
    std::string name = info.param.stem().string();
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
}

// The window the runs cover: the default experiment, at most one second of it.
inline double run_stop(const Description3& md) {
    return std::min(md.stop_time, md.start_time + 1.0);
}

}  // namespace conformance3

#define CONFORMANCE3_SUITE(Name)                     \
    class Name : public ::conformance3::Fmu3Test {}; \
    INSTANTIATE_TEST_SUITE_P(Fmus3, Name, ::testing::ValuesIn(::conformance3::fmu3_files()), ::conformance3::param_name)
