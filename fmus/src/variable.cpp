// The standard's spelling of the enumerations, as they appear in modelDescription.xml.
#include "fmu/variable.hpp"

#include "fmi/vocabulary.hpp"

namespace fmu {

// The order of the enums in variable.hpp is the vocabulary's (fmi/vocabulary.hpp).
static_assert(fmi_vocabulary::spelling(fmi_vocabulary::causalities, Causality::independent) == "independent");
static_assert(fmi_vocabulary::spelling(fmi_vocabulary::variabilities, Variability::continuous) == "continuous");
static_assert(fmi_vocabulary::spelling(fmi_vocabulary::initials, Initial::calculated) == "calculated");
static_assert(fmi_vocabulary::spelling(fmi_vocabulary::types_fmi2, ValueType::Enumeration) == "Enumeration");

std::string_view to_string(ValueType v) {
    return fmi_vocabulary::spelling(fmi_vocabulary::types_fmi2, v);
}

std::string_view to_string(Causality c) {
    return fmi_vocabulary::spelling(fmi_vocabulary::causalities, c);
}

std::string_view to_string(Variability v) {
    return fmi_vocabulary::spelling(fmi_vocabulary::variabilities, v);
}

std::string_view to_string(Initial i) {
    return i == Initial::none ? std::string_view() : fmi_vocabulary::spelling(fmi_vocabulary::initials, i);
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
