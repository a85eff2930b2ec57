#include "panel_thermal/face_thermal.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace panel_thermal {

double plate_sphere_view_factor(double cos_theta, double h_ratio) {
    if (!(h_ratio > 1.0) || !std::isfinite(h_ratio)) throw std::invalid_argument("view factor: h_ratio must be > 1");
    const double c = std::clamp(cos_theta, -1.0, 1.0);
    const double h2 = h_ratio * h_ratio;
    // The disc's angular radius λ: sin λ = 1/h. Whole disc in front while θ ≤ π/2 − λ, i.e. cos θ ≥ 1/h.
    if (c >= 1.0 / h_ratio) return c / h2;
    if (c <= -1.0 / h_ratio) return 0.0;
    const double s = std::sqrt(std::max(0.0, 1.0 - c * c));  // sin θ > 0 here
    const double x = std::sqrt(h2 - 1.0);
    const double term1 = 0.5 - std::asin(std::min(1.0, x / (h_ratio * s))) / std::numbers::pi;
    const double term2 =
        (c * std::acos(std::clamp(-x * c / s, -1.0, 1.0)) - x * std::sqrt(std::max(0.0, 1.0 - h2 * c * c))) /
        (std::numbers::pi * h2);
    return std::max(0.0, term1 + term2);
}

std::array<double, 6> face_heat_input(const ThermalParams& p, const Eigen::Vector3d& sun_body, double irradiance,
                                      const Eigen::Vector3d& nadir_body, double h_ratio, double albedo_source) {
    std::array<double, 6> q{};
    for (int k = 0; k < 6; ++k) {
        const int axis = k / 2;
        const double sign = k % 2 == 0 ? 1.0 : -1.0;
        const double cos_sun = sign * sun_body(axis);
        const double f = plate_sphere_view_factor(sign * nadir_body(axis), h_ratio);
        q[static_cast<std::size_t>(k)] = p.absorptance * (irradiance * std::max(0.0, cos_sun) + albedo_source * f) +
                                         p.emissivity * p.earth_infrared * f;
    }
    return q;
}

std::array<double, 6> face_temperature_derivative(const ThermalParams& p, const std::array<double, 6>& temperature,
                                                  const std::array<double, 6>& heat_input) {
    std::array<double, 6> dt{};
    for (std::size_t k = 0; k < 6; ++k) {
        const double t = temperature[k];
        const double t2 = t * t;
        const double emitted = p.emissivity * stefan_boltzmann * t2 * t2;
        dt[k] = (heat_input[k] - emitted - p.inner_conductance * (t - p.body_temperature)) / p.areal_heat_capacity;
    }
    return dt;
}

}  // namespace panel_thermal
