// Which FMUs the suite runs over: every *.fmu in one directory.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace conformance {

// $PVATT_FMU_DIR if set, else the build's FMU directory compiled in.
std::filesystem::path fmu_directory();
// The .fmu files of fmu_directory(), sorted; empty if the directory is missing.
std::vector<std::filesystem::path> fmu_files();
// gtest parameter name: the file stem with every non-alphanumeric character replaced by '_'.
std::string fmu_param_name(const ::testing::TestParamInfo<std::filesystem::path>& info);

}  // namespace conformance
