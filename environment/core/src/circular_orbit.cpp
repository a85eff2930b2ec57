#include "environment/circular_orbit.hpp"

#include <cmath>
#include <stdexcept>

#include "environment/constants.hpp"

namespace environment {

CircularOrbit::CircularOrbit(const OrbitParams& params) : params_(params) {
    if (!(params.altitude > 0.0) || !std::isfinite(params.altitude)) {
        throw std::invalid_argument("CircularOrbit: altitude must be positive and finite");
    }
    if (!std::isfinite(params.inclination) || !std::isfinite(params.raan) ||
        !std::isfinite(params.argument_of_latitude0)) {
        throw std::invalid_argument("CircularOrbit: angles must be finite");
    }
    a_ = kEarthRadius + params.altitude;
    n_ = std::sqrt(kEarthGravitationalParameter / (a_ * a_ * a_));
}

double CircularOrbit::period() const {
    return 2.0 * kPi / n_;
}

Eigen::Vector3d CircularOrbit::position_eci(double t) const {
    const double u = params_.argument_of_latitude0 + n_ * t;
    const double cu = std::cos(u), su = std::sin(u);
    const double co = std::cos(params_.raan), so = std::sin(params_.raan);
    const double ci = std::cos(params_.inclination), si = std::sin(params_.inclination);
    return a_ * Eigen::Vector3d(cu * co - su * ci * so, cu * so + su * ci * co, su * si);
}

Eigen::Vector3d CircularOrbit::velocity_eci(double t) const {
    const double u = params_.argument_of_latitude0 + n_ * t;
    const double cu = std::cos(u), su = std::sin(u);
    const double co = std::cos(params_.raan), so = std::sin(params_.raan);
    const double ci = std::cos(params_.inclination), si = std::sin(params_.inclination);
    return a_ * n_ * Eigen::Vector3d(-su * co - cu * ci * so, -su * so + cu * ci * co, cu * si);
}

Eigen::Vector3d CircularOrbit::orbit_normal() const {
    const double co = std::cos(params_.raan), so = std::sin(params_.raan);
    const double ci = std::cos(params_.inclination), si = std::sin(params_.inclination);
    return {si * so, -si * co, ci};
}

}  // namespace environment
