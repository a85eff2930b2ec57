#pragma once
// The temperature of each body-mounted panel: a thin plate that absorbs the direct sun, the Earth's
// albedo and the Earth's infrared on its outer side, radiates from it, and exchanges heat with the body
// through its inner side (a conductance to a body held at a fixed temperature):
//
//   C dT/dt = α (E_sun max(0, n·s) + E_albedo) + ε E_IR − ε σ T⁴ − h (T − T_body)
//
// per unit area (C areal heat capacity, α solar absorptance, ε infrared emissivity, which is also the
// infrared absorptance by Kirchhoff's law). The Earth terms use the view factor F of a flat plate to the
// Earth's sphere: E_IR = q_IR F with q_IR the Earth's emitted flux at its surface (about 237 W/m²,
// σ (255 K)⁴), and the albedo by the usual thermal-design approximation E_albedo = ρ E_earth F
// max(0, cos z_ss), z_ss the sun's zenith angle at the sub-satellite point (e.g. D. G. Gilmore (ed.),
// Spacecraft Thermal Control Handbook, vol. I, 2nd ed., The Aerospace Press, 2002, ch. 2): cheap enough
// for every derivative an integrator asks for, where the environment's six-face albedo quadrature is not.
#include <array>

#include <Eigen/Core>

namespace panel_thermal {

struct ThermalParams {
    double absorptance = 0.90;          // solar, of a cell-covered face (assumed; 0.85–0.92 typical)
    double emissivity = 0.85;           // infrared, of the cover glass (assumed; 0.80–0.90 typical)
    double areal_heat_capacity = 2500;  // J/(m² K): ~1.5 kg/m² panel of ~900 J/(kg K) plus cells (assumed)
    double earth_infrared = 237.0;      // W/m², the Earth's emitted flux at its surface
    double inner_conductance = 2.0;     // W/(m² K), face to body through its inner side (assumed)
    double body_temperature = 293.15;   // K, the body the faces exchange heat with
};

inline constexpr double stefan_boltzmann = 5.670374419e-8;  // W/(m² K⁴), CODATA 2018 (exact)

/// View factor of a flat plate to a sphere: the plate's normal makes angle θ with the direction to the
/// sphere's centre (cos θ = cos_theta) and the plate is at distance h_ratio = r / R (> 1) from the centre in
/// radii. cos θ / h² while the whole disc is in front of the plate, 0 when it is wholly behind, the
/// partial-view expression in between (J. R. Howell, A Catalog of Radiation Heat Transfer Configuration
/// Factors: the tilted plane element to a sphere; also J. R. Howell, M. P. Mengüç, R. Siegel, Thermal Radiation Heat
/// Transfer, 6th ed., CRC Press, 2016, the configuration-factor appendix). Checked against a quadrature.
double plate_sphere_view_factor(double cos_theta, double h_ratio);

/// Heat input to each face (W/m²) absorbed on its outer side: direct sun and albedo (times α) and Earth
/// infrared (times ε). sun_body: unit sun direction, body axes; irradiance: direct sunlight at the
/// satellite (after eclipse); nadir_body: unit direction to the Earth's centre, body axes; h_ratio =
/// r / R_E; albedo_source = ρ E_earth max(0, cos z_ss) (0 in the Earth's night).
std::array<double, 6> face_heat_input(const ThermalParams& p, const Eigen::Vector3d& sun_body, double irradiance,
                                      const Eigen::Vector3d& nadir_body, double h_ratio, double albedo_source);

/// dT/dt of each face (K/s) from its temperature and its heat input.
std::array<double, 6> face_temperature_derivative(const ThermalParams& p, const std::array<double, 6>& temperature,
                                                  const std::array<double, 6>& heat_input);

}  // namespace panel_thermal
