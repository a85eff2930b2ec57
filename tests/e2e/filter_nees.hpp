// The filter's normalized estimation error squared per degree of freedom, as the consistency tests compute it
// (e2e_filter_consistency_test.cpp, e2e_filter_random_start_test.cpp; docs/filter.md, "Consistency").
#pragma once

#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "recorder.hpp"

namespace e2e {

// δθᵀ P_θθ⁻¹ δθ / 3 for the true attitude q_true and the filter's q_filt (scalar-last), with P_θθ given by its
// lower Cholesky factor l by rows (L11, L21, L22, L31, L32, L33: the estimator's attitude_cov_sqrt). δθ from
// δq = q_true ⊗ q_filt⁻¹ in Shuster's order (A(δq) = A_true Âᵀ = I − [δθ×]), δθ = 2 vec(δq) with the sign of
// δq₄. The error's size |δθ| (rad) goes to *angle when given.
inline double nees_per_dof(const double q_true[4], const double q_filt[4], const double l[6], double* angle = nullptr) {
    const double x1 = q_true[0], y1 = q_true[1], z1 = q_true[2], w1 = q_true[3];
    const double x2 = -q_filt[0], y2 = -q_filt[1], z2 = -q_filt[2], w2 = q_filt[3];
    double d[3] = {w1 * x2 + w2 * x1 - (y1 * z2 - z1 * y2), w1 * y2 + w2 * y1 - (z1 * x2 - x1 * z2),
                   w1 * z2 + w2 * z1 - (x1 * y2 - y1 * x2)};
    const double s = (w1 * w2 - (x1 * x2 + y1 * y2 + z1 * z2)) < 0 ? -2.0 : 2.0;
    for (double& v : d) v *= s;
    if (angle) *angle = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    // |L⁻¹ δθ|² by forward substitution.
    const double z0 = d[0] / l[0];
    const double zz1 = (d[1] - l[1] * z0) / l[2];
    const double zz2 = (d[2] - l[3] * z0 - l[4] * zz1) / l[5];
    return (z0 * z0 + zz1 * zz1 + zz2 * zz2) / 3.0;
}

// The columns recorded_nees_per_dof reads: env.q_true[1..4], est.q_filt[1..4], est.attitude_cov_sqrt[1..6].
inline std::vector<std::string> nees_columns() {
    std::vector<std::string> columns = vec("env.q_true", 4);
    for (const auto& n : vec("est.q_filt", 4)) columns.push_back(n);
    for (const auto& n : vec("est.attitude_cov_sqrt", 6)) columns.push_back(n);
    return columns;
}

// nees_per_dof at row i of a Recorder holding env.q_true[1..4], est.q_filt[1..4] and
// est.attitude_cov_sqrt[1..6]; none while the filter is not running (a zero diagonal of its factor).
inline std::optional<double> recorded_nees_per_dof(const Recorder& r, std::size_t i, double* angle = nullptr) {
    double q_true[4], q_filt[4], l[6];
    for (int k = 0; k < 4; ++k) {
        q_true[k] = r["env.q_true[" + std::to_string(k + 1) + "]"][i];
        q_filt[k] = r["est.q_filt[" + std::to_string(k + 1) + "]"][i];
    }
    for (int k = 0; k < 6; ++k) l[k] = r["est.attitude_cov_sqrt[" + std::to_string(k + 1) + "]"][i];
    if (!(l[0] > 0 && l[2] > 0 && l[5] > 0)) return std::nullopt;
    return nees_per_dof(q_true, q_filt, l, angle);
}

}  // namespace e2e
