// Internal to the core: what both Wahba solvers do before and after solving — normalize vectors and
// weights, judge validity, and turn a quaternion into the full solution with the loss of 000 eq. 8.
#pragma once

#include <cmath>
#include <cstddef>

#include "attitude_estimator/attitude_matrix.hpp"
#include "attitude_estimator/vec3_math.hpp"
#include "attitude_estimator/wahba.hpp"

namespace attitude_estimator::detail {

template <class T>
struct PreparedProblem {
    std::size_t n = 0;
    std::array<Vec3<T>, kMaxObservations> v{};  // unit reference vectors
    std::array<Vec3<T>, kMaxObservations> w{};  // unit observed vectors
    std::array<T, kMaxObservations> a{};        // weights, Σ a = 1
    bool solvable = false;                      // numbers usable and not all pairs exactly parallel
    bool separated = false;                     // some pair separated by more than the option's angle
};

template <class T>
inline bool normalize_into(const Vec3<T>& in, Vec3<T>& out) noexcept {
    const T n2 = squared_norm(in);
    // !(n2 > 0) also rejects NaN; isfinite rejects infinities (whose square overflows to inf).
    if (!(n2 > T(0)) || !std::isfinite(n2)) return false;
    out = scaled(in, T(1) / std::sqrt(n2));
    return true;
}

template <class T>
inline PreparedProblem<T> prepare(const ObservationSet<T>& set, const WahbaOptions<T>& options) noexcept {
    PreparedProblem<T> p;
    if (set.count < 2 || set.count > kMaxObservations) return p;
    p.n = set.count;
    T sum = T(0);
    for (std::size_t i = 0; i < p.n; ++i) {
        const Observation<T>& o = set.items[i];
        if (!normalize_into(o.ref, p.v[i]) || !normalize_into(o.obs, p.w[i])) return p;
        if (!(o.weight >= T(0)) || !std::isfinite(o.weight)) return p;
        p.a[i] = o.weight;
        sum += o.weight;
    }
    if (!(sum > T(0)) || !std::isfinite(sum)) return p;
    const T inv = T(1) / sum;  // weights normalized to Σ a_i = 1 (000 eq. 8)
    for (std::size_t i = 0; i < p.n; ++i) p.a[i] *= inv;

    // Validity: the first pair (i, j) with positive weights found separated in both frames ends the search,
    // so the usual sun/field pair costs two cross products.
    const T min2 = options.min_separation_sin * options.min_separation_sin;
    bool any_nonparallel = false;
    for (std::size_t i = 0; i < p.n && !p.separated; ++i) {
        if (p.a[i] <= T(0)) continue;
        for (std::size_t j = i + 1; j < p.n; ++j) {
            if (p.a[j] <= T(0)) continue;
            const T sv = squared_norm(cross(p.v[i], p.v[j]));
            const T sw = squared_norm(cross(p.w[i], p.w[j]));
            if (sv > T(0) && sw > T(0)) any_nonparallel = true;
            if (sv >= min2 && sw >= min2) {
                p.separated = true;
                break;
            }
        }
    }
    p.solvable = any_nonparallel;
    return p;
}

// L(A) = ½ Σ a_i |w_i − A v_i|²                                          (000 eq. 8)
// Evaluated as written (not as 1 − g of eq. 9) so small losses keep their digits in float.
template <class T>
inline T wahba_loss(const PreparedProblem<T>& p, const Matrix3RowMajor<T>& a) noexcept {
    T loss = T(0);
    for (std::size_t i = 0; i < p.n; ++i) {
        const Vec3<T> av = multiply(a, p.v[i]);
        const Vec3<T> d{p.w[i][0] - av[0], p.w[i][1] - av[1], p.w[i][2] - av[2]};
        loss += p.a[i] * squared_norm(d);
    }
    return T(0.5) * loss;
}

// From an either-sign quaternion to the full solution. `unit` says q already has unit norm to rounding
// (Shepperd's output from an orthonormal matrix), which saves a square root and a division on the
// critical path of the two-observation solver; otherwise q is normalized here (000 eq. 12).
template <class T>
inline WahbaSolution<T> finish(const PreparedProblem<T>& p, Quaternion<T> q, bool unit = false) noexcept {
    WahbaSolution<T> s;
    const T n2 = q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w;
    if (!(n2 > T(0)) || !std::isfinite(n2)) return s;                         // identity, invalid
    const T k = (q.w < T(0) ? T(-1) : T(1)) / (unit ? T(1) : std::sqrt(n2));  // w >= 0
    q = {q.x * k, q.y * k, q.z * k, q.w * k};
    s.q = q;
    s.a = attitude_matrix(q);
    s.loss = wahba_loss(p, s.a);
    s.valid = p.separated;
    return s;
}

// B = Σ a_i w_i v_iᵀ, the attitude profile matrix, from which S, σ and Z of 000 eq. 15 are taken.
template <class T>
inline Matrix3RowMajor<T> profile_matrix(const PreparedProblem<T>& p) noexcept {
    Matrix3RowMajor<T> b{};
    for (std::size_t i = 0; i < p.n; ++i) {
        for (int r = 0; r < 3; ++r) {
            const T aw = p.a[i] * p.w[i][r];
            for (int c = 0; c < 3; ++c) b[3 * r + c] += aw * p.v[i][c];
        }
    }
    return b;
}

}  // namespace attitude_estimator::detail
