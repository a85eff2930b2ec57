#pragma once
// Rigid body: Euler's equations and quaternion kinematics as continuous states for an external
// integrator (the FMU's Model Exchange interface, CVODE in the tests), torque-free or under an external
// torque given in body axes (the environment's disturbance torques, disturbance_torques.hpp).
//
// State x (7): q = [x, y, z, w] (scalar-last, attitude matrix A(q) maps ECI -> body), then the body
// angular velocity w_body [rad/s].
//   Euler:       J dw/dt = -w x (J w) + tau             (tau = 0: torque-free)
//   Kinematics:  dQ/dt = 1/2 (q_w w - w x Q),  dq_w/dt = -1/2 w . Q
// (Shuster's q' = 1/2 Omega(w) q for A = A(q) inertial-to-body; it keeps dA/dt = -[w x] A.)
//
// Drift: the exact flow keeps |q| = 1, a numerical integrator does not. renormalize() projects q back
// onto the unit sphere (q <- q/|q|); call it after every accepted step (fmi2CompletedIntegratorStep or
// at communication points). It is a projection onto the invariant manifold, so it changes q only by the
// integrator's own error and never touches w (energy and |H| depend on w only).
#include <array>

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

namespace environment {

using RigidBodyState = std::array<double, 7>;

struct RigidBodyParams {
    /// Inertia matrix about the centre of mass in body axes [kg m^2], row-major, symmetric positive definite.
    /// Default: the bundled 3U CubeSat (docs/design.md, "The spacecraft"): 4.0 kg in 100 x 100 x 340 mm,
    /// long axis z the smallest moment, slightly asymmetric with small products of inertia so that the motion
    /// is a true tumble.
    std::array<double, 9> inertia = {0.0405, 1.5e-4, -2.0e-4, 1.5e-4, 0.0398, 1.0e-4, -2.0e-4, 1.0e-4, 0.0072};
    /// Initial attitude [x, y, z, w] (normalised on use).
    std::array<double, 4> q0 = {0.1, -0.2, 0.3, 0.927361849549570};
    /// Initial body rate [rad/s]: |w0| = 0.94 deg/s, within the 0.3-1.3 deg/s of seed 004 fig. 4.
    std::array<double, 3> omega0 = {0.0100759, -0.0080607, 0.0100759};
};

class RigidBody {
public:
    /// Throws std::invalid_argument when the inertia is not symmetric positive definite or q0 is zero.
    explicit RigidBody(const RigidBodyParams& params);

    RigidBodyState initial_state() const;
    /// dx/dt = f(x), torque-free; x and dx may not alias.
    void derivative(const double* x, double* dx) const;
    /// dx/dt = f(x) under the external torque `torque_body` (N m, body axes).
    void derivative(const double* x, const Eigen::Vector3d& torque_body, double* dx) const;
    static void renormalize(double* x);

    double kinetic_energy(const double* x) const;                  // 1/2 w^T J w   [J]
    Eigen::Vector3d angular_momentum_body(const double* x) const;  // J w       [N m s]
    const Eigen::Matrix3d& inertia() const { return j_; }

private:
    RigidBodyParams params_;
    Eigen::Matrix3d j_;
    Eigen::Matrix3d j_inv_;
};

}  // namespace environment
