// The Monte-Carlo study of issue 8: every sun method of the estimator core over the same random scenes
// (sun_scene.hpp), scored by the angle between the estimated and the true sun direction.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "attitude_estimator/sun_methods.hpp"
#include "sun_scene.hpp"

namespace montecarlo {

struct ErrorStatistics {
    attitude_estimator::SunMethod method{};
    std::size_t samples = 0;  // scenes drawn
    std::size_t valid = 0;    // scenes where the method reported a valid sun vector
    double mean_deg = 0.0;    // angular error over the valid scenes, degrees
    double median_deg = 0.0;
    double p95_deg = 0.0;
    double max_deg = 0.0;
    std::size_t faces_rejected = 0;  // scenes where the method rejected at least one lit face
};

inline constexpr attitude_estimator::SunMethod kAllMethods[] = {
    attitude_estimator::SunMethod::difference, attitude_estimator::SunMethod::inverse_response,
    attitude_estimator::SunMethod::cones, attitude_estimator::SunMethod::three_faces};

// The estimator configuration a method runs with in the study: the plant's own angular response and
// normalization (what a calibrated flight unit would be given), everything else at the core's defaults.
attitude_estimator::SunMethodConfig<double> method_config(const SceneConfig& scene, double i_face_norm,
                                                          attitude_estimator::SunMethod method);

// Draws `samples` scenes from `seed` and scores every method of kAllMethods on each. The cones method's
// tracking state starts fresh for every scene (the scenes are independent draws, not a trajectory).
std::vector<ErrorStatistics> run_study(const SceneConfig& scene, std::size_t samples, std::uint64_t seed);

// The one-sample floor of the panel law over the same scenes: the true sun with every component a face
// cannot see (both faces of its axis at zero response: |s_k| below the law's zero, cos 85° for Kelly)
// replaced by 0, scored like a method. No method reading one sample of the faces can know more.
ErrorStatistics dark_band_floor(const SceneConfig& scene, std::size_t samples, std::uint64_t seed);

// Angle in degrees between two unit vectors (robust near 0 and 180°).
double angle_deg(const std::array<double, 3>& a, const std::array<double, 3>& b);

}  // namespace montecarlo
