// Wahba's problem as the seeds state it (000 eq. 7–9): find the attitude matrix A minimizing
//   L(A) = ½ Σ a_i |w_i − A v_i|²,  a_i >= 0, Σ a_i = 1,
// for reference vectors v_i (inertial) and observed vectors w_i (body). Problem and solution types and the
// solver switch; the solvers themselves are in q_method.hpp and fast_solver.hpp.
#pragma once

#include <cstddef>

#include "attitude_estimator/types.hpp"

namespace attitude_estimator {

template <class T>
struct Observation {
    Vec3<T> ref{};    // v_i, any nonzero length (normalized by the solver)
    Vec3<T> obs{};    // w_i, any nonzero length (normalized by the solver)
    T weight = T(1);  // a_i >= 0, any scale (the solver divides by the sum)
};

template <class T>
struct ObservationSet {
    std::array<Observation<T>, kMaxObservations> items{};
    std::size_t count = 0;  // 2 … kMaxObservations are solvable

    // Appends one observation; returns false (and changes nothing) when full.
    constexpr bool add(const Vec3<T>& ref, const Vec3<T>& obs, T weight) noexcept {
        if (count >= kMaxObservations) return false;
        items[count++] = Observation<T>{ref, obs, weight};
        return true;
    }
};

// sin(5°): two directions closer than 5° (or than 5° to antiparallel) do not fix the rotation about
// them well — a measurement error δ turns into an attitude error of about δ/sin(angle), ×11 at 5°.
template <class T>
inline constexpr T kDefaultMinSeparationSin = T(0.08715574274765817);

template <class T>
struct WahbaOptions {
    // The solution is `valid` only when some pair i, j has both |v_i × v_j| and |w_i × w_j| at least this
    // (unit vectors), i.e. both pairs are more than asin(min_separation_sin) from parallel/antiparallel.
    T min_separation_sin = kDefaultMinSeparationSin<T>;
};

template <class T>
struct WahbaSolution {
    Quaternion<T> q{};                                // optimal quaternion, w >= 0
    Matrix3RowMajor<T> a{1, 0, 0, 0, 1, 0, 0, 0, 1};  // A(q), row-major (000 eq. 11)
    T loss = T(0);                                    // L(A) of 000 eq. 8 with the normalized weights and unit vectors
    bool valid = false;
};
// When the problem cannot be solved at all (count outside 2…6, a zero or non-finite vector, negative or
// all-zero weights, all observation pairs exactly parallel) the solution is the identity, loss 0,
// valid == false. When it can be solved but no pair is separated enough, the attitude is returned with
// valid == false.

enum class SolverKind {
    qmethod,  // Q-method: largest eigenpair of K by Eigen's symmetric eigensolver (reference)
    fast,     // closed form for two observations, QUEST λmax + ESOQ null vector for more (flight)
};

template <class T>
WahbaSolution<T> solve_wahba(const ObservationSet<T>& set, SolverKind kind,
                             const WahbaOptions<T>& options = {}) noexcept;

extern template WahbaSolution<float> solve_wahba(const ObservationSet<float>&, SolverKind,
                                                 const WahbaOptions<float>&) noexcept;
extern template WahbaSolution<double> solve_wahba(const ObservationSet<double>&, SolverKind,
                                                  const WahbaOptions<double>&) noexcept;

}  // namespace attitude_estimator
