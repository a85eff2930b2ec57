// The .ssp reader: any bytes as an SSP archive give a SystemDescription or a CosimError, and every
// component source of an accepted archive resolves inside it or is refused (an .ssp is a closed
// world: no fallback folder is given). The reader takes a path, so the input goes through a file.
#include <cstddef>
#include <cstdint>
#include <filesystem>

#include "engine/cosim_error.hpp"
#include "engine/ssp_archive.hpp"
#include "engine/system_description.hpp"
#include "input_file.hpp"

namespace {
const fuzz::InputFile input("fuzz_ssp", ".ssp");
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto& file = input.write(data, size);
    try {
        const cosim::SystemDescription description = cosim::read_system_description(file);
        const auto root = std::filesystem::canonical(description.archive->directory());
        for (const auto& c : description.components) {
            try {
                const auto fmu = std::filesystem::weakly_canonical(cosim::resolve_fmu(description, c.source, {}));
                // Anything resolved must lie inside the unpacked archive.
                if (fmu.string().rfind(root.string() + "/", 0) != 0) __builtin_trap();
            } catch (const cosim::CosimError&) {}
        }
    } catch (const cosim::CosimError&) {}
    return 0;
}
