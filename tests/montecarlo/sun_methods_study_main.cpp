// sun_methods_study: the issue-8 Monte-Carlo table. For the plant's Kelly (and, for reference, cosine)
// panels, with and without Earth albedo, scores every sun method of the estimator core over the same
// random scenes and prints a Markdown table (angular error in degrees over the valid estimates); then the
// Kelly panels with albedo once more, each face at a random cell temperature within an orbit's swing
// (−40 … +80 °C) while the estimator is normalized at the datasheet's 25 °C (issue 19 item 3).
//   sun_methods_study [--samples N] [--seed S] [--bits B]
#include <cstdio>
#include <string>

#include <CLI/CLI.hpp>

#include "sun_method_study.hpp"

namespace {

void print_rows(const montecarlo::SceneConfig& scene, std::size_t samples, std::uint64_t seed) {
    const bool warm = scene.temperature_max > scene.temperature_min;
    for (const auto& s : montecarlo::run_study(scene, samples, seed)) {
        std::printf("| %s | %s | %s | %s | %.2f %% | %.3f | %.3f | %.3f | %.3f | %zu |\n",
                    scene.response == ssr_plant::AngularResponse::kelly ? "Kelly" : "cosine",
                    scene.albedo ? "0.3" : "off", warm ? "−40 … +80 °C" : "25 °C",
                    attitude_estimator::sun_method_name(s.method),
                    100.0 * static_cast<double>(s.valid) / static_cast<double>(s.samples), s.mean_deg, s.median_deg,
                    s.p95_deg, s.max_deg, s.faces_rejected);
    }
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Monte-Carlo study of the estimator's sun methods over random sunlit scenes"};
    std::size_t samples = 10000;
    std::uint64_t seed = 1;
    unsigned bits = 12;
    app.add_option("--samples", samples, "Scenes per case (uniform sun directions in body axes)")
        ->check(CLI::Range(std::size_t{1}, std::size_t{100000000}));
    app.add_option("--seed", seed, "Seed of the scene generator");
    app.add_option("--bits", bits, "A/D converter resolution of the face currents (0 = ideal)")
        ->check(CLI::Range(0u, 24u));
    CLI11_PARSE(app, argc, argv);

    std::printf(
        "| panels | albedo | cells | method | valid | mean ° | median ° | 95th pct ° | max ° | scenes with a face "
        "rejected |\n");
    std::printf("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
    for (auto response : {ssr_plant::AngularResponse::kelly, ssr_plant::AngularResponse::cosine}) {
        for (bool albedo : {false, true}) {
            montecarlo::SceneConfig scene;
            scene.response = response;
            scene.albedo = albedo;
            scene.adc_bits = bits;
            if (!albedo) {
                const auto f = montecarlo::dark_band_floor(scene, samples, seed);
                std::printf(
                    "| %s | — | 25 °C | (floor: unseen components set to 0) | — | %.3f | %.3f | %.3f | %.3f | — |\n",
                    response == ssr_plant::AngularResponse::kelly ? "Kelly" : "cosine", f.mean_deg, f.median_deg,
                    f.p95_deg, f.max_deg);
            }
            print_rows(scene, samples, seed);
        }
    }
    montecarlo::SceneConfig hot_and_cold;  // Kelly panels, albedo 0.3
    hot_and_cold.adc_bits = bits;
    hot_and_cold.temperature_min = 233.15;
    hot_and_cold.temperature_max = 353.15;
    print_rows(hot_and_cold, samples, seed);
    return 0;
}
