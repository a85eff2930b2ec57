// The .fmu extractor: any bytes are refused or extracted within the limits, and nothing is left in
// the temporary directory afterwards. Limits are small here so that a run never writes much.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "fmi_loader/fmu_archive.hpp"
#include "fmi_loader/loader_error.hpp"

namespace {
namespace fs = std::filesystem;
const fs::path scratch = [] {
    std::string pattern = (fs::temp_directory_path() / "fuzz_archive_XXXXXX").string();
    if (!::mkdtemp(pattern.data())) std::abort();
    ::setenv("TMPDIR", pattern.c_str(), 1);  // the extraction directories go here, checked below
    return fs::path(pattern);
}();
const fs::path input = scratch.parent_path() / (scratch.filename().string() + ".fmu");
struct Remove {
    ~Remove() {
        fs::remove_all(scratch);
        fs::remove(input);
    }
} remove_at_exit;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    {
        std::ofstream out(input, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    }
    fmi_loader::Limits limits;
    limits.max_entries = 64;
    limits.max_entry_bytes = 1 << 20;
    limits.max_total_bytes = 4 << 20;
    limits.ratio_min_bytes = 64 << 10;
    try {
        fmi_loader::FmuArchive archive(input, limits);
        for (const auto& entry : fs::recursive_directory_iterator(archive.directory()))
            if (entry.is_symlink()) std::abort();  // nothing may link out of the extraction directory
    } catch (const fmi_loader::LoaderError&) {}
    if (!fs::is_empty(scratch)) std::abort();  // an extraction directory was left behind
    return 0;
}
