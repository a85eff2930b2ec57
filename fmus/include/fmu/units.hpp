// The units a block may name, with their SI base-unit exponents for <UnitDefinitions>. A block names a
// unit by its string; the table refuses a name that is not listed here, so every unit in a model
// description is defined.
#pragma once

#include <optional>
#include <string_view>

namespace fmu {

struct UnitDefinition {
    std::string_view name;
    int kg = 0, m = 0, s = 0, A = 0, K = 0, mol = 0, cd = 0, rad = 0;
    double factor = 1.0;
    double offset = 0.0;
};

std::optional<UnitDefinition> find_unit(std::string_view name);

}  // namespace fmu
