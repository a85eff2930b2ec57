// FMUs imported once per process: a campaign's runs, and every system a process loads, share the
// unpacked archive, the parsed description and the loaded binary of each FMU file instead of unpacking
// it again for each run. An entry is the file's canonical path with its size and modification time, so
// an FMU rebuilt while the process runs is imported again. An FMU that may be instantiated only once
// per process is never shared: each call imports it anew. The unpacked folders stay until the process
// ends (removed with it, or by the signal thread: interrupt.hpp).
#pragma once

#include <filesystem>
#include <memory>

#include "fmi_loader/fmu.hpp"

namespace cosim {

// The FMU imported from `file` (within `limits` when it is unpacked now). Thread-safe.
std::shared_ptr<fmi_loader::Fmu> import_fmu(const std::filesystem::path& file, const fmi_loader::Limits& limits = {});

}  // namespace cosim
