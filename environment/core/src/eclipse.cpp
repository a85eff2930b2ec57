#include "environment/eclipse.hpp"

#include <algorithm>
#include <cmath>

#include "environment/constants.hpp"

namespace environment {

double sunlight_fraction(const Eigen::Vector3d& r_sat, const Eigen::Vector3d& r_sun) {
    // Montenbruck & Gill (2000), section 3.4.2, conical shadow model.
    const Eigen::Vector3d to_sun = r_sun - r_sat;
    const double d_sun = to_sun.norm();
    const double d_earth = r_sat.norm();
    const double a = std::asin(std::min(1.0, kSunRadius / d_sun));      // apparent solar radius
    const double b = std::asin(std::min(1.0, kEarthRadius / d_earth));  // apparent Earth radius
    const double cos_c = std::clamp((-r_sat).dot(to_sun) / (d_earth * d_sun), -1.0, 1.0);
    const double c = std::acos(cos_c);  // separation of the two discs' centres
    if (c >= a + b) return 1.0;
    if (c <= b - a) return 0.0;
    if (c < a - b) return 1.0 - (b * b) / (a * a);
    const double x = (c * c + a * a - b * b) / (2.0 * c);
    const double y = std::sqrt(std::max(0.0, a * a - x * x));
    const double area =
        a * a * std::acos(std::clamp(x / a, -1.0, 1.0)) + b * b * std::acos(std::clamp((c - x) / b, -1.0, 1.0)) - c * y;
    return std::clamp(1.0 - area / (kPi * a * a), 0.0, 1.0);
}

}  // namespace environment
