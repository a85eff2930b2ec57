// Writes a block's modelDescription.xml (FMI 2.0) from its variable table, with libxml2's writer so
// that every attribute is escaped correctly. Build-time only: the FMU binary never links libxml2.
#pragma once

#include <string>

#include "fmu/model.hpp"

namespace fmu {

std::string model_description_xml(const Model& model);

}  // namespace fmu
