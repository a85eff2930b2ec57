// The aerodynamic torque as the on-board computer models it: the box's faces in the wind of the co-rotating
// atmosphere, free-molecular flow on an absorbing plate (the environment's model, environment/core's
// disturbance_torques.hpp: Wertz 1978 §17.2, Montenbruck & Gill 2000 §3.5.2),
//
//   τ = Σ_k c_k × F_k,   F_k = −½ ρ C_D A_k |v|² max(0, n_k·v̂) v̂  =  −½ ρ C_D A_k max(0, n_k·v) v,
//
// c_k face k's centroid from the centre of mass, n_k its outward normal, A_k its area, v the body's velocity
// relative to the air in body axes. On a box one face of each axis meets the flow (the one whose normal has
// the sign of v along that axis). The geometry is what the computer is told (the uplinked design), the
// density what its table says at its own orbit's altitude (ground/atmosphere_table.hpp) times its own belief
// of the solar activity: neither is the truth's (attitude_estimator/docs/filter.md, "Drag").
// Templated on float/double, no heap, no exceptions.
#pragma once

#include <array>

#include "attitude_estimator/types.hpp"

namespace attitude_estimator {

// The spacecraft's outer box as the computer knows it (all zero: no drag model).
template <class T>
struct DragGeometry {
    std::array<T, 3> size{};            // m: the box's edges along body x, y, z (faces +x, −x, +y, −y, +z, −z)
    std::array<T, 3> centre_of_mass{};  // m: from the box's geometric centre, body axes
    T drag_coefficient = T(0);          // C_D of a face (free-molecular flat plate: about 2.2)
};

// True when the geometry gives a drag model (each edge and C_D positive).
template <class T>
bool has_drag(const DragGeometry<T>& g) noexcept;

// The torque (N m, body axes) at air density `density` (kg/m³) and wind v_body (m/s, body axes: the body's
// velocity relative to the air), and, if d_by_velocity is given, its derivative ∂τ/∂v (row-major).
template <class T>
Vec3<T> drag_torque(const DragGeometry<T>& g, T density, const Vec3<T>& v_body,
                    Matrix3RowMajor<T>* d_by_velocity = nullptr) noexcept;

extern template bool has_drag(const DragGeometry<float>&) noexcept;
extern template bool has_drag(const DragGeometry<double>&) noexcept;
extern template Vec3<float> drag_torque(const DragGeometry<float>&, float, const Vec3<float>&,
                                        Matrix3RowMajor<float>*) noexcept;
extern template Vec3<double> drag_torque(const DragGeometry<double>&, double, const Vec3<double>&,
                                         Matrix3RowMajor<double>*) noexcept;

}  // namespace attitude_estimator
