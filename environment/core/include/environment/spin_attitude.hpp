#pragma once
// The seed scenario's attitude motion (paper 000, section 4 and eq. 5): the sun seen in body axes is
//   s_body(t) = (sin phi sin theta, cos phi sin theta, cos theta),
//   phi = phi0 + phi_dot t, theta = theta0 + theta_dot t.
//
// Attitude chosen to produce exactly this for a fixed inertial sun direction s0 (the sun at epoch):
//   A(t) = Rz(pi/2 - phi) Ry(theta) A0,
// where Rz, Ry are the active right-handed rotation matrices about the body z and y axes and A0 is the
// fixed "sun frame" attitude whose rows are x0 = unit(k x s0) (k = ECI pole; e_x if s0 is along k),
// y0 = s0 x x0, z0 = s0, so that A0 s0 = e_z. Then Ry(theta) e_z = (sin theta, 0, cos theta) and the
// rotation by (pi/2 - phi) about z gives exactly s_body(t).
// Angular velocity (from dA/dt = -[w x] A, i.e. [w x] = -R' R^T with R = Rz Ry):
//   w_body = (theta_dot cos phi, -theta_dot sin phi, phi_dot)   [rad/s]
#include <array>

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

#include "environment/attitude.hpp"

namespace environment {

struct SpinParams {
    double phi0 = 0.0;        // rad
    double theta0 = 0.0;      // rad
    double phi_dot = 1.26;    // rad/s, seed 000 section 4
    double theta_dot = 6.28;  // rad/s, seed 000 section 4
};

class SpinAttitude {
public:
    /// sun_eci_at_epoch: the fixed inertial sun direction (need not be unit, must be non-zero).
    SpinAttitude(const SpinParams& params, const Eigen::Vector3d& sun_eci_at_epoch);

    Eigen::Matrix3d attitude_matrix(double t) const;
    Quaternion quaternion(double t) const;
    Eigen::Vector3d angular_velocity_body(double t) const;
    /// The seed formula itself (eq. 5 direction), for tests and for users who want it directly.
    Eigen::Vector3d seed_sun_body(double t) const;
    const Eigen::Matrix3d& sun_frame() const { return a0_; }

private:
    SpinParams params_;
    Eigen::Matrix3d a0_;
};

}  // namespace environment
