// Attitude matrix <-> quaternion, in the design's convention: A maps reference (inertial) vectors to body
// (observed) vectors, w_body = A v_ref (000 eq. 7).
#pragma once

#include <cmath>

#include "attitude_estimator/types.hpp"

namespace attitude_estimator {

// A(q) = (w² − |Q|²) I + 2 Q Qᵀ − 2 w [Q×]            (000 eq. 11, sign of the last term as in design.md)
// with [Q×] = [[0, −z, y], [z, 0, −x], [−y, x, 0]]. q must be of unit norm (000 eq. 12).
template <class T>
constexpr Matrix3RowMajor<T> attitude_matrix(const Quaternion<T>& q) noexcept {
    const T x = q.x, y = q.y, z = q.z, w = q.w;
    const T d = w * w - (x * x + y * y + z * z);
    const T two = T(2);
    return {d + two * x * x,       two * (x * y + w * z), two * (x * z - w * y), two * (y * x - w * z), d + two * y * y,
            two * (y * z + w * x), two * (z * x + w * y), two * (z * y - w * x), d + two * z * z};
}

// Quaternion of a rotation matrix in the same convention, by Shepperd's method: of the four expressions
// 4w², 4x², 4y², 4z² the largest is used as the divisor, so the result never divides by a small number
// (no trouble near 180°). Of unit norm to rounding when A is orthonormal to rounding; either sign.
template <class T>
inline Quaternion<T> shepperd_quaternion(const Matrix3RowMajor<T>& a) noexcept {
    // With the matrix above: A01 − A10 = 4wz, A12 − A21 = 4wx, A20 − A02 = 4wy,
    // A01 + A10 = 4xy, A02 + A20 = 4xz, A12 + A21 = 4yz, trace = 4w² − 1, A00 − A11 − A22 = 4x² − 1.
    const T tr = a[0] + a[4] + a[8];
    Quaternion<T> q;
    if (tr >= a[0] && tr >= a[4] && tr >= a[8]) {
        const T f = T(2) * std::sqrt(T(1) + tr);  // 4w
        const T g = T(1) / f;
        q = {(a[5] - a[7]) * g, (a[6] - a[2]) * g, (a[1] - a[3]) * g, f * T(0.25)};
    } else if (a[0] >= a[4] && a[0] >= a[8]) {
        const T f = T(2) * std::sqrt(T(1) + a[0] - a[4] - a[8]);  // 4x
        const T g = T(1) / f;
        q = {f * T(0.25), (a[1] + a[3]) * g, (a[2] + a[6]) * g, (a[5] - a[7]) * g};
    } else if (a[4] >= a[8]) {
        const T f = T(2) * std::sqrt(T(1) - a[0] + a[4] - a[8]);  // 4y
        const T g = T(1) / f;
        q = {(a[1] + a[3]) * g, f * T(0.25), (a[5] + a[7]) * g, (a[6] - a[2]) * g};
    } else {
        const T f = T(2) * std::sqrt(T(1) - a[0] - a[4] + a[8]);  // 4z
        const T g = T(1) / f;
        q = {(a[2] + a[6]) * g, (a[5] + a[7]) * g, f * T(0.25), (a[1] - a[3]) * g};
    }
    return q;
}

// The same, normalized exactly and with w >= 0.
template <class T>
inline Quaternion<T> quaternion_from_attitude_matrix(const Matrix3RowMajor<T>& a) noexcept {
    const Quaternion<T> q = shepperd_quaternion(a);
    const T n = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
    const T s = (q.w < T(0) ? T(-1) : T(1)) / n;
    return {q.x * s, q.y * s, q.z * s, q.w * s};
}

}  // namespace attitude_estimator
