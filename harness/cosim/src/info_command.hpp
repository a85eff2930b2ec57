// `cosim info X.fmu`: the model's interface as a person reads it.
#pragma once

#include <filesystem>
#include <ostream>

namespace cosim {

void print_info(const std::filesystem::path& fmu_path, std::ostream& out);

}  // namespace cosim
