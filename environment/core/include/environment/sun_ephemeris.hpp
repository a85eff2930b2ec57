#pragma once
// Geocentric sun position. The almanac formula gives mean-of-date coordinates (mean equator and equinox
// of the date); sun_almanac_j2000 rotates them to the J2000 mean equator and equinox, the one inertial
// frame ("ECI") of every *_eci output of the environment (the field's Earth-fixed to ECI rotation uses
// the same precession, earth_rotation.hpp). The two differ by the precession since 2000: 0.36 deg in 2026.
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

namespace environment {

struct SunPosition {
    Eigen::Vector3d direction_eci;  // unit vector, Earth centre -> Sun
    double distance = 0.0;          // m, Earth centre -> Sun
};

/// Low-precision formula of the Astronomical Almanac (section C, "Low precision formulas for the Sun";
/// also US Naval Observatory, "Approximate Solar Coordinates"): accuracy about 0.01 deg in direction
/// for 1950-2050, distance to about 1e-4 AU.
///   n = JD - 2451545.0
///   L = 280.460 + 0.9856474 n   (mean longitude, deg)
///   g = 357.528 + 0.9856003 n   (mean anomaly, deg)
///   lambda = L + 1.915 sin g + 0.020 sin 2g    (ecliptic longitude, latitude ~ 0)
///   eps = 23.439 - 0.0000004 n                 (obliquity)
///   R = 1.00014 - 0.01671 cos g - 0.00014 cos 2g   (AU)
///   direction = (cos lambda, cos eps sin lambda, sin eps sin lambda)
SunPosition sun_almanac(double julian_date);  // mean equator and equinox of date

/// The same in J2000 mean equator and equinox: P(t)^T times the almanac's direction, with P the IAU 1976
/// precession (earth_rotation.hpp) from J2000 to the mean equator and equinox of date.
SunPosition sun_almanac_j2000(double julian_date);

/// Simplified geocentric model of seed 002 (Nygren et al.), eq. 21-23:
///   eps_sun = A sin(2 pi T/365)          (21)  elevation above the equator
///   lambda_sun = 2 pi T / 365            (22)  azimuth from the vernal equinox
///   r = R_theta(eps_sun) R_psi(lambda_sun) [1 0 0]^T   (23)
///     = (cos eps cos lambda, cos eps sin lambda, sin eps)
/// T = days since the vernal equinox. Its frame is that of the equinox it is given (a few degrees of model
/// error dwarf the 0.36 deg of precession). The paper prints A = 2 pi/180 rad (2 deg), which cannot be the
/// sun's declination amplitude; the physical amplitude is the obliquity, 23.44 deg, and that is the
/// default of `elevation_amplitude` (pass 2 pi/180 to get the printed formula). Distance: 1 AU.
SunPosition sun_seed002(double julian_date, double julian_date_vernal_equinox, double elevation_amplitude);

/// Right ascension and declination (rad) of an ECI direction; RA in [0, 2 pi).
double right_ascension(const Eigen::Vector3d& v);
double declination(const Eigen::Vector3d& v);

}  // namespace environment
