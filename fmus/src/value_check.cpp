#include "fmu/value_check.hpp"

#include <charconv>
#include <cmath>
#include <string>

#include "fmu/description.hpp"
#include "fmu/errors.hpp"

namespace fmu {

namespace {

void check_range(const Variable& v, double x) {
    if (v.min && x < *v.min)
        throw Error(v.name + " = " + format_real(x) + " is below its minimum " + format_real(*v.min));
    if (v.max && x > *v.max)
        throw Error(v.name + " = " + format_real(x) + " is above its maximum " + format_real(*v.max));
}

template <class T>
bool parse_whole(std::string_view text, T& x) {
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
    return !text.empty() && ec == std::errc() && end == text.data() + text.size();
}

}  // namespace

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
