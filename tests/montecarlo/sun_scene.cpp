#include "sun_scene.hpp"

#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "attitude_estimator/adc.hpp"
#include "environment/constants.hpp"
#include "environment/earth_albedo.hpp"
#include "environment/eclipse.hpp"

namespace montecarlo {

namespace {

std::array<double, 3> to_array(const Eigen::Vector3d& v) {
    return {v.x(), v.y(), v.z()};
}

// The sun sits on the ECI +x axis at 1 AU: with the attitude uniformly random, the sun direction in body
// axes is uniform on the sphere whatever the sun's inertial direction is.
const Eigen::Vector3d kSunEci = Eigen::Vector3d::UnitX();

}  // namespace

SceneGenerator::SceneGenerator(const SceneConfig& config, std::uint64_t seed) : config_(config), state_(seed) {
    ssr_plant::Parameters p;
    p.fidelity = ssr_plant::Fidelity::averaged;
    p.angular_response = config.response;
    plant_ = ssr_plant::make_model(p);
    ssr_plant::Inputs square;
    square.sun_body = {1.0, 0.0, 0.0};
    square.irradiance = config.irradiance;
    i_face_norm_ = ssr_plant::illuminate(plant_, square).i_sc[0];
}

double SceneGenerator::uniform() {
    // splitmix64, top 53 bits → [0, 1)
    state_ += 0x9E3779B97F4A7C15ull;
    std::uint64_t z = state_;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;
}

Scene SceneGenerator::next() {
    constexpr double two_pi = 2.0 * std::numbers::pi;
    // Uniform attitude: Shoemake's subgroup algorithm (Graphics Gems III, 1992).
    const double u1 = uniform(), u2 = uniform(), u3 = uniform();
    const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
    const Eigen::Quaterniond q(b * std::cos(two_pi * u3), a * std::sin(two_pi * u2), a * std::cos(two_pi * u2),
                               b * std::sin(two_pi * u3));
    const Eigen::Matrix3d body_from_eci = q.toRotationMatrix();

    // Uniform sunlit position on the orbit shell (rejection of the Earth's shadow, penumbra included).
    const double radius = environment::kEarthRadius + config_.altitude;
    const Eigen::Vector3d r_sun = environment::kAstronomicalUnit * kSunEci;
    Eigen::Vector3d r_sat;
    do {
        const double z = 2.0 * uniform() - 1.0;
        const double lon = two_pi * uniform();
        const double rho = std::sqrt(1.0 - z * z);
        r_sat = radius * Eigen::Vector3d(rho * std::cos(lon), rho * std::sin(lon), z);
    } while (environment::sunlight_fraction(r_sat, r_sun) < 1.0);

    Scene s;
    s.sun_body = to_array(body_from_eci * kSunEci);
    s.nadir_body = to_array(body_from_eci * (-r_sat.normalized()));
    if (config_.albedo) {
        environment::AlbedoParams albedo;
        albedo.reflectivity = config_.reflectivity;
        // The Earth's light reaches the panels through their own response, as in leo_orbit (environment
        // albedo_response = kelly for Kelly panels).
        albedo.response = config_.response == ssr_plant::AngularResponse::kelly ? environment::AlbedoResponse::kelly
                                                                                : environment::AlbedoResponse::cosine;
        s.albedo = environment::earth_albedo(albedo, r_sat, kSunEci, config_.irradiance, body_from_eci);
    }

    ssr_plant::Inputs u;
    u.sun_body = s.sun_body;
    u.irradiance = config_.irradiance;
    u.albedo_face = s.albedo;
    // Drawn last, and only when asked for: the scenes of a study without temperatures stay the same.
    for (std::size_t k = 0; k < 6; ++k)
        s.temperature[k] =
            config_.temperature_max > config_.temperature_min
                ? config_.temperature_min + (config_.temperature_max - config_.temperature_min) * uniform()
                : config_.temperature_min;
    u.panel_temperature = s.temperature;
    const auto i_sc = ssr_plant::illuminate(plant_, u).i_sc;
    const attitude_estimator::AdcConfig<double> adc{config_.adc_bits, 0.0, config_.adc_max};
    for (std::size_t k = 0; k < 6; ++k) s.i_face[k] = attitude_estimator::convert(adc, i_sc[k]).value;
    return s;
}

}  // namespace montecarlo
