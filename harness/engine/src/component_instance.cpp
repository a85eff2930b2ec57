#include "engine/component_instance.hpp"

#include "engine/cosim_error.hpp"
#include "engine/name_hint.hpp"
#include "engine/value_text.hpp"

namespace cosim {

void ComponentInstance::apply(const Setting& s) {
    const auto* v = description().find_variable(s.variable);
    if (!v) throw CosimError(unknown_variable_message(description(), name(), s.variable));
    const fmi2ValueReference vr = v->value_reference;
    const TypedValue x = typed_value(description(), *v, s, name() + "." + s.variable);
    try {
        if (const auto* r = std::get_if<double>(&x)) set_real(vr, *r);
        if (const auto* i = std::get_if<fmi2Integer>(&x)) set_integer(vr, *i);
        if (const auto* b = std::get_if<bool>(&x)) set_boolean(vr, *b);
        if (const auto* t = std::get_if<std::string>(&x)) set_string(vr, *t);
    } catch (const CosimError& e) {
        // The FMU refused it: say the value given, unless its own message already does.
        const std::string what = e.what();
        if (what.find(s.value) != std::string::npos) throw;
        throw CosimError(what + " (given " + s.variable + " = " + s.value + ")");
    }
}

std::string ComponentInstance::get_as_text(const fmi_loader::ScalarVariable& v) {
    const fmi2ValueReference vr = v.value_reference;
    switch (v.type) {
        case fmi_loader::VariableType::real:
            return format_real(get_real(vr));
        case fmi_loader::VariableType::integer:
        case fmi_loader::VariableType::enumeration:
            return std::to_string(get_integer(vr));
        case fmi_loader::VariableType::boolean:
            return get_boolean(vr) ? "1" : "0";
        case fmi_loader::VariableType::string:
            return get_string(vr);
    }
    return {};
}

}  // namespace cosim
