#pragma once
// Circular Keplerian orbit (no perturbations) in ECI (J2000).
//   r_eci(t) = a [cos u cos O - sin u cos i sin O,  cos u sin O + sin u cos i cos O,  sin u sin i]
//   u = u0 + n t,  n = sqrt(mu / a^3),  a = R_E + altitude.
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

namespace environment {

struct OrbitParams {
    double altitude = 570.0e3;                                   // m, seed 004 section 5 ("about 570 km")
    double inclination = 64.9 * 3.14159265358979323846 / 180.0;  // rad, seed 004 section 5
    double raan = 0.0;                                           // rad, right ascension of the ascending node
    double argument_of_latitude0 = 0.0;                          // rad, at t = 0
};

class CircularOrbit {
public:
    /// Throws std::invalid_argument for a non-positive altitude.
    explicit CircularOrbit(const OrbitParams& params);
    Eigen::Vector3d position_eci(double t) const;  // m
    Eigen::Vector3d velocity_eci(double t) const;  // m/s
    double semi_major_axis() const { return a_; }
    double mean_motion() const { return n_; }  // rad/s
    double period() const;                     // s
    Eigen::Vector3d orbit_normal() const;      // unit, ECI

private:
    OrbitParams params_;
    double a_;
    double n_;
};

}  // namespace environment
