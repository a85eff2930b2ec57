// Shared by the estimator core tests: the scalar types under test, tolerances per type, random problems
// and an attitude-angle metric. Truth matrices come from Eigen (an independent implementation), never from
// the code under test.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <string>
#include <utility>

#include "attitude_estimator/types.hpp"
#include "ordered_draws.hpp"

namespace attitude_estimator::test {

using Scalars = ::testing::Types<float, double>;

struct ScalarName {
    template <class T>
    static std::string GetName(int) {
        return std::is_same_v<T, float> ? "float" : "double";
    }
};

// Tolerance by scalar type: float for the DSP build, double for the host.
template <class T>
constexpr double tol(double for_float, double for_double) {
    return std::is_same_v<T, float> ? for_float : for_double;
}

// Our quaternion of an attitude matrix: A(q) of attitude_matrix.hpp is Eigen's rotation matrix of
// (w, x, y, z) transposed, so Eigen's quaternion of Aᵀ has our components; and back.
template <class T>
Quaternion<T> quaternion_of(const Eigen::Matrix3d& a) {
    const Eigen::Quaterniond e(Eigen::Matrix3d(a.transpose()));
    return {static_cast<T>(e.x()), static_cast<T>(e.y()), static_cast<T>(e.z()), static_cast<T>(e.w())};
}
template <class T>
Eigen::Matrix3d matrix_of(const Quaternion<T>& q) {
    return Eigen::Quaterniond(q.w, q.x, q.y, q.z).normalized().toRotationMatrix().transpose();
}

template <class T>
Vec3<T> to_vec(const Eigen::Vector3d& v) {
    return {static_cast<T>(v.x()), static_cast<T>(v.y()), static_cast<T>(v.z())};
}

template <class T>
Eigen::Matrix3d to_eigen(const Matrix3RowMajor<T>& a) {
    Eigen::Matrix3d m;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) m(r, c) = static_cast<double>(a[3 * r + c]);
    return m;
}

// The tests' reference rigid-body motion, independent of the filter's propagation: `steps` RK4 steps of
// `h` on the pair (ω, A) with ω̇ = wdot(ω, A) and Ȧ = −[ω×]A.
template <class Wdot>
void rk4_rate_and_attitude(Eigen::Vector3d& w, Eigen::Matrix3d& a, double h, int steps, Wdot wdot) {
    auto skew = [](const Eigen::Vector3d& v) {
        Eigen::Matrix3d m;
        m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
        return m;
    };
    auto f = [&](const Eigen::Vector3d& wv, const Eigen::Matrix3d& av) {
        return std::make_pair(Eigen::Vector3d(wdot(wv, av)), Eigen::Matrix3d(-skew(wv) * av));
    };
    for (int k = 0; k < steps; ++k) {
        const auto k1 = f(w, a);
        const auto k2 = f(w + h / 2 * k1.first, a + h / 2 * k1.second);
        const auto k3 = f(w + h / 2 * k2.first, a + h / 2 * k2.second);
        const auto k4 = f(w + h * k3.first, a + h * k3.second);
        w += h / 6 * (k1.first + 2 * k2.first + 2 * k3.first + k4.first);
        a += h / 6 * (k1.second + 2 * k2.second + 2 * k3.second + k4.second);
    }
}

// Rotation angle (rad) of A1 A2ᵀ, i.e. the attitude difference, computed in double through Eigen's own
// matrix-to-quaternion conversion, in the atan2 form that keeps small angles accurate.
inline double attitude_angle(const Eigen::Matrix3d& a1, const Eigen::Matrix3d& a2) {
    Eigen::Matrix3d d = a1 * a2.transpose();
    // Re-orthonormalize float results so the metric measures direction, not rounding of the norm.
    Eigen::JacobiSVD<Eigen::Matrix3d> svd(d, Eigen::ComputeFullU | Eigen::ComputeFullV);
    d = svd.matrixU() * svd.matrixV().transpose();
    const Eigen::Quaterniond q(d);
    return 2.0 * std::atan2(q.vec().norm(), std::fabs(q.w()));
}

class Random {
public:
    explicit Random(std::uint64_t seed) : gen_(seed) {}
    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(gen_); }
    double gauss() { return std::normal_distribution<double>(0.0, 1.0)(gen_); }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(gen_); }
    // Three draws in ordered_draws' order, not inside one call's arguments (whose order GCC and clang differ
    // on): gauss() each, a fresh distribution per draw as always.
    Eigen::Vector3d gauss3() {
        auto draw = [this](std::mt19937_64&) { return gauss(); };
        return ordered_draws::vector3(draw, gen_);
    }
    Eigen::Vector3d unit() {
        Eigen::Vector3d v;
        do {
            v = gauss3();
        } while (v.norm() < 1e-3);
        return v.normalized();
    }
    // A rotation matrix of the given angle about a random axis (Eigen's AngleAxis, independent of the core).
    Eigen::Matrix3d rotation(double angle) { return Eigen::AngleAxisd(angle, unit()).toRotationMatrix(); }
    Eigen::Matrix3d rotation() { return rotation(uniform(0.0, M_PI)); }

private:
    std::mt19937_64 gen_;
};

// exp(−[ω×] t): the body frame of a constant-rate tumble ω turned over t (Eigen's AngleAxis, not the core's).
inline Eigen::Matrix3d turn(const Eigen::Vector3d& omega, double t) {
    const double n = omega.norm();
    if (n == 0.0) return Eigen::Matrix3d::Identity();
    return Eigen::AngleAxisd(-n * t, omega / n).toRotationMatrix();
}

// A sensor error that persists: per axis a stationary first-order Gauss–Markov process of 1σ `sigma`,
// correlated over `tau` (s), sampled every `dt` (s); it starts from its stationary distribution.
class GaussMarkov3 {
public:
    GaussMarkov3(double sigma, double tau, double dt, Random& rng)
        : sigma_(sigma), phi_(std::exp(-dt / tau)), value_(sigma * rng.gauss3()) {}
    // The next sample; axis i draws before axis i + 1.
    const Eigen::Vector3d& step(Random& rng) {
        for (int i = 0; i < 3; ++i) value_(i) = phi_ * value_(i) + std::sqrt(1 - phi_ * phi_) * sigma_ * rng.gauss();
        return value_;
    }

private:
    double sigma_;
    double phi_;
    Eigen::Vector3d value_;
};

}  // namespace attitude_estimator::test
