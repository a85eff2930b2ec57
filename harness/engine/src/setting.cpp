#include "engine/setting.hpp"

#include "engine/cosim_error.hpp"
#include "engine/value_text.hpp"

namespace cosim {

std::optional<VariableName> split_variable_name(std::string_view name) {
    const auto dot = name.find('.');
    if (dot == std::string_view::npos || dot == 0 || dot + 1 == name.size()) return std::nullopt;
    return VariableName{std::string(name.substr(0, dot)), std::string(name.substr(dot + 1))};
}

Setting parse_setting(std::string_view text, bool with_component) {
    const auto eq = text.find('=');
    const std::string expected = with_component ? "component.variable=value" : "variable=value";
    if (eq == std::string_view::npos || eq == 0)
        throw CosimError("--set expects " + expected + ", got '" + std::string(text) + "'");
    Setting s;
    std::string_view name = text.substr(0, eq);
    s.value = std::string(text.substr(eq + 1));
    s.variable = std::string(name);
    if (with_component) {
        auto split = split_variable_name(name);
        if (!split) throw CosimError("--set expects " + expected + ", got '" + std::string(text) + "'");
        s.component = std::move(split->component);
        s.variable = std::move(split->variable);
    }
    return s;
}

namespace {

bool binding_fits(std::string_view ssv, fmi_loader::VariableType t) {
    using T = fmi_loader::VariableType;
    if (ssv.empty()) return true;
    if (ssv == "Real") return t == T::real;
    if (ssv == "Integer") return t == T::integer || t == T::enumeration;
    if (ssv == "Boolean") return t == T::boolean;
    if (ssv == "String") return t == T::string || t == T::enumeration;
    if (ssv == "Enumeration") return t == T::enumeration;
    return false;  // Binary, or a name SSP does not define
}

}  // namespace

TypedValue typed_value(const fmi_loader::ModelDescription& md, const fmi_loader::ScalarVariable& v, const Setting& s,
                       const std::string& where) {
    if (!binding_fits(s.ssv_type, v.type))
        throw CosimError(where + ": an ssv:" + s.ssv_type + " value cannot set a variable of type " +
                         std::string(fmi_loader::to_string(v.type)));
    switch (v.type) {
        case fmi_loader::VariableType::real:
            return parse_real(s.value, where);
        case fmi_loader::VariableType::integer:
            return static_cast<fmi2Integer>(parse_integer(s.value, where));
        case fmi_loader::VariableType::enumeration:
            return static_cast<fmi2Integer>(parse_enumeration(md, v, s.value, where));
        case fmi_loader::VariableType::boolean:
            return parse_boolean(s.value, where);
        case fmi_loader::VariableType::string:
            return s.value;
    }
    throw CosimError(where + ": unknown variable type");
}

}  // namespace cosim
