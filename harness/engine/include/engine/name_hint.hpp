// What to say when a name is not found: the closest names that exist ("did you mean"), and for a name
// that is an array's base ("q0" where the FMU has q0[1] ... q0[4]) its elements. Used by every message
// about an unknown variable or component, so each says the same thing the same way.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "fmi_loader/model_description.hpp"

namespace cosim {

// Up to three of `candidates` within a small edit distance of `name` (1, or a third of its length for
// names of six characters and more; a swap of neighbours is one edit), those at the smallest distance,
// each once.
std::vector<std::string> closest_names(std::string_view name, const std::vector<std::string>& candidates);

// " (did you mean 'a' or 'b'?)", " (an array: q0[1] .. q0[4])", or "" when nothing is close.
std::string name_hint(std::string_view name, const std::vector<std::string>& candidates);

// "<owner>: no variable named '<name>'" with the hint over the FMU's variables (array elements offered
// by their base name as well: 'sun_bdy' suggests 'sun_body', whose elements are sun_body[1..3]).
std::string unknown_variable_message(const fmi_loader::ModelDescription& md, const std::string& owner,
                                     std::string_view name);

}  // namespace cosim
