#include "sun_method_study.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace montecarlo {

namespace ae = attitude_estimator;

double angle_deg(const std::array<double, 3>& a, const std::array<double, 3>& b) {
    // atan2(|a × b|, a · b): accurate at small angles where acos(a · b) loses half its digits.
    const double cx = a[1] * b[2] - a[2] * b[1];
    const double cy = a[2] * b[0] - a[0] * b[2];
    const double cz = a[0] * b[1] - a[1] * b[0];
    const double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    return std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), dot) * 180.0 / std::numbers::pi;
}

namespace {

void summarize(std::vector<double>& e, ErrorStatistics& st) {
    st.valid = e.size();
    if (e.empty()) return;
    std::sort(e.begin(), e.end());
    double sum = 0.0;
    for (double x : e) sum += x;
    st.mean_deg = sum / static_cast<double>(e.size());
    // Nearest-rank percentiles.
    const auto percentile = [&e](double p) {
        const auto rank = static_cast<std::size_t>(std::ceil(p * static_cast<double>(e.size())));
        return e[std::clamp<std::size_t>(rank, 1, e.size()) - 1];
    };
    st.median_deg = percentile(0.5);
    st.p95_deg = percentile(0.95);
    st.max_deg = e.back();
}

}  // namespace

std::vector<ErrorStatistics> run_study(const SceneConfig& scene, std::size_t samples, std::uint64_t seed) {
    SceneGenerator generator(scene, seed);
    constexpr std::size_t n_methods = std::size(kAllMethods);
    std::array<ae::SunMethodConfig<double>, n_methods> configs;
    std::array<std::vector<double>, n_methods> errors;
    std::vector<ErrorStatistics> stats(n_methods);
    for (std::size_t m = 0; m < n_methods; ++m) {
        configs[m] = method_config(scene, generator.i_face_norm(), kAllMethods[m]);
        errors[m].reserve(samples);
        stats[m].method = kAllMethods[m];
        stats[m].samples = samples;
    }
    for (std::size_t i = 0; i < samples; ++i) {
        const Scene s = generator.next();
        for (std::size_t m = 0; m < n_methods; ++m) {
            ae::SunMethodState<double> state;  // fresh: independent scenes
            const auto r = ae::sun_from_faces(s.i_face, configs[m], state);
            if (r.rejected_faces != 0) ++stats[m].faces_rejected;
            if (!r.valid) continue;
            errors[m].push_back(angle_deg(r.unit, s.sun_body));
        }
    }
    for (std::size_t m = 0; m < n_methods; ++m) summarize(errors[m], stats[m]);
    return stats;
}

ErrorStatistics dark_band_floor(const SceneConfig& scene, std::size_t samples, std::uint64_t seed) {
    // Only the true sun matters here: the same scenes (albedo draws no random numbers) without the albedo
    // integration.
    SceneConfig sun_only = scene;
    sun_only.albedo = false;
    SceneGenerator generator(sun_only, seed);
    const auto law = scene.response == ssr_plant::AngularResponse::kelly ? panel_response::kelly<double>()
                                                                         : panel_response::cosine<double>();
    ErrorStatistics st;
    st.samples = samples;
    std::vector<double> e;
    e.reserve(samples);
    for (std::size_t i = 0; i < samples; ++i) {
        const Scene s = generator.next();
        std::array<double, 3> seen = s.sun_body;
        for (double& c : seen)
            if (panel_response::response_from_cos(law, std::abs(c)) <= 0.0) c = 0.0;
        const double n = std::hypot(seen[0], seen[1], seen[2]);
        for (double& c : seen) c /= n;
        e.push_back(angle_deg(seen, s.sun_body));
    }
    summarize(e, st);
    return st;
}

}  // namespace montecarlo

namespace montecarlo {

attitude_estimator::SunMethodConfig<double> method_config(const SceneConfig& scene, double i_face_norm,
                                                          attitude_estimator::SunMethod method) {
    attitude_estimator::SunMethodConfig<double> c;
    c.method = method;
    c.i_face_norm.fill(i_face_norm);
    c.response = scene.response == ssr_plant::AngularResponse::kelly ? panel_response::kelly<double>()
                                                                     : panel_response::cosine<double>();
    c.cone_albedo_shape = attitude_estimator::cone_albedo_shape_table(c.response, c.cone_earth_sin_radius);
    return c;
}

}  // namespace montecarlo
