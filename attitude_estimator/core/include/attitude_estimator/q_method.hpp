// Davenport's Q-method (000 eq. 13–15, 001 eq. 7–8, 003): the optimal quaternion is the eigenvector of the
// 4x4 matrix K belonging to its largest eigenvalue. Uses Eigen's SelfAdjointEigenSolver on a fixed-size
// 4x4 matrix (no heap). The reference solver: robust everywhere, about ten times slower than the fast one.
#pragma once

#include "attitude_estimator/wahba.hpp"

namespace attitude_estimator {

template <class T>
WahbaSolution<T> solve_q_method(const ObservationSet<T>& set, const WahbaOptions<T>& options = {}) noexcept;

extern template WahbaSolution<float> solve_q_method(const ObservationSet<float>&, const WahbaOptions<float>&) noexcept;
extern template WahbaSolution<double> solve_q_method(const ObservationSet<double>&,
                                                     const WahbaOptions<double>&) noexcept;

}  // namespace attitude_estimator
