// Angles between estimates and truths: the attitude error and the sun vector error of the bundled
// systems, shared by the figures (`cosim plot`), the campaign's angle metrics and the end-to-end tests.
#pragma once

#include <algorithm>
#include <cmath>
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

// Angle in degrees between two 3-vectors (normalized here); NaN when one is zero.
inline double vector_angle_degrees(const double a[3], const double b[3]) {
    const double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    const double na = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    const double nb = std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
    return std::acos(std::clamp(dot / (na * nb), -1.0, 1.0)) * 180.0 / std::numbers::pi;
}

}  // namespace analysis
