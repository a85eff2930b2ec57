// The derived signals a GNC engineer reads off a run of this project's systems, computed in one place
// from the recorded columns (cosim plot's data step; written as columns with `cosim plot --derived`):
// the attitude error of an estimate against the truth as an angle and as roll/pitch/yaw in body axes,
// the angle between two directions (sun vector error), and the filter's normalized error per degree of
// freedom from its covariance factor (the angles alone: analysis/angle_error.hpp).
//
// Why after the run, from the CSV, rather than an observer inside it: the CSV holds what the blocks
// gave, and every error is a function of one row, so computing it afterwards gives the same numbers for
// any CSV of the system (a campaign's --run K replay, another importer's output) without running again.
//
// Conventions (README): quaternions scalar-last [x, y, z, w]; A(q) maps inertial to body axes.
#pragma once

#include <array>

namespace analysis {

// The rotation vector dtheta (rad, body axes) with A(q_true) = R(dtheta) A(q_est): how far and about
// which body axis the estimate must turn to be the truth. Its components are the roll, pitch and yaw
// errors (x, y, z) and its norm is the error angle (the shorter way: q and -q are one attitude).
std::array<double, 3> attitude_error_vector(const std::array<double, 4>& q_true, const std::array<double, 4>& q_est);

// |inv(L) dtheta|^2 / 3 with L the lower-triangular factor of the covariance P = L L' given by rows
// (L11, L21, L22, L31, L32, L33), as the estimator's attitude_cov_sqrt: 1 for a consistent filter. NaN
// when L is singular.
double normalized_error_per_dof(const std::array<double, 3>& dtheta, const std::array<double, 6>& l);

}  // namespace analysis
