#include "environment/sun_ephemeris.hpp"

#include <cmath>

#include "environment/constants.hpp"
#include "environment/earth_rotation.hpp"

namespace environment {

SunPosition sun_almanac(double jd) {
    // Astronomical Almanac, low-precision formulas for the Sun (valid 1950-2050, ~0.01 deg).
    const double n = jd - kJulianDateJ2000;
    const double L = (280.460 + 0.9856474 * n) * kDegToRad;
    const double g = (357.528 + 0.9856003 * n) * kDegToRad;
    const double lambda = L + (1.915 * std::sin(g) + 0.020 * std::sin(2.0 * g)) * kDegToRad;
    const double eps = (23.439 - 0.0000004 * n) * kDegToRad;
    const double r_au = 1.00014 - 0.01671 * std::cos(g) - 0.00014 * std::cos(2.0 * g);
    SunPosition s;
    s.direction_eci =
        Eigen::Vector3d(std::cos(lambda), std::cos(eps) * std::sin(lambda), std::sin(eps) * std::sin(lambda));
    s.distance = r_au * kAstronomicalUnit;
    return s;
}

SunPosition sun_almanac_j2000(double jd) {
    SunPosition s = sun_almanac(jd);
    s.direction_eci = precession_matrix(jd).transpose() * s.direction_eci;  // of date -> J2000
    return s;
}

SunPosition sun_seed002(double jd, double jd_equinox, double amplitude) {
    double t_sun = std::fmod(jd - jd_equinox, 365.0);  // days since the vernal equinox
    if (t_sun < 0.0) t_sun += 365.0;
    const double eps_sun = amplitude * std::sin(t_sun / 365.0 * 2.0 * kPi);  // seed 002 eq. 21
    const double lambda_sun = t_sun / 365.0 * 2.0 * kPi;                     // seed 002 eq. 22
    // seed 002 eq. 23: R_theta(eps) R_psi(lambda) [1 0 0]^T, signs chosen so that a positive elevation is
    // north of the equator (the paper does not print the matrices).
    SunPosition s;
    s.direction_eci = Eigen::Vector3d(std::cos(eps_sun) * std::cos(lambda_sun),
                                      std::cos(eps_sun) * std::sin(lambda_sun), std::sin(eps_sun));
    s.distance = kAstronomicalUnit;
    return s;
}

double right_ascension(const Eigen::Vector3d& v) {
    double a = std::atan2(v.y(), v.x());
    if (a < 0.0) a += 2.0 * kPi;
    return a;
}

double declination(const Eigen::Vector3d& v) {
    return std::asin(v.z() / v.norm());
}

}  // namespace environment
