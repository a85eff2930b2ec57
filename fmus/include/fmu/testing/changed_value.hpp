// Another value a variable takes, written through its table entry: for the table-driven tests that change
// each declared parameter of a block and check that the change reaches its core. A Real becomes 5 % larger
// (smaller where that passes its maximum; 0.01 or half the maximum from zero), an Integer one more (less at its maximum), an
// Enumeration its next item, a Boolean the other value. A String has no generic other value: false.
#pragma once

#include <algorithm>
#include <span>

#include "fmu/value_access.hpp"
#include "fmu/variable.hpp"

namespace fmu::testing {

inline bool write_changed_value(std::span<std::byte> bytes, const Variable& v) {
    switch (v.type) {
        case ValueType::Real: {
            const double x = read_real(bytes, v);
            double y = x == 0.0 ? 0.01 : x * 1.05;
            if (v.max && y > *v.max) y = x == 0.0 ? *v.max / 2.0 : x * 0.95;
            write_real(bytes, v, y);
            return true;
        }
        case ValueType::Integer: {
            const std::int32_t x = read_integer(bytes, v);
            write_integer(bytes, v, v.max && x + 1 > *v.max ? x - 1 : x + 1);
            return true;
        }
        case ValueType::Enumeration: {
            const std::int32_t x = read_integer(bytes, v);
            auto it = std::find_if(v.items.begin(), v.items.end(), [x](const auto& i) { return i.value == x; });
            write_integer(bytes, v, (it == v.items.end() || ++it == v.items.end() ? v.items.front() : *it).value);
            return true;
        }
        case ValueType::Boolean:
            write_boolean(bytes, v, !read_boolean(bytes, v));
            return true;
        case ValueType::String:
            break;
    }
    return false;
}

}  // namespace fmu::testing
