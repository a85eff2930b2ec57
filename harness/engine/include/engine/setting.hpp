// One value set on a variable before initialization, wherever it comes from: `cosim run --set
// comp.var=value`, `cosim simulate --set var=value`, a campaign's [set] table or draws, or an .ssd /
// .ssv parameter binding. Parsed once (parse_setting), typed once against the variable it names
// (typed_value), so every source takes the same path and meets the same checks.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "fmi2/fmi2TypesPlatform.h"
#include "fmi_loader/model_description.hpp"

namespace cosim {

struct Setting {
    std::string component;  // empty when the text named no component (cosim simulate, an .ssd binding)
    std::string variable;
    std::string value;     // as written
    std::string ssv_type;  // the binding's SSV type ("Real", "Integer", "Boolean", "String", "Enumeration"); empty: any
};

// "component.variable" at its first '.' (variable names may hold dots: "der(x.y)"); nullopt when there
// is no dot or either part is empty. The one reading of such a name: settings, --columns, campaign targets.
struct VariableName {
    std::string component, variable;
};
std::optional<VariableName> split_variable_name(std::string_view name);

// "component.variable=value" (with_component) or "variable=value"; the first '=' ends the name, the
// first '.' of the name ends the component (variable names may hold dots: "der(x.y)").
Setting parse_setting(std::string_view text, bool with_component);

// A setting's value as the variable's type: Real -> double, Integer and Enumeration -> fmi2Integer (an
// Enumeration from an item name or an item's number), Boolean -> bool, String -> std::string. Refuses
// a binding whose SSV type does not fit the variable (a String binding may name an Enumeration item, an
// Integer binding may give its number), naming `where`.
using TypedValue = std::variant<double, fmi2Integer, bool, std::string>;
TypedValue typed_value(const fmi_loader::ModelDescription& md, const fmi_loader::ScalarVariable& v, const Setting& s,
                       const std::string& where);

}  // namespace cosim
