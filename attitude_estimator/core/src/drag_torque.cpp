#include "attitude_estimator/drag_torque.hpp"

#include <cmath>

namespace attitude_estimator {

template <class T>
bool has_drag(const DragGeometry<T>& g) noexcept {
    return g.size[0] > T(0) && g.size[1] > T(0) && g.size[2] > T(0) && g.drag_coefficient > T(0);
}

// With K = ½ ρ C_D and u_k = A_k (n_k·v) for the faces that meet the flow (|v|² cos α v̂ = (n·v) v), τ = −K Σ u_k
// [c_k×] v and
//   ∂τ/∂v = −K ( Σ A_k [c_k×] v n_kᵀ + Σ u_k [c_k×] )
// (the step in u_k where a face turns edge-on to the flow has zero height: u_k is continuous).
template <class T>
Vec3<T> drag_torque(const DragGeometry<T>& g, T density, const Vec3<T>& v, Matrix3RowMajor<T>* d) noexcept {
    Vec3<T> torque{};
    if (d != nullptr) *d = Matrix3RowMajor<T>{};
    if (!has_drag(g) || !(density > T(0))) return torque;
    const T k = T(0.5) * density * g.drag_coefficient;
    Vec3<T> sum_cv{};            // Σ u_k c_k × v
    Matrix3RowMajor<T> sum_c{};  // Σ u_k [c_k×] + Σ A_k (c_k × v) n_kᵀ
    for (int a = 0; a < 3; ++a) {
        if (v[a] == T(0)) continue;  // both faces of this axis edge-on
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        const T area = g.size[b] * g.size[c];
        const T side = v[a] > T(0) ? T(1) : T(-1);  // the face meeting the flow: normal side·e_a
        Vec3<T> centroid{-g.centre_of_mass[0], -g.centre_of_mass[1], -g.centre_of_mass[2]};
        centroid[a] += T(0.5) * g.size[a] * side;
        const T u = area * side * v[a];  // A (n·v) > 0
        const Vec3<T> cv{centroid[1] * v[2] - centroid[2] * v[1], centroid[2] * v[0] - centroid[0] * v[2],
                         centroid[0] * v[1] - centroid[1] * v[0]};
        for (int i = 0; i < 3; ++i) sum_cv[i] += u * cv[i];
        if (d != nullptr) {
            // u [c×]
            sum_c[1] += -u * centroid[2];
            sum_c[2] += u * centroid[1];
            sum_c[3] += u * centroid[2];
            sum_c[5] += -u * centroid[0];
            sum_c[6] += -u * centroid[1];
            sum_c[7] += u * centroid[0];
            // A (c × v) n_kᵀ: n_k = side e_a, so column a only
            for (int i = 0; i < 3; ++i) sum_c[3 * i + a] += area * side * cv[i];
        }
    }
    for (int i = 0; i < 3; ++i) torque[i] = -k * sum_cv[i];
    if (d != nullptr)
        for (int i = 0; i < 9; ++i) (*d)[i] = -k * sum_c[i];
    return torque;
}

template bool has_drag(const DragGeometry<float>&) noexcept;
template bool has_drag(const DragGeometry<double>&) noexcept;
template Vec3<float> drag_torque(const DragGeometry<float>&, float, const Vec3<float>&,
                                 Matrix3RowMajor<float>*) noexcept;
template Vec3<double> drag_torque(const DragGeometry<double>&, double, const Vec3<double>&,
                                  Matrix3RowMajor<double>*) noexcept;

}  // namespace attitude_estimator
