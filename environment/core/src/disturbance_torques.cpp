#include "environment/disturbance_torques.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Geometry>  // cross products

#include "environment/constants.hpp"

namespace environment {

void validate(const SpacecraftBody& b) {
    for (int i = 0; i < 3; ++i) {
        if (!(b.size[i] > 0.0) || !std::isfinite(b.size[i]))
            throw std::invalid_argument("SpacecraftBody: the box's size must be finite and > 0 on each axis");
        if (!std::isfinite(b.centre_of_mass[i]) || std::abs(b.centre_of_mass[i]) > 0.5 * b.size[i])
            throw std::invalid_argument("SpacecraftBody: the centre of mass must lie inside the box");
        if (!std::isfinite(b.dipole_moment[i]))
            throw std::invalid_argument("SpacecraftBody: the dipole moment must be finite");
    }
    if (!(b.drag_coefficient >= 0.0) || !std::isfinite(b.drag_coefficient))
        throw std::invalid_argument("SpacecraftBody: the drag coefficient must be finite and >= 0");
    if (!(b.specular_reflectivity >= 0.0) || !(b.diffuse_reflectivity >= 0.0) ||
        !(b.specular_reflectivity + b.diffuse_reflectivity <= 1.0)) {
        throw std::invalid_argument(
            "SpacecraftBody: the reflectivities must be >= 0 with specular + diffuse <= 1 (the rest absorbed)");
    }
}

std::array<Face, 6> box_faces(const SpacecraftBody& b) {
    const Eigen::Vector3d com(b.centre_of_mass[0], b.centre_of_mass[1], b.centre_of_mass[2]);
    std::array<Face, 6> faces{};
    for (int axis = 0; axis < 3; ++axis) {
        const double area = b.size[(axis + 1) % 3] * b.size[(axis + 2) % 3];
        for (int side = 0; side < 2; ++side) {
            Eigen::Vector3d n = Eigen::Vector3d::Zero();
            n(axis) = side == 0 ? 1.0 : -1.0;
            faces[2 * axis + side] = Face{n, area, 0.5 * b.size[axis] * n - com};
        }
    }
    return faces;
}

Eigen::Vector3d gravity_gradient_torque(const Eigen::Matrix3d& inertia, const Eigen::Vector3d& r_body) {
    const double r2 = r_body.squaredNorm();
    const double r5 = r2 * r2 * std::sqrt(r2);
    return (3.0 * kEarthGravitationalParameter / r5) * r_body.cross(inertia * r_body);
}

Eigen::Vector3d magnetic_torque(const Eigen::Vector3d& dipole, const Eigen::Vector3d& field_body) {
    return dipole.cross(field_body);
}

Eigen::Vector3d aerodynamic_torque(const std::array<Face, 6>& faces, double drag_coefficient, double density,
                                   const Eigen::Vector3d& v_rel_body) {
    const double speed = v_rel_body.norm();
    if (!(speed > 0.0)) return Eigen::Vector3d::Zero();
    const Eigen::Vector3d v_hat = v_rel_body / speed;
    const double q = 0.5 * density * speed * speed * drag_coefficient;  // N/m² per unit projected area
    Eigen::Vector3d torque = Eigen::Vector3d::Zero();
    for (const Face& f : faces) {
        const double cos_incidence = f.normal.dot(v_hat);  // > 0: the face meets the flow
        if (cos_incidence > 0.0) torque += f.centroid.cross(-q * f.area * cos_incidence * v_hat);
    }
    return torque;
}

Eigen::Vector3d solar_pressure_torque(const std::array<Face, 6>& faces, double specular, double diffuse,
                                      double irradiance, const Eigen::Vector3d& sun_body) {
    const double pressure = irradiance / kSpeedOfLight;  // N/m²
    Eigen::Vector3d torque = Eigen::Vector3d::Zero();
    if (!(pressure > 0.0)) return torque;
    for (const Face& f : faces) {
        const double cos_theta = f.normal.dot(sun_body);
        if (cos_theta <= 0.0) continue;
        const Eigen::Vector3d force =
            -pressure * f.area * cos_theta *
            ((1.0 - specular) * sun_body + 2.0 * (specular * cos_theta + diffuse / 3.0) * f.normal);
        torque += f.centroid.cross(force);
    }
    return torque;
}

}  // namespace environment
