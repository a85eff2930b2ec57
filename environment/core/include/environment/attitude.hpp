#pragma once
// Quaternion and attitude-matrix conventions of the whole project (design.md):
// quaternions are scalar-last q = [x, y, z, w], Q = (x, y, z); the attitude matrix maps inertial
// vectors to body vectors, w_body = A v_eci, A(q) = (w^2 - |Q|^2) I + 2 Q Q^T - 2 w [Q x].
// Note: Eigen::Quaterniond stores (x, y, z, w) too but its constructor takes (w, x, y, z), and its
// toRotationMatrix() is the active rotation, i.e. A(q)^T. We therefore never hand our arrays to Eigen's
// quaternion type without going through the two functions below.
#include <array>

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

namespace environment {

using Quaternion = std::array<double, 4>;  // [x, y, z, w]

/// A(q) for a unit quaternion (the formula above; q need not be normalised exactly, the matrix is then
/// scaled by |q|^2).
Eigen::Matrix3d attitude_matrix(const Quaternion& q);

/// The unit quaternion with w >= 0 whose attitude matrix is A (A must be a proper rotation).
Quaternion quaternion_from_attitude_matrix(const Eigen::Matrix3d& A);

/// Cross-product matrix [v x].
Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& v);

}  // namespace environment
