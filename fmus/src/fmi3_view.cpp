#include "fmu/fmi3_view.hpp"

#include <string>

#include "fmu/errors.hpp"

namespace fmu {

namespace {

// What FMI 3.0 states once for all the elements of an array variable.
void require_uniform(const Variable& first, const Variable& element) {
    auto differs = [&](const char* what) {
        throw Error("FMI 3.0: the elements of " + first.base_name + " differ in their " + what + " (" + first.name +
                    " and " + element.name + "); an FMI 3.0 array states it once for all elements");
    };
    if (element.type != first.type) differs("type");
    if (element.unit != first.unit) differs("unit");
    if (element.description != first.description) differs("description");
    if (element.causality != first.causality) differs("causality");
    if (element.variability != first.variability) differs("variability");
    if (element.initial != first.initial) differs("initial");
    if (element.min != first.min) differs("minimum");
    if (element.max != first.max) differs("maximum");
    if (element.nominal != first.nominal) differs("nominal");
}

}  // namespace

Fmi3View::Fmi3View(const TableBase& table, std::size_t event_indicator_count)
    : event_indicator_count_(event_indicator_count) {
    const auto& vars = table.variables();
    owner_.resize(vars.size());
    element_references_.resize(vars.size());
    std::uint32_t highest = 0;
    for (std::size_t i = 0; i < vars.size(); ++i) {
        const Variable& v = vars[i];
        element_references_[i] = v.value_reference;
        highest = std::max(highest, v.value_reference);
        // An element continues the variable before it when it has the same declared name; the table
        // names a scalar by its declared name and an array's elements `name[i]`.
        const bool continues =
            !variables_.empty() && v.name != v.base_name && vars[variables_.back().first].base_name == v.base_name;
        if (continues) {
            require_uniform(vars[variables_.back().first], v);
            ++variables_.back().count;
        } else {
            variables_.push_back({i, 1, v.name != v.base_name, v.value_reference});
        }
        owner_[i] = variables_.size() - 1;
    }
    time_reference_ = vars.empty() ? 0 : highest + 1;
    by_reference_.assign(time_reference_, 0);
    for (std::size_t k = 0; k < variables_.size(); ++k) by_reference_[variables_[k].value_reference] = k + 1;
}

const Fmi3Variable* Fmi3View::find(std::uint32_t value_reference) const {
    if (value_reference >= by_reference_.size() || by_reference_[value_reference] == 0) return nullptr;
    return &variables_[by_reference_[value_reference] - 1];
}

}  // namespace fmu
