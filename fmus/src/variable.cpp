// The standard's spelling of the enumerations, as they appear in modelDescription.xml.
#include "fmu/variable.hpp"

namespace fmu {

std::string_view to_string(ValueType v) {
    switch (v) {
        case ValueType::Real:
            return "Real";
        case ValueType::Integer:
            return "Integer";
        case ValueType::Boolean:
            return "Boolean";
        case ValueType::String:
            return "String";
        case ValueType::Enumeration:
            return "Enumeration";
    }
    return "?";
}

std::string_view to_string(Causality c) {
    switch (c) {
        case Causality::parameter:
            return "parameter";
        case Causality::calculated_parameter:
            return "calculatedParameter";
        case Causality::input:
            return "input";
        case Causality::output:
            return "output";
        case Causality::local:
            return "local";
        case Causality::independent:
            return "independent";
    }
    return "?";
}

std::string_view to_string(Variability v) {
    switch (v) {
        case Variability::constant:
            return "constant";
        case Variability::fixed:
            return "fixed";
        case Variability::tunable:
            return "tunable";
        case Variability::discrete:
            return "discrete";
        case Variability::continuous:
            return "continuous";
    }
    return "?";
}

std::string_view to_string(Initial i) {
    switch (i) {
        case Initial::none:
            return "";
        case Initial::exact:
            return "exact";
        case Initial::approx:
            return "approx";
        case Initial::calculated:
            return "calculated";
    }
    return "?";
}

const EnumerationItem* Variable::item_named(std::string_view item) const {
    for (const auto& i : items)
        if (i.name == item) return &i;
    return nullptr;
}

const EnumerationItem* Variable::item_valued(std::int32_t value) const {
    for (const auto& i : items)
        if (i.value == value) return &i;
    return nullptr;
}

std::string Variable::item_names() const {
    std::string names;
    for (const auto& i : items) names += (names.empty() ? "" : ", ") + i.name;
    return names;
}

}  // namespace fmu
