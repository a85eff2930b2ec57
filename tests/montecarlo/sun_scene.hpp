// One random scene of the sun-sensing Monte-Carlo study (issue 8): a satellite at a random sunlit point of
// a 570 km orbit shell (seed 004's "Aist" altitude) in a uniformly random attitude, the Earth albedo on its
// six faces from the environment block's model, and the six face currents the power plant's panels deliver
// (ssr_plant's own illumination: angular response, single-diode short-circuit current), digitized as the
// on-board computer would read them. The truth (sun direction in body axes) comes with it.
#pragma once

#include <array>
#include <cstdint>

#include "ssr_plant/plant.hpp"

namespace montecarlo {

struct SceneConfig {
    ssr_plant::AngularResponse response = ssr_plant::AngularResponse::kelly;  // the plant's panels
    bool albedo = true;          // Earth albedo on the faces (environment's Lambertian sphere model)
    double reflectivity = 0.3;   // Earth's mean Bond albedo
    double altitude = 570e3;     // m
    double irradiance = 1367.0;  // W/m², direct sun (seed 000 §4)
    unsigned adc_bits = 12;      // the estimator's converters (TMS320F2808), 0 = ideal
    double adc_max = 1.2;        // A, full scale of the per-face current channels (0 … adc_max)
    // K: each face's cell temperature drawn uniformly from [temperature_min, temperature_max] (the panels'
    // datasheet 298.15 K both: no draw, every face at its fit); the estimator stays normalized at 298.15 K.
    double temperature_min = 298.15;
    double temperature_max = 298.15;
};

struct Scene {
    std::array<double, 3> sun_body{};     // truth: unit sun direction in body axes
    std::array<double, 3> nadir_body{};   // unit direction to the Earth's centre in body axes
    std::array<double, 6> albedo{};       // W/m² on +x, −x, +y, −y, +z, −z
    std::array<double, 6> i_face{};       // A, digitized short-circuit current of each face
    std::array<double, 6> temperature{};  // K, each face's cell temperature
};

// Draws scenes from a fixed seed, so a study is reproducible run to run and machine to machine (the
// generator is splitmix64 and every transform is written out, no std:: distribution).
class SceneGenerator {
public:
    SceneGenerator(const SceneConfig& config, std::uint64_t seed);

    Scene next();

    // Short-circuit current of one face squarely facing the sun, no albedo: eq. 5's denominator.
    double i_face_norm() const { return i_face_norm_; }

private:
    double uniform();  // [0, 1)

    SceneConfig config_;
    ssr_plant::Model plant_;
    std::uint64_t state_;
    double i_face_norm_ = 0.0;
};

}  // namespace montecarlo
