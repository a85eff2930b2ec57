#include "attitude_estimator/wahba.hpp"

#include "attitude_estimator/fast_solver.hpp"
#include "attitude_estimator/q_method.hpp"

namespace attitude_estimator {

template <class T>
WahbaSolution<T> solve_wahba(const ObservationSet<T>& set, SolverKind kind, const WahbaOptions<T>& options) noexcept {
    return kind == SolverKind::qmethod ? solve_q_method(set, options) : solve_fast(set, options);
}

template WahbaSolution<float> solve_wahba(const ObservationSet<float>&, SolverKind,
                                          const WahbaOptions<float>&) noexcept;
template WahbaSolution<double> solve_wahba(const ObservationSet<double>&, SolverKind,
                                           const WahbaOptions<double>&) noexcept;

}  // namespace attitude_estimator
