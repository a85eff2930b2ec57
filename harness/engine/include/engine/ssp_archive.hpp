// SSP archives (SSP 1.0, section 5: a zip with SystemStructure.ssd at its root and the FMUs it
// references inside, here under resources/): `cosim pack` writes one from an .ssd and the FMUs it
// names; read_system_description() opens one (system_description.hpp).
#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <vector>

#include "engine/system_description.hpp"

namespace cosim {

// Where a component's source FMU is: beside the .ssd, else in one of fmu_dirs (by its path, then by its
// file name). Throws CosimError listing every place looked at.
std::filesystem::path resolve_fmu(const SystemDescription& description, const std::string& source,
                                  const std::vector<std::filesystem::path>& fmu_dirs);
// The places resolve_fmu looks at, in order, absolute and each once; the first regular file among them.
std::vector<std::filesystem::path> fmu_candidates(const SystemDescription& description, const std::string& source,
                                                  const std::vector<std::filesystem::path>& fmu_dirs);
std::optional<std::filesystem::path> find_fmu(const SystemDescription& description, const std::string& source,
                                              const std::vector<std::filesystem::path>& fmu_dirs);
// Refuses a system (not an .ssp) any of whose FMUs is not found, naming each missing source once and
// every folder looked in, before anything is unpacked.
void check_fmus_found(const SystemDescription& description, const std::vector<std::filesystem::path>& fmu_dirs);

// Every file a run of the system reads: the .ssd and its FMUs and parameter files, or the .ssp alone.
std::vector<std::filesystem::path> system_inputs(const SystemDescription& description,
                                                 const std::vector<std::filesystem::path>& fmu_dirs);

struct PackOptions {
    std::vector<std::filesystem::path> fmu_dirs;
    // Fixed communication step written for OMSimulator's weakly coupled master (the org.openmodelica
    // annotation). Default: the system's smallest Co-Simulation communicationStep hint, else the smallest
    // DefaultExperiment stepSize of its FMUs.
    std::optional<double> oms_step;
};

// Packs `ssd` and every FMU its components name into the SSP archive `ssp`: resources/*.fmu (stored, an
// FMU being compressed already) and SystemStructure.ssd, the .ssd made to travel (docs in
// harness/systems/README.md, "SSP archives"):
//  - the system's own parameters (system_description.hpp) resolved into the bindings of the component
//    parameters they feed, and the system's connectors, bindings and feeding connections removed
//    (OMSimulator 2.1.3 connects a system's parameter connector only under a plain identifier name);
//  - each component's source rewritten to resources/<file name>;
//  - a binding of an Enumeration parameter by item name (ssv:String or ssv:Enumeration) written as
//    ssv:Integer with the item's value, which every SSP 1.0 importer reads;
//  - a String binding that repeats its variable's start value left out (it changes nothing; OMSimulator
//    2.1.3 counts every ssv:String binding as an error); one that changes a value is kept and named on `out`;
//  - the components' vendor annotations (execution hints, hardware bridges) moved to the system's
//    annotations with a component attribute (OMSimulator 2.1.3 refuses any annotation in a component);
//  - an org.openmodelica annotation first among the system's: OMSimulator reads the kind of system from
//    it, here a weakly coupled co-simulation (FixedStepMaster, oms-ma) at options.oms_step.
// Written to a temporary file beside `ssp` and renamed over it only when complete: a failure (a missing
// FMU, a full disk) leaves no partial archive. Reports what it wrote on `out`.
void pack_system(const std::filesystem::path& ssd, const std::filesystem::path& ssp, const PackOptions& options,
                 std::ostream& out);

}  // namespace cosim
