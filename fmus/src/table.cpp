// Table bookkeeping that does not depend on the block's data type.
#include "fmu/table.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "fmu/units.hpp"

namespace fmu {

const Variable& TableBase::by_name(std::string_view name) const {
    return variables_[index_of(name)];
}

std::size_t TableBase::index_of(std::string_view name) const {
    for (std::size_t i = 0; i < variables_.size(); ++i)
        if (variables_[i].name == name) return i;
    throw Error("no variable named '" + std::string(name) + "'");
}

std::size_t TableBase::add(Variable v) {
    for (const auto& existing : variables_)
        if (existing.name == v.name) throw Error("variable '" + v.name + "' declared twice");
    v.value_reference = static_cast<std::uint32_t>(variables_.size());
    variables_.push_back(std::move(v));
    return variables_.size() - 1;
}

namespace {
// "sun_method" -> "SunMethod": the name of a choice's type definition.
std::string camel_case(std::string_view name) {
    std::string out;
    bool upper = true;
    for (char c : name) {
        if (c == '_') {
            upper = true;
            continue;
        }
        out += upper ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : c;
        upper = false;
    }
    return out;
}
}  // namespace

void TableBase::set_items(std::vector<EnumerationItem> items) {
    auto& v = variables_.back();
    if (items.empty()) throw Error("choice " + v.name + " has no items");
    for (std::size_t i = 0; i < items.size(); ++i)
        for (std::size_t k = 0; k < i; ++k)
            if (items[i].name == items[k].name || items[i].value == items[k].value)
                throw Error("choice " + v.name + ": items '" + items[k].name + "' and '" + items[i].name +
                            "' repeat a name or a value");
    v.items = std::move(items);
    v.declared_type = camel_case(v.base_name);
    for (const auto& other : variables_)
        if (&other != &v && other.declared_type == v.declared_type)
            throw Error("choices " + other.name + " and " + v.name + " would share the type name " + v.declared_type);
}

void TableBase::mark_state(std::size_t state, std::size_t derivative) {
    variables_[state].is_state_ = true;
    variables_[derivative].derivative_of = state;
    states_.push_back(state);
    derivatives_.push_back(derivative);
}

void TableBase::check_unit(std::string_view unit) const {
    if (!unit.empty() && !find_unit(unit)) throw Error("unit '" + std::string(unit) + "' is not defined in fmu/units");
}

TableBase::Handle& TableBase::Handle::min(double value) {
    for (auto i = first_; i < last_; ++i) table_.variables_[i].min = value;
    return *this;
}

TableBase::Handle& TableBase::Handle::max(double value) {
    for (auto i = first_; i < last_; ++i) table_.variables_[i].max = value;
    return *this;
}

TableBase::Handle& TableBase::Handle::nominal(double value) {
    if (!(value > 0.0) || !std::isfinite(value)) throw Error("nominal must be positive and finite");
    for (auto i = first_; i < last_; ++i) {
        table_.variables_[i].nominal = value;
        // A state's derivative gets the same nominal, so a host scaling by it sees like magnitudes.
        if (table_.variables_[i].is_state_)
            for (std::size_t k = 0; k < table_.states_.size(); ++k)
                if (table_.states_[k] == i) table_.variables_[table_.derivatives_[k]].nominal = value;
    }
    return *this;
}

TableBase::Handle& TableBase::Handle::plausible(double lo, double hi, std::string_view why) {
    if (!(lo <= hi)) throw Error("plausible: the low end must not exceed the high end");
    for (auto i = first_; i < last_; ++i) {
        auto& v = table_.variables_[i];
        if (v.causality != Causality::parameter) throw Error("plausible applies to parameters: " + v.name);
        v.plausible_min = lo;
        v.plausible_max = hi;
        v.plausible_note = std::string(why);
    }
    return *this;
}

TableBase::Handle& TableBase::Handle::applies_when(std::string_view variable,
                                                   std::initializer_list<std::string_view> values) {
    const Variable& selector = table_.by_name(variable);  // declared before: throws for an unknown name
    if (selector.type != ValueType::Enumeration && selector.type != ValueType::Boolean)
        throw Error("applies_when: " + selector.name + " is neither a choice nor a Boolean");
    for (const auto value : values) {
        const bool known = selector.type == ValueType::Boolean ? (value == "true" || value == "false")
                                                               : selector.item_named(value) != nullptr;
        if (!known) throw Error("applies_when: '" + std::string(value) + "' is no value of " + selector.name);
    }
    for (auto i = first_; i < last_; ++i) {
        auto& v = table_.variables_[i];
        if (v.causality != Causality::parameter) throw Error("applies_when applies to parameters: " + v.name);
        v.applies_when_variable = selector.name;
        v.applies_when_values.assign(values.begin(), values.end());
    }
    return *this;
}

TableBase::Handle& TableBase::Handle::tunable() {
    for (auto i = first_; i < last_; ++i) {
        auto& v = table_.variables_[i];
        if (v.causality != Causality::parameter) throw Error("only parameters can be tunable: " + v.name);
        v.variability = Variability::tunable;
    }
    return *this;
}

TableBase::Handle& TableBase::Handle::discrete() {
    for (auto i = first_; i < last_; ++i) table_.variables_[i].variability = Variability::discrete;
    return *this;
}

TableBase::Handle& TableBase::Handle::calculated_start() {
    for (auto i = first_; i < last_; ++i) {
        auto& v = table_.variables_[i];
        if (!v.is_state_) throw Error("calculated_start applies to states: " + v.name);
        v.initial = Initial::calculated;
    }
    return *this;
}

void TableBase::Handle::set_dependencies(std::size_t first, std::size_t last,
                                         std::initializer_list<std::string_view> names, bool elementwise) {
    const auto& vars = table_.variables_;
    for (auto i = first; i < last; ++i) {
        auto& deps = table_.variables_[i].dependencies;
        if (!deps) deps.emplace();
        for (auto name : names) {
            std::vector<std::size_t> matches;
            for (std::size_t k = 0; k < vars.size(); ++k)
                if (vars[k].name == name || vars[k].base_name == name) matches.push_back(k);
            if (matches.empty()) throw Error("dependency '" + std::string(name) + "' is not declared (yet)");
            if (elementwise) {
                if (matches.size() != last - first)
                    throw Error("elementwise dependency '" + std::string(name) + "' has a different length");
                matches = {matches[i - first]};
            }
            for (auto k : matches) {
                const auto& known = vars[k];
                if (known.causality != Causality::input && !known.is_state_)
                    throw Error("'" + known.name + "' is neither an input nor a state: not a valid dependency");
                if (std::find(deps->begin(), deps->end(), k) == deps->end()) deps->push_back(k);
            }
        }
        std::sort(deps->begin(), deps->end());
    }
}

TableBase::Handle& TableBase::Handle::depends_on(std::initializer_list<std::string_view> names) {
    set_dependencies(first_, last_, names, false);
    return *this;
}

TableBase::Handle& TableBase::Handle::depends_elementwise(std::initializer_list<std::string_view> names) {
    set_dependencies(first_, last_, names, true);
    return *this;
}

TableBase::Handle& TableBase::Handle::initial_depends_on(std::initializer_list<std::string_view> names) {
    const auto& vars = table_.variables_;
    for (auto i = first_; i < last_; ++i) {
        auto& v = table_.variables_[i];
        if (v.causality != Causality::output) throw Error("'" + v.name + "': initial dependencies are for outputs");
        auto& deps = v.initial_dependencies.emplace();
        for (auto name : names) {
            bool found = false;
            for (std::size_t k = 0; k < vars.size(); ++k) {
                if (vars[k].name != name && vars[k].base_name != name) continue;
                if (vars[k].causality != Causality::input && vars[k].causality != Causality::parameter)
                    throw Error("'" + vars[k].name +
                                "' is neither an input nor a parameter: not an initial dependency");
                deps.push_back(k);
                found = true;
            }
            if (!found) throw Error("initial dependency '" + std::string(name) + "' is not declared (yet)");
        }
        std::sort(deps.begin(), deps.end());
    }
    return *this;
}

// The derivatives of a state block were declared right after it, with the same length.
TableBase::Handle& TableBase::Handle::derivative_depends_on(std::initializer_list<std::string_view> names) {
    const auto n = last_ - first_;
    set_dependencies(last_, last_ + n, names, false);
    return *this;
}

TableBase::Handle& TableBase::Handle::derivative_depends_elementwise(std::initializer_list<std::string_view> names) {
    const auto n = last_ - first_;
    set_dependencies(last_, last_ + n, names, true);
    return *this;
}

}  // namespace fmu
