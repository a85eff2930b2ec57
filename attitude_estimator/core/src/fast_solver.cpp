#include "attitude_estimator/fast_solver.hpp"

#include <cmath>
#include <limits>

#include "wahba_detail.hpp"

namespace attitude_estimator {
namespace {

// Closed-form optimum for exactly two observations (see fast_solver.hpp). prepare() has checked that both
// weights are positive and that neither pair is exactly parallel.
template <class T>
Quaternion<T> solve_two(const detail::PreparedProblem<T>& p) noexcept {
    const Vec3<T>& v1 = p.v[0];
    const Vec3<T>& v2 = p.v[1];
    const Vec3<T>& w1 = p.w[0];
    const Vec3<T>& w2 = p.w[1];
    const Vec3<T> cv = cross(v1, v2);
    const Vec3<T> cw = cross(w1, w2);
    const T sin_v = std::sqrt(squared_norm(cv));  // sin ∠(v1, v2), in (0, 1]
    const T sin_w = std::sqrt(squared_norm(cw));
    const T cos_v = dot(v1, v2);
    const T cos_w = dot(w1, w2);
    const Vec3<T> v3 = scaled(cv, T(1) / sin_v);  // unit normal of the reference plane
    const Vec3<T> w3 = scaled(cw, T(1) / sin_w);  // unit normal of the observation plane
    const Vec3<T> v1p = cross(v3, v1);            // in-plane, 90° from v1 toward v2
    const Vec3<T> w1p = cross(w3, w1);            // in-plane, 90° from w1 toward w2

    // δ = ∠(w1,w2) − ∠(v1,v2) by its cosine and sine; the gain of 000 eq. 9 in the plane is
    // a1 cos φ + a2 cos(φ − δ), largest at (cos φ, sin φ) ∝ (a1 + a2 cos δ, a2 sin δ). The norm of that
    // vector is λmax; it is zero only for a1 = a2 and δ = ±180°, impossible with both angles in (0°, 180°).
    const T cos_d = cos_w * cos_v + sin_w * sin_v;
    const T sin_d = sin_w * cos_v - cos_w * sin_v;
    T c = p.a[0] + p.a[1] * cos_d;
    T s = p.a[1] * sin_d;
    const T inv = T(1) / std::sqrt(c * c + s * s);
    c *= inv;
    s *= inv;

    // A = b1 v1ᵀ + b2 v1pᵀ + w3 v3ᵀ: the frame (v1, v1p, v3) onto (w1, w1p, w3) turned by φ about w3.
    const Vec3<T> b1{c * w1[0] + s * w1p[0], c * w1[1] + s * w1p[1], c * w1[2] + s * w1p[2]};
    const Vec3<T> b2{c * w1p[0] - s * w1[0], c * w1p[1] - s * w1[1], c * w1p[2] - s * w1[2]};
    Matrix3RowMajor<T> a{};
    for (int r = 0; r < 3; ++r) {
        for (int col = 0; col < 3; ++col) {
            a[3 * r + col] = b1[r] * v1[col] + b2[r] * v1p[col] + w3[r] * v3[col];
        }
    }
    return shepperd_quaternion(a);
}

// det(H) for H = K − λI with λ >= λmax, where −H is positive semidefinite: its LDLᵀ factorization (Cholesky
// without square roots) needs no pivoting and is backward stable, so det H = det(−H) = Π d_j comes out to
// rounding of K. A pivot that is not positive means −H is singular to rounding: the determinant is 0
// there (for a semidefinite matrix a vanishing leading minor forces det = 0), which ends the Newton
// iteration.
template <class T>
T det_ldlt(const T (&h)[4][4]) noexcept {
    T l[4][4] = {};
    T d[4] = {};
    T det = T(1);
    for (int j = 0; j < 4; ++j) {
        T dj = -h[j][j];
        for (int k = 0; k < j; ++k) dj -= l[j][k] * l[j][k] * d[k];
        if (!(dj > T(0))) return T(0);
        d[j] = dj;
        det *= dj;
        const T inv = T(1) / dj;
        for (int i = j + 1; i < 4; ++i) {
            T v = -h[i][j];
            for (int k = 0; k < j; ++k) v -= l[i][k] * l[j][k] * d[k];
            l[i][j] = v * inv;
        }
    }
    return det;
}

// Adjugate of a 4x4 matrix from its 2x2 minors (Laplace expansion along the row pairs 0-1 and 2-3): all
// sixteen cofactors for about a hundred multiplications, without branches.
template <class T>
void adjugate4(const T (&m)[4][4], T (&adj)[4][4]) noexcept {
    const T s0 = m[0][0] * m[1][1] - m[1][0] * m[0][1];
    const T s1 = m[0][0] * m[1][2] - m[1][0] * m[0][2];
    const T s2 = m[0][0] * m[1][3] - m[1][0] * m[0][3];
    const T s3 = m[0][1] * m[1][2] - m[1][1] * m[0][2];
    const T s4 = m[0][1] * m[1][3] - m[1][1] * m[0][3];
    const T s5 = m[0][2] * m[1][3] - m[1][2] * m[0][3];
    const T c5 = m[2][2] * m[3][3] - m[3][2] * m[2][3];
    const T c4 = m[2][1] * m[3][3] - m[3][1] * m[2][3];
    const T c3 = m[2][1] * m[3][2] - m[3][1] * m[2][2];
    const T c2 = m[2][0] * m[3][3] - m[3][0] * m[2][3];
    const T c1 = m[2][0] * m[3][2] - m[3][0] * m[2][2];
    const T c0 = m[2][0] * m[3][1] - m[3][0] * m[2][1];
    adj[0][0] = m[1][1] * c5 - m[1][2] * c4 + m[1][3] * c3;
    adj[0][1] = -m[0][1] * c5 + m[0][2] * c4 - m[0][3] * c3;
    adj[0][2] = m[3][1] * s5 - m[3][2] * s4 + m[3][3] * s3;
    adj[0][3] = -m[2][1] * s5 + m[2][2] * s4 - m[2][3] * s3;
    adj[1][0] = -m[1][0] * c5 + m[1][2] * c2 - m[1][3] * c1;
    adj[1][1] = m[0][0] * c5 - m[0][2] * c2 + m[0][3] * c1;
    adj[1][2] = -m[3][0] * s5 + m[3][2] * s2 - m[3][3] * s1;
    adj[1][3] = m[2][0] * s5 - m[2][2] * s2 + m[2][3] * s1;
    adj[2][0] = m[1][0] * c4 - m[1][1] * c2 + m[1][3] * c0;
    adj[2][1] = -m[0][0] * c4 + m[0][1] * c2 - m[0][3] * c0;
    adj[2][2] = m[3][0] * s4 - m[3][1] * s2 + m[3][3] * s0;
    adj[2][3] = -m[2][0] * s4 + m[2][1] * s2 - m[2][3] * s0;
    adj[3][0] = -m[1][0] * c3 + m[1][1] * c1 - m[1][2] * c0;
    adj[3][1] = m[0][0] * c3 - m[0][1] * c1 + m[0][2] * c0;
    adj[3][2] = -m[3][0] * s3 + m[3][1] * s1 - m[3][2] * s0;
    adj[3][3] = m[2][0] * s3 - m[2][1] * s1 + m[2][2] * s0;
}

// Three or more observations: QUEST's λmax, ESOQ's null vector (see fast_solver.hpp).
template <class T>
Quaternion<T> solve_many(const detail::PreparedProblem<T>& p) noexcept {
    const Matrix3RowMajor<T> b = detail::profile_matrix(p);
    // S, σ, Z of 000 eq. 15.
    const T s00 = T(2) * b[0], s11 = T(2) * b[4], s22 = T(2) * b[8];
    const T s01 = b[1] + b[3], s02 = b[2] + b[6], s12 = b[5] + b[7];
    const T sigma = b[0] + b[4] + b[8];
    const T z0 = b[5] - b[7], z1 = b[6] - b[2], z2 = b[1] - b[3];

    // Characteristic equation of K (Shuster & Oh 1981):
    //   f(λ) = (λ² − α)(λ² − β) − γλ + γσ − Zᵀ S² Z = 0,
    //   α = σ² − tr adj S, β = σ² + ZᵀZ, γ = det S + Zᵀ S Z;
    // only its derivative f'(λ) = 4λ³ − 2(α + β)λ − γ is taken from this form (see below).
    const T adj_trace = s00 * s11 - s01 * s01 + s00 * s22 - s02 * s02 + s11 * s22 - s12 * s12;
    const T det_s = s00 * (s11 * s22 - s12 * s12) - s01 * (s01 * s22 - s12 * s02) + s02 * (s01 * s12 - s11 * s02);
    const T sz0 = s00 * z0 + s01 * z1 + s02 * z2;
    const T sz1 = s01 * z0 + s11 * z1 + s12 * z2;
    const T sz2 = s02 * z0 + s12 * z1 + s22 * z2;
    const T zz = z0 * z0 + z1 * z1 + z2 * z2;
    const T alpha = sigma * sigma - adj_trace;
    const T beta = sigma * sigma + zz;
    const T gamma = det_s + z0 * sz0 + z1 * sz1 + z2 * sz2;

    // Newton from λ = Σ a_i = 1 >= λmax: to the right of the largest root f is increasing and convex, so the
    // iterates decrease monotonically to λmax; stop when the step is at rounding level. The cap only bounds
    // the time of a degenerate (double-root) problem, which converges linearly.
    // f itself is evaluated as det(K − λI) by LDLᵀ, not from the expanded quartic: the factorization is
    // backward stable, so λmax comes out to rounding of K even when the next eigenvalue is
    // close (nearly parallel observations), where the expanded coefficients lose digits as ε/gap and the
    // eigenvector as ε/gap² — fatal in float. The expanded derivative only sets the step size.
    constexpr int kMaxNewton = 32;
    const T tol = T(4) * std::numeric_limits<T>::epsilon();
    T lambda = T(1);
    for (int it = 0; it < kMaxNewton; ++it) {
        const T f = det_ldlt({{s00 - sigma - lambda, s01, s02, z0},
                              {s01, s11 - sigma - lambda, s12, z1},
                              {s02, s12, s22 - sigma - lambda, z2},
                              {z0, z1, z2, sigma - lambda}});
        const T df = T(4) * lambda * lambda * lambda - T(2) * (alpha + beta) * lambda - gamma;
        if (!(df > T(0))) break;
        const T step = f / df;
        lambda -= step;
        if (std::fabs(step) <= tol) break;
    }

    // H = K − λmax I. adj(H) = Π_{j>1}(λj − λmax) q qᵀ, so its columns are all multiples of q; take the
    // one with the largest diagonal element (|q_i| largest, >= ½).
    const T h[4][4] = {{s00 - sigma - lambda, s01, s02, z0},
                       {s01, s11 - sigma - lambda, s12, z1},
                       {s02, s12, s22 - sigma - lambda, z2},
                       {z0, z1, z2, sigma - lambda}};
    T adj[4][4];
    adjugate4(h, adj);
    int best = 0;
    for (int i = 1; i < 4; ++i) {
        if (std::fabs(adj[i][i]) > std::fabs(adj[best][best])) best = i;
    }
    const T q[4] = {adj[0][best], adj[1][best], adj[2][best], adj[3][best]};

    // One step of the power method with K + I (eigenvalues λj + 1 in [0, 2], the largest for q): it cannot
    // grow any error component relative to q, and it all but removes the components along eigenvalues near
    // −1 — where the cofactors' rounding goes when the observations are nearly parallel (K's spectrum is then
    // ≈ {1, 1 − gap, −1, −1}). Measured in float on nearly parallel sets: the loss excess over the optimum drops from 4e-6 to 5e-10.
    T r[4];
    for (int i = 0; i < 4; ++i) {
        r[i] = (lambda + T(1)) * q[i];
        for (int k = 0; k < 4; ++k) r[i] += h[i][k] * q[k];
    }
    return {r[0], r[1], r[2], r[3]};
}

}  // namespace

template <class T>
WahbaSolution<T> solve_fast(const ObservationSet<T>& set, const WahbaOptions<T>& options) noexcept {
    const detail::PreparedProblem<T> p = detail::prepare(set, options);
    if (!p.solvable) return {};
    // The closed form needs both weights positive; prepare() only marks a two-observation problem solvable
    // when the single pair has positive weights and is not exactly parallel.
    if (p.n == 2) return detail::finish(p, solve_two(p), /*unit=*/true);
    return detail::finish(p, solve_many(p));
}

template WahbaSolution<float> solve_fast(const ObservationSet<float>&, const WahbaOptions<float>&) noexcept;
template WahbaSolution<double> solve_fast(const ObservationSet<double>&, const WahbaOptions<double>&) noexcept;

}  // namespace attitude_estimator
