// Random vectors drawn in a fixed order. The order in which a call's arguments are evaluated is unspecified:
// GCC evaluates Eigen::Vector3d(n(rng), n(rng), n(rng)) from the last argument, clang from the first, so a
// test drawing inside a call's arguments gets other numbers from each compiler and can pass under one and
// fail under the other. These draw one component per statement, the last first: the draws the tests were
// written with (GCC's).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace ordered_draws {

template <class Distribution, class Engine>
Eigen::Vector3d vector3(Distribution& d, Engine& rng) {
    const double z = d(rng);
    const double y = d(rng);
    const double x = d(rng);
    return {x, y, z};
}

// Eigen::Quaterniond(w, x, y, z) from four draws, z first.
template <class Distribution, class Engine>
Eigen::Quaterniond quaternion(Distribution& d, Engine& rng) {
    const Eigen::Vector3d xyz = vector3(d, rng);
    const double w = d(rng);
    return {w, xyz.x(), xyz.y(), xyz.z()};
}

}  // namespace ordered_draws
