// The panels' heat balance (face_thermal.hpp) against closed forms and an independent quadrature.
#include "panel_thermal/face_thermal.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace panel_thermal {
namespace {

constexpr double pi = std::numbers::pi;

// The view factor from its definition, F = ∫ cos θ₁ cos θ₂ / (π s²) dA over the part of the sphere the
// plate sees (in front of the plate and on the near side of the sphere), by a midpoint rule in the
// polar angle about the sub-satellite point and the azimuth: independent of the closed form.
double view_factor_by_quadrature(double theta, double h) {
    const double gamma_max = std::acos(1.0 / h);  // the horizon
    const int n_gamma = 800, n_psi = 800;
    const Eigen::Vector3d sat(0, 0, h);                                  // sphere of radius 1 at the origin
    const Eigen::Vector3d normal(std::sin(theta), 0, -std::cos(theta));  // θ from the nadir (−z)
    double f = 0.0;
    for (int i = 0; i < n_gamma; ++i) {
        const double g = (i + 0.5) * gamma_max / n_gamma;
        for (int j = 0; j < n_psi; ++j) {
            const double p = (j + 0.5) * 2.0 * pi / n_psi;
            const Eigen::Vector3d point(std::sin(g) * std::cos(p), std::sin(g) * std::sin(p), std::cos(g));
            const Eigen::Vector3d d = point - sat;
            const double s2 = d.squaredNorm(), s = std::sqrt(s2);
            const double cos1 = normal.dot(d) / s, cos2 = -point.dot(d) / s;
            if (cos1 <= 0.0 || cos2 <= 0.0) continue;
            f += cos1 * cos2 / (pi * s2) * std::sin(g) * (gamma_max / n_gamma) * (2.0 * pi / n_psi);
        }
    }
    return f;
}

TEST(PanelThermalCore, ViewFactorToTheEarthMatchesItsDefinition) {
    const double h = (6378137.0 + 570e3) / 6378137.0;  // the bundled 570 km orbit
    for (double theta_deg : {0.0, 20.0, 50.0, 70.0, 90.0, 110.0, 130.0, 160.0}) {
        const double theta = theta_deg * pi / 180.0;
        EXPECT_NEAR(plate_sphere_view_factor(std::cos(theta), h), view_factor_by_quadrature(theta, h), 2e-4)
            << theta_deg << " deg from nadir";
    }
    EXPECT_NEAR(plate_sphere_view_factor(1.0, h), 1.0 / (h * h), 1e-15);  // nadir face: (R/r)² = 0.8427
    EXPECT_EQ(plate_sphere_view_factor(-1.0, h), 0.0);                    // zenith face
}

// A face squarely toward the sun, nothing else: α S = ε σ T⁴ at equilibrium, T = (α S / (ε σ))^(1/4):
// 0.9 · 1367 / (0.85 · 5.670374419e-8) = 2.55258e10 K⁴, T = 399.71 K (hand calculation).
TEST(PanelThermalCore, SunlitFaceSettlesAtItsRadiativeEquilibrium) {
    ThermalParams p;
    p.inner_conductance = 0.0;
    p.earth_infrared = 0.0;
    const auto q = face_heat_input(p, Eigen::Vector3d(1, 0, 0), 1367.0, Eigen::Vector3d(0, 0, -1), 1.1, 0.0);
    EXPECT_DOUBLE_EQ(q[0], 0.9 * 1367.0);  // +x faces the sun
    EXPECT_EQ(q[1], 0.0);                  // −x: no sun (and the Earth's infrared and albedo are off here)
    std::array<double, 6> t{};
    t.fill(300.0);
    for (int k = 0; k < 200000; ++k) {  // explicit Euler, 1 s steps over 55 h: settled (τ ≈ 2500 / 13 s)
        const auto dt = face_temperature_derivative(p, t, q);
        for (std::size_t i = 0; i < 6; ++i) t[i] += dt[i];
    }
    EXPECT_NEAR(t[0], 399.71, 0.01);
}

// In the dark with no other exchange, C dT/dt = −ε σ T⁴: T(t) = (T₀⁻³ + 3 ε σ t / C)^(−1/3).
TEST(PanelThermalCore, FaceInTheDarkCoolsAsTheClosedForm) {
    ThermalParams p;
    p.inner_conductance = 0.0;
    const std::array<double, 6> dark{};
    std::array<double, 6> t{};
    t.fill(350.0);
    const double h = 0.5, end = 2100.0;                      // 35 min: a long eclipse
    for (double time = 0.0; time < end - 1e-9; time += h) {  // classical RK4 in the test
        auto f = [&](const std::array<double, 6>& x) { return face_temperature_derivative(p, x, dark); };
        auto add = [](std::array<double, 6> a, const std::array<double, 6>& b, double s) {
            for (std::size_t i = 0; i < 6; ++i) a[i] += s * b[i];
            return a;
        };
        const auto k1 = f(t), k2 = f(add(t, k1, h / 2)), k3 = f(add(t, k2, h / 2)), k4 = f(add(t, k3, h));
        for (std::size_t i = 0; i < 6; ++i) t[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    }
    const double exact =
        std::pow(std::pow(350.0, -3.0) + 3.0 * 0.85 * stefan_boltzmann * end / p.areal_heat_capacity, -1.0 / 3.0);
    EXPECT_NEAR(t[0], exact, 1e-6);
    EXPECT_NEAR(exact, 190.44, 0.01);  // hand calculation: 350 K → 190.4 K in 35 min, alone in the dark
}

}  // namespace
}  // namespace panel_thermal
