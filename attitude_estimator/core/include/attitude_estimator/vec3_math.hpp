// The few 3-vector operations the core needs, on std::array so that they work in both float and double
// without pulling Eigen into the public headers.
#pragma once

#include <cmath>

#include "attitude_estimator/types.hpp"

namespace attitude_estimator {

template <class T>
constexpr T dot(const Vec3<T>& a, const Vec3<T>& b) noexcept {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

template <class T>
constexpr Vec3<T> cross(const Vec3<T>& a, const Vec3<T>& b) noexcept {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

template <class T>
constexpr Vec3<T> scaled(const Vec3<T>& a, T s) noexcept {
    return {a[0] * s, a[1] * s, a[2] * s};
}

template <class T>
constexpr T squared_norm(const Vec3<T>& a) noexcept {
    return dot(a, a);
}

// w = A v with A row-major.
template <class T>
constexpr Vec3<T> multiply(const Matrix3RowMajor<T>& a, const Vec3<T>& v) noexcept {
    return {a[0] * v[0] + a[1] * v[1] + a[2] * v[2], a[3] * v[0] + a[4] * v[1] + a[5] * v[2],
            a[6] * v[0] + a[7] * v[1] + a[8] * v[2]};
}

}  // namespace attitude_estimator
