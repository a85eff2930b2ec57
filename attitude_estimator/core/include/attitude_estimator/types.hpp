// Plain value types shared by the whole estimator core: vectors, the quaternion, the row-major matrix.
// Everything here is an aggregate of scalars so an FMU wrapper (or a DSP main loop) can fill and read it
// without knowing about Eigen.
#pragma once

#include <array>
#include <cstddef>

namespace attitude_estimator {

// Scalar type T is float or double. The TMS320F2808 the seeds fly has no 64-bit floating point (its C
// compiler makes `double` 32 bits), so every algorithm is a template and the tests run both.
template <class T>
using Vec3 = std::array<T, 3>;

// THE QUATERNION ORDER, written down once for the whole block: scalar-last [x, y, z, w] as in the seeds
// (000 eq. 10: q̄ = [Q; q] = [sin(θ/2) n; cos(θ/2)]). Fields are named so no index can be misread.
// Beware Eigen: Eigen::Quaternion stores x, y, z, w too, but its constructor takes (w, x, y, z).
// The estimator returns the sign with w >= 0 (q and -q are the same attitude).
template <class T>
struct Quaternion {
    T x{0};
    T y{0};
    T z{0};
    T w{1};
};

// A 3x3 matrix stored row-major: element (row r, column c) is m[3 * r + c].
template <class T>
using Matrix3RowMajor = std::array<T, 9>;

// Fixed capacity of an observation set (sun, field and up to four more); no heap anywhere in the core.
inline constexpr std::size_t kMaxObservations = 6;

}  // namespace attitude_estimator
