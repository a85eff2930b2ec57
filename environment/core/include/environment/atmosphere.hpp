#pragma once
// The thermosphere's density for the aerodynamic torque: the table the on-board computer carries too
// (ground/atmosphere_table.hpp, one copy for both), an exponential model in altitude bands,
//
//   ρ(h) = ρ₀ exp(−(h − h₀) / H)        for h₀ ≤ h < h₁ (the band's base and the next one's),
//
// with the base densities ρ₀ and scale heights H of D. A. Vallado, Fundamentals of Astrodynamics and
// Applications, 4th ed., Microcosm Press, 2013, table 8-4 (from CIRA-72, mean solar activity), 0 to
// 1000 km; above 1000 km the last band continues.
//
// Why this model and not Harris–Priester or NRLMSISE-00: at the bundled orbit's 570 km the aerodynamic
// torque on a 3U is two orders of magnitude below the residual dipole's (docs/design.md, "The
// spacecraft"), so the density's own uncertainty (a factor of about 10 between solar minimum and maximum,
// which neither the table nor Harris–Priester's mean-activity coefficients follow without an F10.7 input)
// does not reach the attitude. The table is 28 rows, needs no sun position and no space-weather input,
// and costs one exponential per evaluation; NRLMSISE-00 would need F10.7 and Ap inputs the scenario does
// not have. The diurnal bulge (a factor of about 2 day/night at 570 km) is not modelled.
//
// The altitude is taken above the WGS-84 ellipsoid, approximated to first order in the flattening (the
// local radius a(1 − f sin²φ), φ the geocentric latitude): at the bundled 64.9° inclination the
// ellipsoid lies up to 18 km below the equatorial sphere, a quarter of the scale height.

#include <Eigen/Core>

namespace environment {

/// Density (kg/m³) at the geodetic altitude h (m); h below 0 is refused (std::invalid_argument).
double atmosphere_density(double altitude);

/// Altitude (m) of r (m, Earth-centred, any frame whose z is the Earth's axis) above the WGS-84
/// ellipsoid, to first order in the flattening.
double ellipsoid_altitude(const Eigen::Vector3d& r);

}  // namespace environment
