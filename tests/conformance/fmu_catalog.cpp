#include "fmu_catalog.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>

namespace conformance {

std::filesystem::path fmu_directory() {
    if (const char* env = std::getenv("PVATT_FMU_DIR"); env && *env) return env;
    return PVATT_FMU_DIR_DEFAULT;
}

std::vector<std::filesystem::path> fmu_files() {
    std::vector<std::filesystem::path> out;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(fmu_directory(), ec))
        if (entry.is_regular_file() && entry.path().extension() == ".fmu") out.push_back(entry.path());
    std::sort(out.begin(), out.end());
    return out;
}

std::string fmu_param_name(const ::testing::TestParamInfo<std::filesystem::path>& info) {
    std::string name = info.param.stem().string();
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name.empty() ? "fmu" + std::to_string(info.index) : name;
}

}  // namespace conformance
