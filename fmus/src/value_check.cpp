#include "fmu/value_check.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <set>
#include <string>

#include "fmu/description.hpp"
#include "fmu/errors.hpp"
#include "fmu/value_access.hpp"

namespace fmu {

namespace {

// A value with its unit, as a person reads it: "300 K"; no unit for a dimensionless one ("" or "1").
std::string with_unit(const Variable& v, double x) {
    const std::string number = format_real(x);
    return v.unit.empty() || v.unit == "1" ? number : number + " " + v.unit;
}

void check_range(const Variable& v, double x) {
    if (v.min && x < *v.min)
        throw Error(v.name + " = " + with_unit(v, x) + " is below its minimum " + with_unit(v, *v.min));
    if (v.max && x > *v.max)
        throw Error(v.name + " = " + with_unit(v, x) + " is above its maximum " + with_unit(v, *v.max));
}

template <class T>
bool parse_whole(std::string_view text, T& x) {
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
    return !text.empty() && ec == std::errc() && end == text.data() + text.size();
}

// A variable's value as a person would type it: a number with its unit, an item's name, true or false.
std::string value_text(const Variable& v, std::span<const std::byte> data) {
    switch (v.type) {
        case ValueType::Real:
            return with_unit(v, read_real(data, v));
        case ValueType::Integer:
            return with_unit(v, read_integer(data, v));
        case ValueType::Enumeration: {
            const auto* item = v.item_valued(read_integer(data, v));
            return item ? item->name : std::to_string(read_integer(data, v));
        }
        case ValueType::Boolean:
            return read_boolean(data, v) ? "true" : "false";
        case ValueType::String:
            return "'" + std::string(read_string(data, v)) + "'";
    }
    return {};
}

bool same_value(const Variable& v, std::span<const std::byte> a, std::span<const std::byte> b) {
    switch (v.type) {
        case ValueType::Real:
            return read_real(a, v) == read_real(b, v);
        case ValueType::Integer:
        case ValueType::Enumeration:
            return read_integer(a, v) == read_integer(b, v);
        case ValueType::Boolean:
            return read_boolean(a, v) == read_boolean(b, v);
        case ValueType::String:
            return read_string(a, v) == read_string(b, v);
    }
    return true;
}

}  // namespace

std::vector<std::string> setting_notes(const std::vector<Variable>& variables, std::span<const std::byte> values,
                                       std::span<const std::byte> defaults) {
    std::vector<std::string> notes;
    std::set<std::string> said;  // one note per declared name (an array's elements share it)
    for (const auto& v : variables) {
        if (v.causality != Causality::parameter || said.contains(v.base_name)) continue;
        if (!v.applies_when_variable.empty() && !same_value(v, values, defaults)) {
            const auto selector = std::find_if(variables.begin(), variables.end(),
                                               [&](const Variable& s) { return s.name == v.applies_when_variable; });
            if (selector != variables.end()) {
                const std::string now = value_text(*selector, values);
                if (std::find(v.applies_when_values.begin(), v.applies_when_values.end(), now) ==
                    v.applies_when_values.end()) {
                    std::string when;
                    for (const auto& w : v.applies_when_values) when += (when.empty() ? "" : " or ") + w;
                    notes.push_back(v.name + " = " + value_text(v, values) + " has no effect: it applies when " +
                                    selector->name + " is " + when + ", and " + selector->name + " is " + now);
                    said.insert(v.base_name);
                    continue;
                }
            }
        }
        if ((v.plausible_min || v.plausible_max) && (v.type == ValueType::Real || v.type == ValueType::Integer)) {
            const double x = v.type == ValueType::Real ? read_real(values, v) : read_integer(values, v);
            if ((v.plausible_min && x < *v.plausible_min) || (v.plausible_max && x > *v.plausible_max)) {
                notes.push_back(v.name + " = " + with_unit(v, x) + " is legal but unlikely (outside " +
                                with_unit(v, v.plausible_min.value_or(-INFINITY)) + " to " +
                                with_unit(v, v.plausible_max.value_or(INFINITY)) + "): " + v.plausible_note);
                said.insert(v.base_name);
            }
        }
    }
    return notes;
}

void check_real(const Variable& v, double x) {
    if (!std::isfinite(x)) throw Error(v.name + " cannot be set to " + format_real(x) + " (not finite)");
    check_range(v, x);
}

void check_integer(const Variable& v, std::int32_t x) {
    if (v.type == ValueType::Enumeration && !v.item_valued(x))
        throw Error(v.name + " = " + std::to_string(x) + " is not an item of " + v.declared_type + " (" +
                    v.item_names() + ")");
    check_range(v, x);
}

double checked_value_from_text(const Variable& v, std::string_view text) {
    const std::string given = v.name + ": '" + std::string(text) + "'";
    switch (v.type) {
        case ValueType::Real: {
            double x = 0.0;
            if (!parse_whole(text, x)) throw Error(given + " is not a number");
            check_real(v, x);
            return x;
        }
        case ValueType::Enumeration:
            if (const EnumerationItem* item = v.item_named(text)) return item->value;
            [[fallthrough]];
        case ValueType::Integer: {
            std::int32_t x = 0;
            if (!parse_whole(text, x))
                throw Error(given + (v.type == ValueType::Enumeration ? " is not an item (" + v.item_names() + ")"
                                                                      : " is not a 32-bit integer"));
            check_integer(v, x);
            return x;
        }
        case ValueType::Boolean:
            if (text == "true" || text == "1") return 1.0;
            if (text == "false" || text == "0") return 0.0;
            throw Error(given + " is not a Boolean (true, false, 1, 0)");
        case ValueType::String:
            break;
    }
    throw Error(v.name + ": a String variable has no number");
}

}  // namespace fmu
