// SSP archives (SSP 1.0, section 5: a zip with SystemStructure.ssd at its root and the FMUs it
// references inside, here under resources/): `cosim pack` writes one from an .ssd and the FMUs it
// names; read_system_description() opens one (system_description.hpp).
#pragma once

#include <filesystem>
#include <ostream>
#include <vector>

#include "system_description.hpp"

namespace cosim {

// Where a component's source FMU is: beside the .ssd, else in one of fmu_dirs (by its path, then by its
// file name). Throws CosimError listing every place looked at.
std::filesystem::path resolve_fmu(const SystemDescription& description, const std::string& source,
                                  const std::vector<std::filesystem::path>& fmu_dirs);

// Packs `ssd` and every FMU its components name into the SSP archive `ssp`: SystemStructure.ssd (the
// .ssd with each component's source rewritten to resources/<file name>, nothing else changed) and
// resources/*.fmu (stored, an FMU being compressed already). Written to a temporary file beside `ssp`
// and renamed over it only when complete: a failure (a missing FMU, a full disk) leaves no partial
// archive. Reports what it wrote on `out`.
void pack_system(const std::filesystem::path& ssd, const std::filesystem::path& ssp,
                 const std::vector<std::filesystem::path>& fmu_dirs, std::ostream& out);

}  // namespace cosim
