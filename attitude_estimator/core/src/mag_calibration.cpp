// The in-flight magnetometer calibration of mag_calibration.hpp. Eigen's fixed-size matrices only (no heap).
#include "attitude_estimator/mag_calibration.hpp"

#include <Eigen/Dense>
#include <cmath>

namespace attitude_estimator {
namespace {

// Fields enter the equations in units of 10 µT: |H| of a few units, so that float keeps the sums' digits.
template <class T>
constexpr T kFieldUnit = T(1e-5);

template <class T>
using VecN = Eigen::Matrix<T, kMagCalUnknowns, 1>;
template <class T>
using MatN = Eigen::Matrix<T, kMagCalUnknowns, kMagCalUnknowns>;

constexpr int packed_index(int i, int j) noexcept {  // i ≤ j, upper triangle row by row
    return i * kMagCalUnknowns - i * (i - 1) / 2 + (j - i);
}

}  // namespace

template <class T>
void mag_calibration_start(MagCalibrationState<T>& s, const MagCalibrationConfig<T>& config) noexcept {
    s = MagCalibrationState<T>{};
    if (!(config.prior_offset_sigma > T(0))) return;
    // c = (I + D) b is b to first order (D of a few thousandths moves a 10 µT offset by tens of nT, well within
    // a ground calibration's residual): the prior b₀ ± σ is information 1/σ² on c at b₀, in the equations' units.
    const T u = kFieldUnit<T>;
    const T sigma = config.prior_offset_sigma / u;
    const T w = T(1) / (sigma * sigma);
    for (int i = 0; i < 3; ++i) {
        const auto k = static_cast<std::size_t>(i);
        s.offset[k] = config.prior_offset[k];
        s.info[static_cast<std::size_t>(packed_index(i, i))] = w;
        s.rhs[k] = w * config.prior_offset[k] / u;
    }
}

template <class T>
Vec3<T> dipole_field_at_sensor(const Vec3<T>& moment, const Vec3<T>& dipole_position,
                               const Vec3<T>& sensor_position) noexcept {
    const T mu0_over_4pi = T(1e-7);  // T m/A
    Vec3<T> r{};
    for (std::size_t i = 0; i < 3; ++i) r[i] = sensor_position[i] - dipole_position[i];
    const T d = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    if (!(d > T(0))) return Vec3<T>{};
    const T m_dot_r = (moment[0] * r[0] + moment[1] * r[1] + moment[2] * r[2]) / d;
    Vec3<T> b{};
    for (std::size_t i = 0; i < 3; ++i) b[i] = mu0_over_4pi * (T(3) * r[i] / d * m_dot_r - moment[i]) / (d * d * d);
    return b;
}

template <class T>
void mag_calibration_offer(MagCalibrationState<T>& s, const Vec3<T>& field, T ref_magnitude,
                           const MagCalibrationConfig<T>& config) noexcept {
    if (s.countdown > 0) {
        --s.countdown;
        return;
    }
    const T u = kFieldUnit<T>;
    const T h[3] = {field[0] / u, field[1] / u, field[2] / u};
    const T h2 = h[0] * h[0] + h[1] * h[1] + h[2] * h[2];
    const T r = ref_magnitude / u;
    const T sigma = config.sigma / u;
    if (!(h2 > T(0)) || !std::isfinite(h2) || !std::isfinite(r) || !(sigma > T(0))) return;
    s.countdown = config.every > 1 ? config.every - 1 : 0;
    // z = 2 Hᵀc − Hᵀ E H − μ; var z ≈ 4 σ² |H|² (the field noise along H).
    const T l[kMagCalUnknowns] = {T(2) * h[0],         T(2) * h[1],  T(2) * h[2],         -h[0] * h[0],
                                  -h[1] * h[1],        -h[2] * h[2], -T(2) * h[0] * h[1], -T(2) * h[0] * h[2],
                                  -T(2) * h[1] * h[2], T(-1)};
    const T z = h2 - r * r;
    const T w = T(1) / (T(4) * sigma * sigma * h2);
    for (int i = 0; i < kMagCalUnknowns; ++i) {
        for (int j = i; j < kMagCalUnknowns; ++j)
            s.info[static_cast<std::size_t>(packed_index(i, j))] += w * l[i] * l[j];
        s.rhs[static_cast<std::size_t>(i)] += w * l[i] * z;
    }
    ++s.equations;
    if (s.equations >= config.min_equations && config.solve_every > 0 && s.equations % config.solve_every == 0)
        mag_calibration_solve(s, config);
}

template <class T>
bool mag_calibration_solve(MagCalibrationState<T>& s, const MagCalibrationConfig<T>& config) noexcept {
    MatN<T> a;
    VecN<T> y;
    for (int i = 0; i < kMagCalUnknowns; ++i) {
        y(i) = s.rhs[static_cast<std::size_t>(i)];
        for (int j = i; j < kMagCalUnknowns; ++j)
            a(i, j) = a(j, i) = s.info[static_cast<std::size_t>(packed_index(i, j))];
    }
    // Scale rows and columns to a unit diagonal: the unknowns differ in size (c, E, μ) and so do their sums.
    VecN<T> d;
    for (int i = 0; i < kMagCalUnknowns; ++i) {
        if (!(a(i, i) > T(0))) return false;
        d(i) = T(1) / std::sqrt(a(i, i));
    }
    MatN<T> l = d.asDiagonal() * a * d.asDiagonal();
    // Cholesky in place (lower), by hand: Eigen's factorizations take a blocked, heap-using path for some
    // right-hand sides on the firmware's compiler. A pivot below 1e-6 (relative to the unit diagonal) means
    // a nearly singular system: too little rotation or magnitude variation seen.
    for (int j = 0; j < kMagCalUnknowns; ++j) {
        T p = l(j, j);
        for (int k = 0; k < j; ++k) p -= l(j, k) * l(j, k);
        if (!(p > T(1e-6))) return false;
        l(j, j) = std::sqrt(p);
        for (int i = j + 1; i < kMagCalUnknowns; ++i) {
            T v = l(i, j);
            for (int k = 0; k < j; ++k) v -= l(i, k) * l(j, k);
            l(i, j) = v / l(j, j);
        }
    }
    // Solves (scaled A) z = rhs by forward and back substitution.
    const auto solve = [&l](VecN<T> z) {
        for (int i = 0; i < kMagCalUnknowns; ++i) {
            for (int k = 0; k < i; ++k) z(i) -= l(i, k) * z(k);
            z(i) /= l(i, i);
        }
        for (int i = kMagCalUnknowns - 1; i >= 0; --i) {
            for (int k = i + 1; k < kMagCalUnknowns; ++k) z(i) -= l(k, i) * z(k);
            z(i) /= l(i, i);
        }
        return z;
    };
    const VecN<T> x = d.asDiagonal() * solve(d.asDiagonal() * y);
    if (!x.allFinite()) return false;
    // The solution's covariance is the inverse normal matrix: refuse it until it is well determined.
    VecN<T> var;
    for (int i = 0; i < kMagCalUnknowns; ++i) var(i) = solve(VecN<T>::Unit(i))(i) * d(i) * d(i);
    const T u = kFieldUnit<T>;
    for (int i = 0; i < 3; ++i)
        if (!(std::sqrt(var(i)) * u <= config.max_offset_sigma)) return false;
    for (int i = 3; i < 9; ++i)
        if (!(std::sqrt(var(i)) <= T(2) * config.max_gain_sigma)) return false;
    Eigen::Matrix<T, 3, 3> e;
    e << x(3), x(6), x(7), x(6), x(4), x(8), x(7), x(8), x(5);
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<T, 3, 3>> eig(Eigen::Matrix<T, 3, 3>::Identity() + e);
    if (eig.info() != Eigen::Success || !(eig.eigenvalues().minCoeff() > T(0))) return false;
    const Eigen::Matrix<T, 3, 3> gain =
        eig.eigenvectors() * eig.eigenvalues().cwiseSqrt().asDiagonal() * eig.eigenvectors().transpose();
    const Eigen::Matrix<T, 3, 1> c(x(0), x(1), x(2));
    const Eigen::Matrix<T, 3, 1> b = gain.inverse() * c * kFieldUnit<T>;
    const T distortion = (gain - Eigen::Matrix<T, 3, 3>::Identity()).cwiseAbs().maxCoeff();
    if (!(distortion <= config.max_distortion) || !(b.norm() <= config.max_offset) || !b.allFinite()) return false;
    for (int i = 0; i < 3; ++i) {
        const auto row = static_cast<std::size_t>(i);
        s.offset[row] = b(i);
        for (int j = 0; j < 3; ++j) s.gain[3 * row + static_cast<std::size_t>(j)] = gain(i, j);
    }
    s.valid = true;
    return true;
}

template <class T>
void mag_calibration_reopen_offset(MagCalibrationState<T>& s, const Vec3<T>& shift) noexcept {
    for (std::size_t i = 0; i < 3; ++i) s.offset[i] += shift[i];
    // The old equations' information on c and μ (which hold the old offset) is marginalized out: the Schur
    // complement keeps what they say about E alone; c and μ start again with no information.
    MatN<T> a;
    VecN<T> y;
    for (int i = 0; i < kMagCalUnknowns; ++i) {
        y(i) = s.rhs[static_cast<std::size_t>(i)];
        for (int j = i; j < kMagCalUnknowns; ++j)
            a(i, j) = a(j, i) = s.info[static_cast<std::size_t>(packed_index(i, j))];
    }
    constexpr int kOut[4] = {0, 1, 2, 9};         // c, μ
    constexpr int kKeep[6] = {3, 4, 5, 6, 7, 8};  // E
    Eigen::Matrix<T, 4, 4> amm;
    Eigen::Matrix<T, 6, 4> akm;
    Eigen::Matrix<T, 4, 1> ym;
    for (int i = 0; i < 4; ++i) {
        ym(i) = y(kOut[i]);
        for (int j = 0; j < 4; ++j) amm(i, j) = a(kOut[i], kOut[j]);
        for (int k = 0; k < 6; ++k) akm(k, i) = a(kKeep[k], kOut[i]);
    }
    const bool invertible = Eigen::LLT<Eigen::Matrix<T, 4, 4>>(amm).info() == Eigen::Success;
    const Eigen::Matrix<T, 4, 4> amm_inv =
        invertible ? Eigen::Matrix<T, 4, 4>(amm.inverse()) : Eigen::Matrix<T, 4, 4>::Zero();
    const Eigen::Matrix<T, 6, 4> gain = akm * amm_inv;
    for (int i = 0; i < kMagCalUnknowns; ++i) {
        for (int j = i; j < kMagCalUnknowns; ++j) {
            int ki = -1, kj = -1;
            for (int k = 0; k < 6; ++k) {
                if (kKeep[k] == i) ki = k;
                if (kKeep[k] == j) kj = k;
            }
            T v = T(0);
            if (ki >= 0 && kj >= 0) v = a(i, j) - gain.row(ki).dot(akm.row(kj));
            s.info[static_cast<std::size_t>(packed_index(i, j))] = v;
        }
        int ki = -1;
        for (int k = 0; k < 6; ++k)
            if (kKeep[k] == i) ki = k;
        s.rhs[static_cast<std::size_t>(i)] = ki >= 0 ? y(i) - gain.row(ki).dot(ym) : T(0);
    }
}

template <class T>
Vec3<T> mag_calibration_apply(const MagCalibrationState<T>& s, const Vec3<T>& field) noexcept {
    // Before a solution: the ground calibration's offset (mag_calibration_start), or identity and zero.
    Vec3<T> out{};
    for (std::size_t i = 0; i < 3; ++i)
        out[i] = s.gain[3 * i] * field[0] + s.gain[3 * i + 1] * field[1] + s.gain[3 * i + 2] * field[2] - s.offset[i];
    return out;
}

#define ATTITUDE_ESTIMATOR_MAG_CAL_INSTANTIATE(T)                                                          \
    template void mag_calibration_start(MagCalibrationState<T>&, const MagCalibrationConfig<T>&) noexcept; \
    template Vec3<T> dipole_field_at_sensor(const Vec3<T>&, const Vec3<T>&, const Vec3<T>&) noexcept;      \
    template void mag_calibration_offer(MagCalibrationState<T>&, const Vec3<T>&, T,                        \
                                        const MagCalibrationConfig<T>&) noexcept;                          \
    template bool mag_calibration_solve(MagCalibrationState<T>&, const MagCalibrationConfig<T>&) noexcept; \
    template Vec3<T> mag_calibration_apply(const MagCalibrationState<T>&, const Vec3<T>&) noexcept;        \
    template void mag_calibration_reopen_offset(MagCalibrationState<T>&, const Vec3<T>&) noexcept;
ATTITUDE_ESTIMATOR_MAG_CAL_INSTANTIATE(float)
ATTITUDE_ESTIMATOR_MAG_CAL_INSTANTIATE(double)
#undef ATTITUDE_ESTIMATOR_MAG_CAL_INSTANTIATE

}  // namespace attitude_estimator
