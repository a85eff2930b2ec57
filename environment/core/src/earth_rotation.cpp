#include "environment/earth_rotation.hpp"

#include <cmath>

#include "environment/constants.hpp"
#include "environment/time_scales.hpp"
#include "orbit/frames.hpp"  // IAU 1976 precession, shared with the TEME -> J2000 rotation

namespace environment {

Eigen::Matrix3d earth_rotation_z(double a) {
    // Passive (frame) rotation about z by angle a.
    const double c = std::cos(a), s = std::sin(a);
    Eigen::Matrix3d m;
    m << c, s, 0.0, -s, c, 0.0, 0.0, 0.0, 1.0;
    return m;
}

Eigen::Vector3d precession_angles(double jd) {
    return orbit::precession_angles_iau1976(orbit::julian_centuries(jd));
}

Eigen::Matrix3d precession_matrix(double jd) {
    return orbit::mod_from_j2000(orbit::julian_centuries(jd));
}

Eigen::Matrix3d ecef_from_eci(double jd_utc) {
    return earth_rotation_z(gmst(jd_utc)) * precession_matrix(jd_utc);
}

}  // namespace environment
