#include "environment/atmosphere.hpp"

#include <cmath>
#include <stdexcept>

#include "ground/atmosphere_table.hpp"

namespace environment {

double atmosphere_density(double altitude) {
    if (!(altitude >= 0.0) || !std::isfinite(altitude)) {
        throw std::invalid_argument("atmosphere_density: the altitude must be finite and >= 0 (below the surface)");
    }
    return ground::atmosphere::density(altitude);
}

double ellipsoid_altitude(const Eigen::Vector3d& r) {
    return ground::atmosphere::ellipsoid_altitude(r.x(), r.y(), r.z());
}

}  // namespace environment
