#include "environment/rigid_body.hpp"

#include <cmath>
#include <stdexcept>

#include <Eigen/Eigenvalues>

namespace environment {

RigidBody::RigidBody(const RigidBodyParams& params) : params_(params) {
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) j_(r, c) = params.inertia[3 * r + c];
    }
    if (!j_.allFinite() || (j_ - j_.transpose()).cwiseAbs().maxCoeff() > 1e-12 * j_.cwiseAbs().maxCoeff()) {
        throw std::invalid_argument("RigidBody: the inertia matrix must be finite and symmetric");
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(j_);
    const Eigen::Vector3d& p = eig.eigenvalues();  // ascending
    if (!(p(0) > 0.0)) throw std::invalid_argument("RigidBody: the inertia matrix must be positive definite");
    // Principal moments of a real body obey the triangle inequality.
    if (p(2) > p(0) + p(1) * (1.0 + 1e-12)) {
        throw std::invalid_argument("RigidBody: principal moments violate the triangle inequality");
    }
    j_inv_ = j_.inverse();
    double qn = 0.0;
    for (double c : params.q0) qn += c * c;
    if (!(qn > 0.0) || !std::isfinite(qn)) throw std::invalid_argument("RigidBody: q0 must be a non-zero quaternion");
    for (double w : params.omega0) {
        if (!std::isfinite(w)) throw std::invalid_argument("RigidBody: omega0 must be finite");
    }
}

RigidBodyState RigidBody::initial_state() const {
    RigidBodyState x{params_.q0[0],     params_.q0[1],     params_.q0[2],    params_.q0[3],
                     params_.omega0[0], params_.omega0[1], params_.omega0[2]};
    renormalize(x.data());
    return x;
}

void RigidBody::derivative(const double* x, double* dx) const {
    derivative(x, Eigen::Vector3d::Zero(), dx);
}

void RigidBody::derivative(const double* x, const Eigen::Vector3d& torque_body, double* dx) const {
    const Eigen::Vector3d Q(x[0], x[1], x[2]);
    const double w = x[3];
    const Eigen::Vector3d om(x[4], x[5], x[6]);
    // Kinematics q' = 1/2 Omega(w) q (Shuster 1993) for A(q) inertial -> body.
    const Eigen::Vector3d dQ = 0.5 * (w * om - om.cross(Q));
    const double dw = -0.5 * om.dot(Q);
    // Euler's equations: J w' = -w x (J w) + tau.
    const Eigen::Vector3d dom = j_inv_ * (torque_body - om.cross(j_ * om));
    dx[0] = dQ.x();
    dx[1] = dQ.y();
    dx[2] = dQ.z();
    dx[3] = dw;
    dx[4] = dom.x();
    dx[5] = dom.y();
    dx[6] = dom.z();
}

void RigidBody::renormalize(double* x) {
    const double n = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);
    if (!(n > 0.0) || !std::isfinite(n)) throw std::invalid_argument("RigidBody::renormalize: degenerate quaternion");
    for (int i = 0; i < 4; ++i) x[i] /= n;
}

double RigidBody::kinetic_energy(const double* x) const {
    const Eigen::Vector3d om(x[4], x[5], x[6]);
    return 0.5 * om.dot(j_ * om);
}

Eigen::Vector3d RigidBody::angular_momentum_body(const double* x) const {
    return j_ * Eigen::Vector3d(x[4], x[5], x[6]);
}

}  // namespace environment
