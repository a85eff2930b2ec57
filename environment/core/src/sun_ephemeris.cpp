#include "environment/sun_ephemeris.hpp"

#include <cmath>

#include "environment/constants.hpp"
#include "environment/earth_rotation.hpp"
#include "ground/almanac_formulas.hpp"

namespace environment {

SunPosition sun_almanac(double jd) {
    // Astronomical Almanac, low-precision formulas for the Sun (valid 1950-2050, ~0.01 deg).
    // The formula is shared with the on-board computer (almanac_formulas.hpp).
    const ground::formulas::AlmanacSun<double> a = ground::formulas::sun_almanac_of_date(jd - kJulianDateJ2000);
    SunPosition s;
    s.direction_eci = Eigen::Vector3d(a.direction[0], a.direction[1], a.direction[2]);
    s.distance = a.distance_au * kAstronomicalUnit;
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
