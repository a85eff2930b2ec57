// Writes documentation/index.html of a block's .fmu from the same variable table: the block's own
// text, then every parameter, input, output and state with unit, start, range and description.
#pragma once

#include <string>

#include "fmu/model.hpp"

namespace fmu {

std::string documentation_html(const Model& model);

}  // namespace fmu
