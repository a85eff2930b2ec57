// The field of the panels' string currents at the magnetometer as the on-board computer is told it (uplinked
// knowledge, derived on the host from the block's parameters): each face's cell string is a rectangular loop
// of four straight wires, and its field at the sensor per ampere is the exact Biot–Savart field of the four
// segments (J. D. Hanson, S. P. Hirshman, "Compact expressions for the Biot–Savart fields of a filamentary
// segment", Phys. Plasmas 9, 4410, 2002). Plain C++, no heap, no exceptions (the firmware builds it too).
#pragma once

#include <array>
#include <cstddef>

#include "attitude_estimator/types.hpp"

namespace attitude_estimator {

inline constexpr std::size_t kStringFaces = 6;  // +x, −x, +y, −y, +z, −z

// A rectangular current loop (any parallelogram): corners center ± side_a/2 ± side_b/2, the current running
// along side_a, then side_b, then back, so that a positive current's moment is I (side_a × side_b). Metres,
// body axes; zero sides: no loop (no field).
struct StringLoop {
    Vec3<double> center{};
    Vec3<double> side_a{};
    Vec3<double> side_b{};
};

// The loop's field at p per ampere (T/A, body axes). A point on a wire's line outside the wire gets that
// wire's zero; a point on a wire itself is the caller's to refuse (string_loop_wire_distance).
Vec3<double> string_loop_field_per_ampere(const StringLoop& loop, const Vec3<double>& p) noexcept;

// Distance from p to the loop's nearest wire (m).
double string_loop_wire_distance(const StringLoop& loop, const Vec3<double>& p) noexcept;

}  // namespace attitude_estimator
