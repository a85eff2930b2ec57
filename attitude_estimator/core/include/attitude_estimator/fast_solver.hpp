// The flight solver for the same problem as the Q-method, with no iteration over a 4x4 eigenproblem and
// no singularity at 180° rotations:
//  - n == 2: closed form. The optimal A maps v1×v2 onto w1×w2 exactly; in that plane it is the rotation
//    by the angle φ with (cos φ, sin φ) ∝ (a1 + a2 cos δ, a2 sin δ), δ = ∠(w1,w2) − ∠(v1,v2), which
//    maximizes the gain a1 cos φ + a2 cos(φ − δ) (000 eq. 9). No trigonometric call.
//  - n >= 3: λmax by Newton's method on det(K − λI) (the QUEST idea, Shuster & Oh 1981), started at
//    Σ a_i = 1 >= λmax where the characteristic quartic is increasing and convex, so the iterates descend
//    monotonically onto λmax. The determinant is evaluated by an LDLᵀ factorization of λI − K (positive
//    semidefinite there, so no pivoting and backward stable), not from the expanded quartic, whose
//    coefficients lose λmax to ε/gap — and the eigenvector to ε/gap² — when observations are nearly
//    parallel. The quaternion is then the null vector of H = K − λmax I taken, as in Mortari's ESOQ, from
//    the column of adj(H) = c q qᵀ with the largest diagonal element: that column has norm |c| max|q_i|
//    >= |c|/2 whatever the rotation angle, so 180° needs no sequential rotations. One power step with K + I
//    then damps rounding along the eigenvectors near λ = −1.
#pragma once

#include "attitude_estimator/wahba.hpp"

namespace attitude_estimator {

template <class T>
WahbaSolution<T> solve_fast(const ObservationSet<T>& set, const WahbaOptions<T>& options = {}) noexcept;

extern template WahbaSolution<float> solve_fast(const ObservationSet<float>&, const WahbaOptions<float>&) noexcept;
extern template WahbaSolution<double> solve_fast(const ObservationSet<double>&, const WahbaOptions<double>&) noexcept;

}  // namespace attitude_estimator
