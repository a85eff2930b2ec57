// Static rules of an FMI 2.0 model description (FMI 2.0.4 section 2.2) that the loader does not
// enforce because a tool may still want to read a slightly broken file.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "fmi_loader/model_description.hpp"

namespace conformance {

// Every rule broken by `md`, one readable line each; empty when the description conforms.
std::vector<std::string> description_violations(const fmi_loader::ModelDescription& md);

// The structured-name grammar of section 2.2.9 (variableNamingConvention="structured").
bool is_structured_name(std::string_view name);

// Value references share a namespace per accessor: fmi2GetInteger serves Integer and Enumeration.
int accessor_class(fmi_loader::VariableType type);

}  // namespace conformance
