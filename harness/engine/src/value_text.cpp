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

}  // namespace cosim
