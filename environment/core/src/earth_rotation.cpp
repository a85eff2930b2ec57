#include "environment/earth_rotation.hpp"

#include <cmath>

#include "environment/constants.hpp"
#include "environment/time_scales.hpp"
#include "orbit/frames.hpp"  // IAU 1976 precession, shared with the TEME -> J2000 rotation

namespace environment {

namespace {
// Passive (frame) rotation about z by angle a.
Eigen::Matrix3d r3(double a) {
    Eigen::Matrix3d m;
    m << std::cos(a), std::sin(a), 0.0, -std::sin(a), std::cos(a), 0.0, 0.0, 0.0, 1.0;
    return m;
}
}  // namespace

Eigen::Vector3d precession_angles(double jd) {
    return orbit::precession_angles_iau1976(orbit::julian_centuries(jd));
}

Eigen::Matrix3d precession_matrix(double jd) {
    return orbit::mod_from_j2000(orbit::julian_centuries(jd));
}

Eigen::Matrix3d ecef_from_eci(double jd_utc) {
    return r3(gmst(jd_utc)) * precession_matrix(jd_utc);
}

}  // namespace environment
