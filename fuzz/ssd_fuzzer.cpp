// The .ssd reader (the master's system files): any bytes give a SystemDescription or a CosimError.
// The reader takes a path (parameter files are found beside it), so the input goes through a file.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "cosim_error.hpp"
#include "system_description.hpp"

namespace {
const std::filesystem::path file =
    std::filesystem::temp_directory_path() / ("fuzz_ssd_" + std::to_string(::getpid()) + ".ssd");
struct Remove {
    ~Remove() { std::filesystem::remove(file); }
} remove_at_exit;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    {
        std::ofstream out(file, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    }
    try {
        (void)cosim::read_system_description(file);
    } catch (const cosim::CosimError&) {}
    return 0;
}
