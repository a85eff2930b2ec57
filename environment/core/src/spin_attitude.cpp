#include "environment/spin_attitude.hpp"

#include <cmath>
#include <stdexcept>

#include "environment/constants.hpp"

namespace environment {

namespace {
// Active right-handed rotations (v' = R v) about the z and y axes.
Eigen::Matrix3d rot_z(double a) {
    Eigen::Matrix3d r;
    r << std::cos(a), -std::sin(a), 0.0, std::sin(a), std::cos(a), 0.0, 0.0, 0.0, 1.0;
    return r;
}
Eigen::Matrix3d rot_y(double a) {
    Eigen::Matrix3d r;
    r << std::cos(a), 0.0, std::sin(a), 0.0, 1.0, 0.0, -std::sin(a), 0.0, std::cos(a);
    return r;
}
}  // namespace

SpinAttitude::SpinAttitude(const SpinParams& params, const Eigen::Vector3d& sun_eci_at_epoch) : params_(params) {
    if (!(sun_eci_at_epoch.norm() > 0.0) || !std::isfinite(sun_eci_at_epoch.norm())) {
        throw std::invalid_argument("SpinAttitude: the sun direction at epoch must be finite and non-zero");
    }
    if (!std::isfinite(params.phi0) || !std::isfinite(params.theta0) || !std::isfinite(params.phi_dot) ||
        !std::isfinite(params.theta_dot)) {
        throw std::invalid_argument("SpinAttitude: spin angles and rates must be finite");
    }
    const Eigen::Vector3d z0 = sun_eci_at_epoch.normalized();
    Eigen::Vector3d x0 = Eigen::Vector3d::UnitZ().cross(z0);
    // The sun is never within 66 deg of the pole, but keep the frame defined for any input.
    x0 = x0.norm() > 1e-9 ? x0.normalized() : Eigen::Vector3d::UnitX();
    const Eigen::Vector3d y0 = z0.cross(x0);
    a0_.row(0) = x0.transpose();
    a0_.row(1) = y0.transpose();
    a0_.row(2) = z0.transpose();
}

Eigen::Matrix3d SpinAttitude::attitude_matrix(double t) const {
    const double phi = params_.phi0 + params_.phi_dot * t;
    const double theta = params_.theta0 + params_.theta_dot * t;
    // A(t) = Rz(pi/2 - phi) Ry(theta) A0: A(t) s0 = Rz(pi/2 - phi) (sin theta, 0, cos theta) = seed eq. 5 direction.
    return rot_z(kPi / 2.0 - phi) * rot_y(theta) * a0_;
}

Quaternion SpinAttitude::quaternion(double t) const {
    return quaternion_from_attitude_matrix(attitude_matrix(t));
}

Eigen::Vector3d SpinAttitude::angular_velocity_body(double t) const {
    const double phi = params_.phi0 + params_.phi_dot * t;
    // [w x] = -R' R^T with R = Rz(alpha) Ry(theta), alpha = pi/2 - phi:
    // R' R^T = [(alpha' e_z + theta' Rz(alpha) e_y) x]  =>  w = phi' e_z - theta' (-sin alpha, cos alpha, 0)
    return {params_.theta_dot * std::cos(phi), -params_.theta_dot * std::sin(phi), params_.phi_dot};
}

Eigen::Vector3d SpinAttitude::seed_sun_body(double t) const {
    const double phi = params_.phi0 + params_.phi_dot * t;
    const double theta = params_.theta0 + params_.theta_dot * t;
    // seed 000 eq. 5 (left-hand side) with section 4's rates
    return {std::sin(phi) * std::sin(theta), std::cos(phi) * std::sin(theta), std::cos(theta)};
}

}  // namespace environment
