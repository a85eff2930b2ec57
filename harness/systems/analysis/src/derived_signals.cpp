#include "analysis/derived_signals.hpp"

#include <cmath>
#include <limits>

namespace analysis {

std::array<double, 3> attitude_error_vector(const std::array<double, 4>& q_true, const std::array<double, 4>& q_est) {
    // dq = q_true (x) q_est^-1 in the product with A(p (x) q) = A(p) A(q) (Shuster's convention):
    // vector part w1 v2 + w2 v1 - v1 x v2, scalar part w1 w2 - v1 . v2, with q_est^-1 = [-v, w].
    const double x1 = q_true[0], y1 = q_true[1], z1 = q_true[2], w1 = q_true[3];
    const double x2 = -q_est[0], y2 = -q_est[1], z2 = -q_est[2], w2 = q_est[3];
    const std::array<double, 3> v{w1 * x2 + w2 * x1 - (y1 * z2 - z1 * y2), w1 * y2 + w2 * y1 - (z1 * x2 - x1 * z2),
                                  w1 * z2 + w2 * z1 - (x1 * y2 - y1 * x2)};
    const double w = w1 * w2 - (x1 * x2 + y1 * y2 + z1 * z2);
    const double s = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (s == 0.0) return {0.0, 0.0, 0.0};
    // The shorter rotation: angle 2 atan2(|v|, |w|) about v, turned with w's sign.
    const double angle = 2.0 * std::atan2(s, std::abs(w)) * (w < 0.0 ? -1.0 : 1.0);
    return {angle * v[0] / s, angle * v[1] / s, angle * v[2] / s};
}

double normalized_error_per_dof(const std::array<double, 3>& d, const std::array<double, 6>& l) {
    if (l[0] == 0.0 || l[2] == 0.0 || l[5] == 0.0) return std::numeric_limits<double>::quiet_NaN();
    const double z0 = d[0] / l[0];  // forward substitution: L z = d
    const double z1 = (d[1] - l[1] * z0) / l[2];
    const double z2 = (d[2] - l[3] * z0 - l[4] * z1) / l[5];
    return (z0 * z0 + z1 * z1 + z2 * z2) / 3.0;
}

}  // namespace analysis
