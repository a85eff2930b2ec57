#pragma once
// ECI (J2000 mean equator and equinox) <-> Earth-fixed rotation used for the geomagnetic field:
//   r_ecef = R3(GMST) P(t) r_eci
// P = IAU 1976 precession from J2000 to the mean equator and equinox of date (Lieske et al. 1977;
// Vallado eq. 3-88): P = R3(-z) R2(theta) R3(-zeta), with R_i the passive (frame) rotations, computed by
// orbit/frames.hpp (which the TEME -> J2000 rotation of the SGP4 orbit shares);
// GMST = IAU 1982 (time_scales.hpp). Neglected: nutation (< 17.2" in longitude, 9.2" in obliquity) and the
// equation of the equinoxes (< 1.2 s of time), polar motion (< 0.5"), UT1-UTC (< 0.9 s) and TT-UTC
// in the precession argument (69 s): together below 0.01 deg of Earth orientation, i.e. < 5 nT of
// field direction error at 570 km. Precession itself is 0.36 deg in 2026 and is included.
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

namespace environment {

/// IAU 1976 precession angles zeta, z, theta (rad) at a Julian date (TT, UTC accepted).
Eigen::Vector3d precession_angles(double julian_date);

/// Matrix taking J2000 (ECI) coordinates to mean-of-date coordinates.
Eigen::Matrix3d precession_matrix(double julian_date);

/// R3(gmst): mean of date -> Earth-fixed, the passive rotation about z by the sidereal angle (rad).
Eigen::Matrix3d earth_rotation_z(double gmst);

/// Matrix taking ECI (J2000) coordinates to Earth-fixed coordinates: R3(GMST) P.
Eigen::Matrix3d ecef_from_eci(double julian_date_utc);

}  // namespace environment
