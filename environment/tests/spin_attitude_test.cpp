#include <gtest/gtest.h>

#include <cmath>

#include "environment/attitude.hpp"
#include "environment/spin_attitude.hpp"

namespace env = environment;

namespace {
// Seed 000, section 4 / eq. 5, typed here independently of the library.
Eigen::Vector3d seed_formula(double t, double phi0, double theta0) {
    const double phi = phi0 + 1.26 * t, theta = theta0 + 6.28 * t;
    return {std::sin(phi) * std::sin(theta), std::cos(phi) * std::sin(theta), std::cos(theta)};
}
}  // namespace

TEST(EnvironmentCoreSpin, ReproducesSeedSunDirectionTo1e12) {
    env::SpinParams p;  // defaults: phi_dot = 1.26, theta_dot = 6.28 rad/s
    p.phi0 = 0.3;
    p.theta0 = -0.7;
    const Eigen::Vector3d sun_eci = Eigen::Vector3d(-0.38, 0.85, 0.37).normalized();
    const env::SpinAttitude spin(p, sun_eci);
    for (double t : {0.0, 0.001, 0.25, 1.0, 3.7, 10.0, 59.9, 100.0}) {
        const Eigen::Vector3d expected = seed_formula(t, 0.3, -0.7);
        const Eigen::Vector3d by_matrix = spin.attitude_matrix(t) * sun_eci;
        const Eigen::Vector3d by_quaternion = env::attitude_matrix(spin.quaternion(t)) * sun_eci;
        EXPECT_LT((by_matrix - expected).norm(), 1e-12) << "t = " << t;
        EXPECT_LT((by_quaternion - expected).norm(), 1e-12) << "t = " << t;
    }
}

TEST(EnvironmentCoreSpin, AngularVelocityMatchesAttitudeDerivative) {
    // Kinematics dA/dt = -[w x] A; central difference of the attitude, independent of the analytic w.
    env::SpinParams p;
    const env::SpinAttitude spin(p, Eigen::Vector3d(1.0, 0.2, -0.4));
    const double h = 1e-5;
    for (double t : {0.0, 0.4, 2.2, 17.0}) {
        const Eigen::Matrix3d dA = (spin.attitude_matrix(t + h) - spin.attitude_matrix(t - h)) / (2.0 * h);
        const Eigen::Matrix3d W = -dA * spin.attitude_matrix(t).transpose();
        const Eigen::Vector3d w_fd(W(2, 1), W(0, 2), W(1, 0));
        EXPECT_LT((w_fd - spin.angular_velocity_body(t)).norm(), 1e-7) << "t = " << t;
        // |w|^2 = theta_dot^2 + phi_dot^2 (hand: the two rotation axes are orthogonal).
        EXPECT_NEAR(spin.angular_velocity_body(t).norm(), std::hypot(1.26, 6.28), 1e-12);
    }
}

TEST(EnvironmentCoreSpin, RejectsZeroSunDirection) {
    EXPECT_THROW(env::SpinAttitude(env::SpinParams{}, Eigen::Vector3d::Zero()), std::invalid_argument);
}
