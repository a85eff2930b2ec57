// An .ssd connector names a scalar variable, or an FMI 3.0 array whole: "x" for x[1], x[2], ... (the
// elements fmi_loader::scalar_view made of it). A connection of two arrays connects them element by
// element.
#pragma once

#include <string>
#include <vector>

#include "fmi_loader/model_description.hpp"

namespace cosim {

// The variable named `name`, or else the elements of the array of that name in row-major order;
// empty when neither exists.
std::vector<const fmi_loader::ScalarVariable*> connector_elements(const fmi_loader::ModelDescription& md,
                                                                  const std::string& name);

}  // namespace cosim
