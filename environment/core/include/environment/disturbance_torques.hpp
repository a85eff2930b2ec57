#pragma once
// The external torques on the spacecraft, body axes, N·m: each a closed form of a few flops, no quadrature
// (the body is a convex box, so a face is either wholly exposed to the sun or the wind or not at all).
//
//   gravity gradient   τ = 3μ/|r|⁵ · r_b × (J r_b)              r_b the Earth → satellite vector, body axes
//   magnetic           τ = m × B_b                               m the residual dipole (A·m²), B_b the field (T)
//   aerodynamic        τ = Σ_k c_k × F_k,  F_k = −½ ρ C_D A_k |v|² max(0, n_k·v̂) v̂
//   solar pressure     τ = Σ_k c_k × F_k,  F_k = −P A_k cos θ_k [(1 − ρ_s) ŝ + 2 (ρ_s cos θ_k + ρ_d/3) n_k]
//                      cos θ_k = n_k·ŝ > 0, P = E/c (E the irradiance at the satellite, after the eclipse)
//
// c_k is face k's centroid measured from the centre of mass; v the velocity of the body relative to the
// air, body axes; ŝ the unit vector to the sun, body axes. Sources: J. R. Wertz (ed.), Spacecraft Attitude
// Determination and Control, Reidel, 1978, §17.2 (gravity gradient, magnetic, aerodynamic, solar radiation
// torques); O. Montenbruck, E. Gill, Satellite Orbits, Springer, 2000, §3.4.1 (the flat plate's radiation
// force with specular and diffuse reflection) and §3.5.2 (drag on free-molecular flow, C_D ≈ 2.2).
// The aerodynamic model is the absorbing (Newtonian) plate: momentum of the incoming flow, no
// re-emission lift; the shadowing of one face by another cannot occur on a convex box.
//
// For a box whose centre of mass is at its geometric centre the aerodynamic torque vanishes in any wind:
// each axis' exposed face contributes (L_i A_i / 2) v_i = (V/2) v_i along its normal, so Σ c_k × F_k ∝
// v̂ × v̂ = 0. What turns the box is the offset of the centre of mass (and, for the solar pressure, the
// normal reflection terms about the same offset).
#include <array>

#include <Eigen/Core>

#include "ground/atmosphere_table.hpp"

namespace environment {

/// The spacecraft's outer surface, mass and magnetism as the torques see them (docs/design.md, "The
/// spacecraft"; defaults the bundled 3U).
struct SpacecraftBody {
    /// Edges of the box along body x, y, z (m); its faces are +x, −x, +y, −y, +z, −z.
    std::array<double, 3> size = {0.1, 0.1, 0.34};
    /// Centre of mass from the box's geometric centre (m, body axes): within the CubeSat Design
    /// Specification's 2 cm (x, y) and 7 cm (z) of a 3U (assumed offsets).
    std::array<double, 3> centre_of_mass = {0.004, -0.003, -0.012};
    double drag_coefficient = 2.2;        // free-molecular flat plate (Montenbruck & Gill §3.5.2)
    double specular_reflectivity = 0.05;  // cell cover glass (assumed; absorptance 0.90 as panel_thermal's)
    double diffuse_reflectivity = 0.05;   // (assumed)
    /// Residual magnetic dipole (A·m², body axes); the magnetometer's `dipole_moment` must be the same.
    std::array<double, 3> dipole_moment{};
};

/// Validated once by Environment (throws std::invalid_argument): sizes > 0, the centre of mass inside
/// the box, C_D ≥ 0, reflectivities ≥ 0 with ρ_s + ρ_d ≤ 1, everything finite.
void validate(const SpacecraftBody& body);

/// Face k (0..5 = +x, −x, +y, −y, +z, −z): outward unit normal, area (m²), centroid from the centre of mass (m).
struct Face {
    Eigen::Vector3d normal;
    double area;
    Eigen::Vector3d centroid;
};
std::array<Face, 6> box_faces(const SpacecraftBody& body);

Eigen::Vector3d gravity_gradient_torque(const Eigen::Matrix3d& inertia, const Eigen::Vector3d& r_body);
Eigen::Vector3d magnetic_torque(const Eigen::Vector3d& dipole, const Eigen::Vector3d& field_body);
/// density kg/m³; v_rel_body the body's velocity relative to the air (m/s, body axes).
Eigen::Vector3d aerodynamic_torque(const std::array<Face, 6>& faces, double drag_coefficient, double density,
                                   const Eigen::Vector3d& v_rel_body);
/// irradiance W/m² at the satellite (0 in the umbra, the eclipse's fraction of the disc in the penumbra);
/// sun_body the unit vector to the sun, body axes.
Eigen::Vector3d solar_pressure_torque(const std::array<Face, 6>& faces, double specular, double diffuse,
                                      double irradiance, const Eigen::Vector3d& sun_body);

inline constexpr double kSpeedOfLight = 299792458.0;                                  // m/s
inline constexpr double kEarthRotationRate = ground::atmosphere::kEarthRotationRate;  // the atmosphere co-rotates

/// The four torques (N·m, body axes) at one instant.
struct DisturbanceTorques {
    Eigen::Vector3d gravity_gradient = Eigen::Vector3d::Zero();
    Eigen::Vector3d magnetic = Eigen::Vector3d::Zero();
    Eigen::Vector3d aerodynamic = Eigen::Vector3d::Zero();
    Eigen::Vector3d solar_pressure = Eigen::Vector3d::Zero();
    Eigen::Vector3d total() const { return gravity_gradient + magnetic + aerodynamic + solar_pressure; }
};

}  // namespace environment
