// The Earth's light on one face as the cones method's albedo model sees it: the Earth as a uniformly bright
// sphere of angular radius λ (sin λ = R_E/(R_E + h)), each element of its visible disc weighed by the
// panels' own angular response R — the cosine for ideal panels, the Kelly cosine for the bundled ones, as
// the environment weighs its albedo for the plant (environment `albedo_response`). The result is G(cos θ),
// θ the angle between the face normal and the nadir, normalized to G(1) = 1 (face squarely toward the Earth):
//   G(cos θ) = 1/(π sin²λ) ∫_disc R(max(0, cos ψ)) dΩ,   ψ the angle between the element and the normal.
// For the cosine law this is the plate-to-sphere view factor in closed form (cone_albedo_shape_cosine);
// for any other law a table over cos θ ∈ [−sin λ, 1] is integrated once (configure time) and interpolated
// on board. Fixed sizes, no heap, no exceptions, float and double. docs/sun_methods.md, "The albedo model".
#pragma once

#include <array>

#include "panel_response/kelly.hpp"

namespace attitude_estimator {

inline constexpr int kConeAlbedoShapePoints = 129;

template <class T>
struct ConeAlbedoShape {
    bool valid = false;                         // false: use the cosine closed form
    T sin_radius = T(0);                        // sin λ the table was built for
    std::array<T, kConeAlbedoShapePoints> g{};  // G at cos θ = −sin λ + i (1 + sin λ)/(N − 1)
};

// Closed form for the cosine law (Howell's differential-plate-to-sphere view factor × H², H = 1/sin λ).
template <class T>
T cone_albedo_shape_cosine(T cos_t, T sin_radius) noexcept;

// The table of G for `response` at `sin_radius` (0 < sin_radius < 1; otherwise an invalid table).
// Midpoint quadrature over the disc, 64 × 128 cells in (cos γ, φ) about the nadir.
template <class T>
ConeAlbedoShape<T> cone_albedo_shape_table(const panel_response::Response<T>& response, T sin_radius) noexcept;

// G at cos θ: the table when it is valid and built for this sin λ, else the cosine closed form.
template <class T>
T cone_albedo_shape(const ConeAlbedoShape<T>& table, T cos_t, T sin_radius) noexcept;

#define ATTITUDE_ESTIMATOR_CONE_ALBEDO_EXTERN(T)                                                                \
    extern template T cone_albedo_shape_cosine(T, T) noexcept;                                                  \
    extern template ConeAlbedoShape<T> cone_albedo_shape_table(const panel_response::Response<T>&, T) noexcept; \
    extern template T cone_albedo_shape(const ConeAlbedoShape<T>&, T, T) noexcept;
ATTITUDE_ESTIMATOR_CONE_ALBEDO_EXTERN(float)
ATTITUDE_ESTIMATOR_CONE_ALBEDO_EXTERN(double)
#undef ATTITUDE_ESTIMATOR_CONE_ALBEDO_EXTERN

}  // namespace attitude_estimator
