// Writes a block's FMI 3.0 modelDescription.xml from its variable table (the FMI 2.0 one comes from
// the same table, description_xml.hpp): arrays with <Dimension>, the 3.0 type names, Enumerations as
// <EnumerationType>, the independent variable and the event indicators as FMI 3.0 wants them
// (fmu/fmi3_view.hpp). Build-time only.
#pragma once

#include <string>

#include "fmu/model.hpp"

namespace fmu {

std::string model_description3_xml(const Model& model);

}  // namespace fmu
