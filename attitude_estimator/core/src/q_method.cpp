#include "attitude_estimator/q_method.hpp"

#include <Eigen/Eigenvalues>

#include "wahba_detail.hpp"

namespace attitude_estimator {

template <class T>
WahbaSolution<T> solve_q_method(const ObservationSet<T>& set, const WahbaOptions<T>& options) noexcept {
    const detail::PreparedProblem<T> p = detail::prepare(set, options);
    if (!p.solvable) return {};
    const Matrix3RowMajor<T> b = detail::profile_matrix(p);

    // K = [[S − σI, Z], [Zᵀ, σ]] with S = B + Bᵀ, σ = tr B, Z = Σ a_i w_i × v_i   (000 eq. 15)
    // (the printed Z beside the lower-left block is its transpose: K is symmetric). With B_rc = Σ a w_r v_c,
    // (w × v)_x = B_12 − B_21 etc. Scalar-last order [Q; q] as in eq. 10.
    const T sigma = b[0] + b[4] + b[8];
    const T z[3] = {b[5] - b[7], b[6] - b[2], b[1] - b[3]};
    Eigen::Matrix<T, 4, 4> k;
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) k(r, c) = b[3 * r + c] + b[3 * c + r];
        k(r, r) -= sigma;
        k(r, 3) = z[r];
        k(3, r) = z[r];
    }
    k(3, 3) = sigma;

    // K q = λmax q (000 eq. 14). Fixed-size matrices: the solver lives on the stack.
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<T, 4, 4>> eig(k, Eigen::ComputeEigenvectors);
    if (eig.info() != Eigen::Success) return {};
    const auto q = eig.eigenvectors().col(3);  // eigenvalues come sorted in increasing order
    return detail::finish(p, Quaternion<T>{q(0), q(1), q(2), q(3)});
}

template WahbaSolution<float> solve_q_method(const ObservationSet<float>&, const WahbaOptions<float>&) noexcept;
template WahbaSolution<double> solve_q_method(const ObservationSet<double>&, const WahbaOptions<double>&) noexcept;

}  // namespace attitude_estimator
