// The .ssd reader (the master's system files): any bytes give a SystemDescription or a CosimError.
// The reader takes a path (parameter files are found beside it), so the input goes through a file.
#include <cstddef>
#include <cstdint>
#include <filesystem>

#include "engine/cosim_error.hpp"
#include "engine/system_description.hpp"
#include "input_file.hpp"

namespace {
const fuzz::InputFile input("fuzz_ssd", ".ssd");
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto& file = input.write(data, size);
    try {
        (void)cosim::read_system_description(file);
    } catch (const cosim::CosimError&) {}
    return 0;
}
