// The on-board aerodynamic torque (attitude_estimator/core's drag_torque.hpp, the density from
// ground/atmosphere_table.hpp) against the truth's (environment/core's aerodynamic_torque on box_faces, the
// density from atmosphere_density) for the same wind, attitude and geometry: the same within rounding when the
// computer is told the truth's geometry and its density scale is 1; the named on-board errors (the density's
// scale, the drag coefficient) move it by exactly their factor.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "attitude_estimator/drag_torque.hpp"
#include "environment/atmosphere.hpp"
#include "environment/disturbance_torques.hpp"
#include "ground/atmosphere_table.hpp"
#include "ordered_draws.hpp"

namespace {

namespace ae = attitude_estimator;
namespace env = environment;

template <class T>
ae::DragGeometry<T> geometry_of(const env::SpacecraftBody& b) {
    ae::DragGeometry<T> g;
    for (std::size_t i = 0; i < 3; ++i) {
        g.size[i] = static_cast<T>(b.size[i]);
        g.centre_of_mass[i] = static_cast<T>(b.centre_of_mass[i]);
    }
    g.drag_coefficient = static_cast<T>(b.drag_coefficient);
    return g;
}

Eigen::Vector3d random_unit(std::mt19937& rng) {
    std::normal_distribution<double> n;
    return ordered_draws::vector3(n, rng).normalized();
}

TEST(OnboardModels, FirmwaresFloatDensityIsTheTruthsWithinItsRounding) {
    // One table (ground/atmosphere_table.hpp) for both; the environment evaluates it in double, the firmware in
    // float, where h/1000 and the exponent of a 60 km scale height lose a few parts in 1e7.
    for (double h = 0.0; h <= 1200e3; h += 2.5e3) {
        const double truth = env::atmosphere_density(h);
        EXPECT_NEAR(ground::atmosphere::density(static_cast<float>(h)), truth, 2e-6 * truth) << h << " m";
    }
    std::mt19937 rng(42);
    for (int k = 0; k < 200; ++k) {
        const Eigen::Vector3d r = (6.6e6 + 1e5 * k / 200.0) * random_unit(rng);
        const float h = ground::atmosphere::ellipsoid_altitude(static_cast<float>(r.x()), static_cast<float>(r.y()),
                                                               static_cast<float>(r.z()));
        EXPECT_NEAR(h, env::ellipsoid_altitude(r), 2.0) << "m (float: 0.5 m steps at 6.7e6 m)";
    }
}

TEST(OnboardModels, DragTorqueIsTheEnvironmentsForTheSameWindAttitudeAndGeometry) {
    // The bundled 3U (docs/design.md), and a box of other proportions with its centre of mass further off.
    env::SpacecraftBody other;
    other.size = {0.2, 0.3, 0.1};
    other.centre_of_mass = {-0.03, 0.05, 0.02};
    other.drag_coefficient = 2.5;
    std::mt19937 rng(39);
    for (const env::SpacecraftBody& body : {env::SpacecraftBody{}, other}) {
        const std::array<env::Face, 6> faces = env::box_faces(body);
        for (int k = 0; k < 500; ++k) {
            // An orbit point at 400-600 km, its inertial velocity, the co-rotating air, a random attitude:
            // the environment's wind (environment.cpp) and the computer's, v − ω_E ẑ × r turned into the body.
            const Eigen::Vector3d r = (6.778e6 + 2e5 * (k % 10) / 10.0) * random_unit(rng);
            const Eigen::Vector3d v = 7.6e3 * r.cross(random_unit(rng)).normalized();
            const Eigen::Vector3d wind = v - env::kEarthRotationRate * Eigen::Vector3d::UnitZ().cross(r);
            const Eigen::Matrix3d a = Eigen::AngleAxisd(3.0 * (k + 1) / 500.0, random_unit(rng)).toRotationMatrix();
            const Eigen::Vector3d v_body = a * wind;
            const double rho = env::atmosphere_density(env::ellipsoid_altitude(r));
            const Eigen::Vector3d truth = env::aerodynamic_torque(faces, body.drag_coefficient, rho, v_body);
            const double rho_onboard =
                ground::atmosphere::density(ground::atmosphere::ellipsoid_altitude(r.x(), r.y(), r.z()));
            const ae::Vec3<double> onboard = ae::drag_torque(geometry_of<double>(body), rho_onboard,
                                                             ae::Vec3<double>{v_body.x(), v_body.y(), v_body.z()});
            const double scale = std::max(truth.norm(), 1e-20);
            for (int i = 0; i < 3; ++i)
                EXPECT_NEAR(onboard[static_cast<std::size_t>(i)], truth(i), 1e-12 * scale)
                    << "run " << k << " axis " << i;
            // The firmware's float: within its rounding.
            const ae::Vec3<float> in_float =
                ae::drag_torque(geometry_of<float>(body), static_cast<float>(rho_onboard),
                                ae::Vec3<float>{static_cast<float>(v_body.x()), static_cast<float>(v_body.y()),
                                                static_cast<float>(v_body.z())});
            for (int i = 0; i < 3; ++i)
                EXPECT_NEAR(in_float[static_cast<std::size_t>(i)], truth(i), 2e-5 * scale)
                    << "run " << k << " axis " << i;
            // A named on-board error moves it by its factor: the computer's density scale (its belief of the
            // solar activity) and its drag coefficient enter as one product.
            ae::DragGeometry<double> wrong = geometry_of<double>(body);
            wrong.drag_coefficient *= 1.3;
            const ae::Vec3<double> scaled =
                ae::drag_torque(wrong, 2.0 * rho_onboard, ae::Vec3<double>{v_body.x(), v_body.y(), v_body.z()});
            for (int i = 0; i < 3; ++i)
                EXPECT_NEAR(scaled[static_cast<std::size_t>(i)], 2.6 * truth(i), 1e-12 * scale) << "run " << k;
        }
    }
}

}  // namespace
