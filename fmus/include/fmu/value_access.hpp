// Typed access to one variable's value inside a block's bytes, located by the table's offset.
#pragma once

#include <cstdint>
#include <cstring>
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
