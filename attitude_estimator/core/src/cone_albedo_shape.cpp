// The cones method's albedo model seen through the panels' angular response (cone_albedo_shape.hpp).
#include "attitude_estimator/cone_albedo_shape.hpp"

#include <algorithm>
#include <cmath>

namespace attitude_estimator {
namespace {

template <class T>
T clamp_unit(T x) noexcept {
    return x < T(-1) ? T(-1) : (x > T(1) ? T(1) : x);
}

constexpr int kCellsCosGamma = 64;  // cells in cos γ over [cos λ, 1] (γ: angle from the nadir)
constexpr int kCellsPhi = 128;      // cells in azimuth over [0, π] (the disc is symmetric about the plane of n, d)

}  // namespace

// cos θ ≥ 1/H: the whole disc is above the face's horizon, G = cos θ; cos θ ≤ −1/H: none of it, G = 0;
// otherwise, with X = √(H² − 1),
//   G = H² (1/2 − asin(X / (H sin θ))/π) + (cos θ acos(−X cot θ) − X √(1 − H² cos²θ))/π.
// G(c) − G(−c) = c (the net flux is linear in the normal); a face at 90° to the nadir still gets
// G(0) ≈ 0.30 at 570 km.
template <class T>
T cone_albedo_shape_cosine(T cos_t, T sin_radius) noexcept {
    const T inv_h = sin_radius;
    if (cos_t >= inv_h) return cos_t;
    if (cos_t <= -inv_h) return T(0);
    constexpr T pi = T(3.14159265358979323846);
    const T h = T(1) / inv_h, h2 = h * h;
    const T x = std::sqrt(h2 - T(1));
    const T sin_t = std::sqrt(std::max(T(0), T(1) - cos_t * cos_t));
    const T a = T(0.5) - std::asin(clamp_unit(x / (h * sin_t))) / pi;
    const T b =
        cos_t * std::acos(clamp_unit(-x * cos_t / sin_t)) - x * std::sqrt(std::max(T(0), T(1) - h2 * cos_t * cos_t));
    return h2 * a + b / pi;
}

// The face normal n = (sin θ, 0, cos θ) in a frame whose z axis is the nadir; a disc element at (γ, φ) is
// ω = (sin γ cos φ, sin γ sin φ, cos γ), so cos ψ = sin θ sin γ cos φ + cos θ cos γ and dΩ = d(cos γ) dφ.
// Accumulated in double whatever T (a configure-time integral; the table is rounded to T at the end).
template <class T>
ConeAlbedoShape<T> cone_albedo_shape_table(const panel_response::Response<T>& response, T sin_radius) noexcept {
    ConeAlbedoShape<T> out;
    if (!(sin_radius > T(0) && sin_radius < T(1))) return out;
    constexpr double pi = 3.14159265358979323846;
    const double sl = static_cast<double>(sin_radius);
    const double cos_l = std::sqrt(1.0 - sl * sl);
    const double du = (1.0 - cos_l) / kCellsCosGamma, dphi = pi / kCellsPhi;
    std::array<double, kCellsPhi> cos_phi{};
    for (int j = 0; j < kCellsPhi; ++j) cos_phi[static_cast<std::size_t>(j)] = std::cos((j + 0.5) * dphi);
    const double norm = 2.0 * du * dphi / (pi * sl * sl);  // both halves of the disc, over π sin²λ
    for (int i = 0; i < kConeAlbedoShapePoints; ++i) {
        const double c = -sl + i * (1.0 + sl) / (kConeAlbedoShapePoints - 1);
        const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
        double sum = 0.0;
        for (int a = 0; a < kCellsCosGamma; ++a) {
            const double u = cos_l + (a + 0.5) * du;
            const double sg = std::sqrt(std::max(0.0, 1.0 - u * u));
            for (double cp : cos_phi) {
                const double cos_psi = s * sg * cp + c * u;
                if (cos_psi > 0.0)
                    sum += static_cast<double>(panel_response::response_from_cos(response, static_cast<T>(cos_psi)));
            }
        }
        out.g[static_cast<std::size_t>(i)] = static_cast<T>(sum * norm);
    }
    out.sin_radius = sin_radius;
    out.valid = true;
    return out;
}

template <class T>
T cone_albedo_shape(const ConeAlbedoShape<T>& table, T cos_t, T sin_radius) noexcept {
    if (!table.valid || table.sin_radius != sin_radius) return cone_albedo_shape_cosine(cos_t, sin_radius);
    if (!(cos_t > -sin_radius)) return T(0);
    const T step = (T(1) + sin_radius) / T(kConeAlbedoShapePoints - 1);
    const T x = std::min((cos_t + sin_radius) / step, T(kConeAlbedoShapePoints - 1));
    const int i = std::min(static_cast<int>(x), kConeAlbedoShapePoints - 2);
    const T f = x - T(i);
    const auto k = static_cast<std::size_t>(i);
    return table.g[k] + f * (table.g[k + 1] - table.g[k]);
}

#define ATTITUDE_ESTIMATOR_CONE_ALBEDO_INSTANTIATE(T)                                                    \
    template T cone_albedo_shape_cosine(T, T) noexcept;                                                  \
    template ConeAlbedoShape<T> cone_albedo_shape_table(const panel_response::Response<T>&, T) noexcept; \
    template T cone_albedo_shape(const ConeAlbedoShape<T>&, T, T) noexcept;
ATTITUDE_ESTIMATOR_CONE_ALBEDO_INSTANTIATE(float)
ATTITUDE_ESTIMATOR_CONE_ALBEDO_INSTANTIATE(double)
#undef ATTITUDE_ESTIMATOR_CONE_ALBEDO_INSTANTIATE

}  // namespace attitude_estimator
