// Checks of a block state that came in as bytes (fmi2DeSerializeFMUstate): a payload whose checksum
// matches can still be one nobody produced (made by hand, or by another version of the FMU), and its
// numbers, flags, strings and indices feed equations that assume them sane. Each check throws
// fmu::Error naming the field and what is wrong with it.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <string_view>

#include "fmu/errors.hpp"

namespace fmu {

class Model;

// Every variable of the block's table: Reals not NaN (infinite only when no min/max bounds them),
// Reals and Integers within their declared min/max, Booleans stored as 0 or 1, Strings terminated
// within their capacity and one of their allowed values. Then the block's validate() and check_state().
void check_restored_state(const Model& model);

// FNV-1a 64 of a serialized state's header and payload: the checksum its last 8 bytes hold.
std::uint64_t serialized_state_checksum(std::span<const char> bytes);

// Helpers for a block's check_state() over fields that are not in its table.
inline void require_finite(double x, std::string_view name) {
    if (!std::isfinite(x)) throw Error("restored FMU state: " + std::string(name) + " is not finite");
}
template <std::size_t N>
void require_finite(const double (&xs)[N], std::string_view name) {
    for (const double x : xs) require_finite(x, name);
}
inline void require_finite(std::span<const double> xs, std::string_view name) {
    for (const double x : xs) require_finite(x, name);
}
// A bool's byte is read as a byte: any value but 0 and 1 would be undefined behaviour as a bool.
inline void require_bool(const bool& flag, std::string_view name) {
    unsigned char byte = 0;
    std::memcpy(&byte, &flag, 1);
    if (byte > 1)
        throw Error("restored FMU state: " + std::string(name) + " is not a boolean (byte " + std::to_string(byte) +
                    ")");
}
inline void require_range(std::int64_t value, std::int64_t lo, std::int64_t hi, std::string_view name) {
    if (value < lo || value > hi)
        throw Error("restored FMU state: " + std::string(name) + " = " + std::to_string(value) + " is outside " +
                    std::to_string(lo) + " ... " + std::to_string(hi));
}

}  // namespace fmu
