#pragma once
// Earth shadow: conical (umbra/penumbra) model with spherical Earth and Sun, Montenbruck & Gill,
// Satellite Orbits (2000), section 3.4.2. With a = apparent solar radius, b = apparent Earth radius and
// c = angular separation of the two centres as seen from the satellite:
//   c >= a + b            : full sunlight, nu = 1
//   c <= b - a            : umbra, nu = 0
//   c <  a - b            : annular (not reachable from LEO), nu = 1 - b^2/a^2
//   otherwise (penumbra)  : nu = 1 - A / (pi a^2), A = overlap area of two discs (smooth in c)
//     x = (c^2 + a^2 - b^2) / (2c), y = sqrt(a^2 - x^2),
//     A = a^2 acos(x/a) + b^2 acos((c - x)/b) - c y
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

namespace environment {

/// Fraction nu in [0, 1] of the solar disc visible from r_sat (ECI, m), sun at r_sun (ECI, m).
double sunlight_fraction(const Eigen::Vector3d& r_sat, const Eigen::Vector3d& r_sun);

}  // namespace environment
