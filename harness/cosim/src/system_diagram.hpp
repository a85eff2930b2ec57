// `cosim info SYSTEM --diagram OUT`: the system's components and connections as a picture (issue 40),
// written as Graphviz text (OUT.dot) and drawn by Graphviz's dot (OUT.svg). One box per component (its
// name, FMU and how it runs) and one arrow per pair of connected components, labelled with the
// connectors it carries (an array's elements as one: sun_body[1..3]).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "engine/system_description.hpp"

namespace cosim {

// The Graphviz text of the system (names quoted and escaped: any name is safe).
std::string system_dot(const SystemDescription& system);

// Writes OUT.dot and, through `dot` run without a shell in OUT's folder, OUT.svg; returns the files
// written. Throws CosimError when a file cannot be written or dot fails (naming the Debian package).
std::vector<std::filesystem::path> write_system_diagram(const std::filesystem::path& system,
                                                        const std::filesystem::path& out);

}  // namespace cosim
