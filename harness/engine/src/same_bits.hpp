// Bit-for-bit equality of doubles: what the master asks when it wants to know whether a value, a time or the
// states changed (0.0 and −0.0 differ, a NaN equals itself), which == does not answer.
#pragma once

#include <cstring>
#include <span>

namespace cosim {

inline bool same_bits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

// Two arrays, bit for bit: the same length and the same bytes (memcmp takes no null pointer, even for zero
// bytes: two empty arrays are the same without it).
inline bool same_bits(std::span<const double> a, std::span<const double> b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size_bytes()) == 0);
}

}  // namespace cosim
