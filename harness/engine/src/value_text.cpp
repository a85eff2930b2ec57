#include "engine/value_text.hpp"

#include <cctype>
#include <charconv>
#include <cmath>

#include "engine/cosim_error.hpp"
#include "engine/name_hint.hpp"

namespace cosim {

double parse_real(std::string_view text, const std::string& what) {
    double x = 0.0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
    if (ec != std::errc() || end != text.data() + text.size() || text.empty())
        throw CosimError(what + ": '" + std::string(text) + "' is not a number");
    return x;
}

int parse_integer(std::string_view text, const std::string& what) {
    int x = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
    if (ec != std::errc() || end != text.data() + text.size() || text.empty())
        throw CosimError(what + ": '" + std::string(text) + "' is not an integer");
    return x;
}

bool parse_boolean(std::string_view text, const std::string& what) {
    if (text == "true" || text == "1") return true;
    if (text == "false" || text == "0") return false;
    throw CosimError(what + ": '" + std::string(text) + "' is not a Boolean (true, false, 1, 0)");
}

int parse_enumeration(const fmi_loader::ModelDescription& md, const fmi_loader::ScalarVariable& v,
                      std::string_view text, const std::string& what) {
    const fmi_loader::SimpleType* type = md.find_type(v.declared_type);
    if (!type) return parse_integer(text, what);  // the loader checked the declared type exists
    std::string names;
    for (const auto& item : type->items) {
        if (item.name == text) return static_cast<int>(item.value);
        names += (names.empty() ? "" : ", ") + item.name;
    }
    const bool number = !text.empty() && (std::isdigit(static_cast<unsigned char>(text[0])) || text[0] == '-');
    if (number) {
        const int x = parse_integer(text, what);
        for (const auto& item : type->items)
            if (item.value == x) return x;
    }
    std::vector<std::string> items;
    for (const auto& item : type->items) items.push_back(item.name);
    throw CosimError(what + ": '" + std::string(text) + "' is not an item of " + v.declared_type + " (" + names + ")" +
                     name_hint(text, items));
}

std::string format_real(double x) {
    char buf[32];
    const auto result = std::to_chars(buf, buf + sizeof buf, x);
    return std::string(buf, result.ptr);
}

void check_value(const fmi_loader::ModelDescription& md, const fmi_loader::ScalarVariable& v, double x,
                 const std::string& what) {
    using T = fmi_loader::VariableType;
    const std::string given = what + ": " + format_real(x);
    switch (v.type) {
        case T::real:
            if (!std::isfinite(x)) throw CosimError(given + " is not a finite number");
            break;
        case T::integer:
        case T::enumeration:
            if (!std::isfinite(x) || x != std::trunc(x) || x < -2147483648.0 || x > 2147483647.0)
                throw CosimError(given + " is not a whole 32-bit number, as an " +
                                 std::string(fmi_loader::to_string(v.type)) + " must be");
            if (v.type == T::enumeration)
                if (const auto* type = md.find_type(v.declared_type); type && !type->items.empty()) {
                    std::string names;
                    for (const auto& item : type->items) {
                        if (static_cast<double>(item.value) == x) return;
                        names += (names.empty() ? "" : ", ") + item.name + " = " + std::to_string(item.value);
                    }
                    throw CosimError(given + " is not an item of " + v.declared_type + " (" + names + ")");
                }
            break;
        case T::boolean:
            if (x != 0.0 && x != 1.0) throw CosimError(given + " is not a Boolean (0 or 1)");
            return;
        case T::string:
            throw CosimError(what + ": a String has no number");
    }
    if (v.min && x < *v.min) throw CosimError(given + " is below its minimum " + format_real(*v.min));
    if (v.max && x > *v.max) throw CosimError(given + " is above its maximum " + format_real(*v.max));
}

}  // namespace cosim
