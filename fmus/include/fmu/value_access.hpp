// Typed access to one variable's value inside a block's bytes, located by the table's offset.
#pragma once

#include <cstdint>
#include <cstring>
#include <limits>
#include <span>
#include <string_view>

#include "fmu/variable.hpp"

namespace fmu {

inline double read_real(std::span<const std::byte> data, const Variable& v) {
    double x;
    std::memcpy(&x, data.data() + v.offset, sizeof x);
    return x;
}
inline void write_real(std::span<std::byte> data, const Variable& v, double x) {
    std::memcpy(data.data() + v.offset, &x, sizeof x);
}
inline std::int32_t read_integer(std::span<const std::byte> data, const Variable& v) {
    std::int32_t x;
    std::memcpy(&x, data.data() + v.offset, sizeof x);
    return x;
}
inline void write_integer(std::span<std::byte> data, const Variable& v, std::int32_t x) {
    std::memcpy(data.data() + v.offset, &x, sizeof x);
}
inline bool read_boolean(std::span<const std::byte> data, const Variable& v) {
    bool x;
    std::memcpy(&x, data.data() + v.offset, sizeof x);
    return x;
}
inline void write_boolean(std::span<std::byte> data, const Variable& v, bool x) {
    std::memcpy(data.data() + v.offset, &x, sizeof x);
}
// A Real, Integer, Enumeration or Boolean variable's value as a double (a Boolean as 0 or 1): the form the
// bridge's frames carry and a test compares. A String has none (NaN): its callers refuse or skip those.
inline double read_number(std::span<const std::byte> data, const Variable& v) {
    switch (v.type) {
        case ValueType::Real:
            return read_real(data, v);
        case ValueType::Integer:
        case ValueType::Enumeration:
            return read_integer(data, v);
        case ValueType::Boolean:
            return read_boolean(data, v) ? 1.0 : 0.0;
        case ValueType::String:
            break;
    }
    return std::numeric_limits<double>::quiet_NaN();
}
inline std::string_view read_string(std::span<const std::byte> data, const Variable& v) {
    return std::string_view(reinterpret_cast<const char*>(data.data() + v.offset));
}
// The caller has checked text.size() <= v.string_capacity.
inline void write_string(std::span<std::byte> data, const Variable& v, std::string_view text) {
    auto* dst = reinterpret_cast<char*>(data.data() + v.offset);
    std::memset(dst, 0, v.string_capacity + 1);
    std::memcpy(dst, text.data(), text.size());
}

}  // namespace fmu
