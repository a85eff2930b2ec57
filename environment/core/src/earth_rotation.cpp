#include "environment/earth_rotation.hpp"

#include <cmath>

#include "environment/almanac_formulas.hpp"
#include "environment/constants.hpp"
#include "environment/time_scales.hpp"

namespace environment {

namespace {
// Passive (frame) rotations about z and y by angle a.
Eigen::Matrix3d r3(double a) {
    Eigen::Matrix3d m;
    m << std::cos(a), std::sin(a), 0.0, -std::sin(a), std::cos(a), 0.0, 0.0, 0.0, 1.0;
    return m;
}
Eigen::Matrix3d r2(double a) {
    Eigen::Matrix3d m;
    m << std::cos(a), 0.0, -std::sin(a), 0.0, 1.0, 0.0, std::sin(a), 0.0, std::cos(a);
    return m;
}
}  // namespace

Eigen::Vector3d precession_angles(double jd) {
    // Lieske et al. (1977), IAU 1976 precession from J2000 (Vallado eq. 3-87), shared with the on-board
    // computer (almanac_formulas.hpp).
    const auto a = formulas::precession_angles((jd - kJulianDateJ2000) / 36525.0);
    return Eigen::Vector3d(a[0], a[1], a[2]);
}

Eigen::Matrix3d precession_matrix(double jd) {
    const Eigen::Vector3d a = precession_angles(jd);
    // r_mod = R3(-z) R2(theta) R3(-zeta) r_J2000
    return r3(-a.y()) * r2(a.z()) * r3(-a.x());
}

Eigen::Matrix3d ecef_from_eci(double jd_utc) {
    return r3(gmst(jd_utc)) * precession_matrix(jd_utc);
}

}  // namespace environment
