// Angles between estimates and truths: the attitude error and the sun vector error of the bundled
// systems, shared by the figures (`cosim plot`), the campaign's angle metrics and the end-to-end tests.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace analysis {

// Angle in degrees between two attitudes given as scalar-last quaternions (normalized here).
inline double attitude_error_degrees(const double q_a[4], const double q_b[4]) {
    double dot = 0.0, na = 0.0, nb = 0.0;
    for (int i = 0; i < 4; ++i) {
        dot += q_a[i] * q_b[i];
        na += q_a[i] * q_a[i];
        nb += q_b[i] * q_b[i];
    }
    const double c = std::min(1.0, std::abs(dot) / std::sqrt(na * nb));  // q and −q are one attitude
    return 2.0 * std::acos(c) * 180.0 / std::numbers::pi;
}

// Angle in degrees between two 3-vectors (not necessarily unit); NaN when one is zero. atan2 of |a x b|
// and a . b: accurate at small and near-180 degree angles alike (acos of the cosine loses small ones).
inline double vector_angle_degrees(const double a[3], const double b[3]) {
    const double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    const double na = std::hypot(a[0], a[1], a[2]), nb = std::hypot(b[0], b[1], b[2]);
    if (na == 0.0 || nb == 0.0) return std::numeric_limits<double>::quiet_NaN();
    return std::atan2(std::hypot(c[0], c[1], c[2]), a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) * 180.0 / std::numbers::pi;
}

}  // namespace analysis
