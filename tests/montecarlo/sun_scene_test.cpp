// The Monte-Carlo's scene generator: the sun directions it draws are uniform on the sphere, the faces'
// currents are the plant's, and the albedo is the environment's — checked against independent facts
// (moments of the uniform distribution, the plant's documented short-circuit current, the geometry of a
// lit face), never against numbers this generator produced.
#include <cmath>

#include <gtest/gtest.h>

#include "sun_scene.hpp"

namespace {

using montecarlo::SceneConfig;
using montecarlo::SceneGenerator;

TEST(SunScene, SunDirectionsAreUniformOnTheSphere) {
    SceneConfig config;
    config.albedo = false;
    SceneGenerator g(config, 7);
    constexpr int n = 20000;
    std::array<double, 3> mean{}, second{};
    for (int i = 0; i < n; ++i) {
        const auto s = g.next();
        for (int k = 0; k < 3; ++k) {
            mean[k] += s.sun_body[k] / n;
            second[k] += s.sun_body[k] * s.sun_body[k] / n;
        }
        EXPECT_NEAR(std::hypot(s.sun_body[0], s.sun_body[1], s.sun_body[2]), 1.0, 1e-12);
    }
    // Uniform on the sphere: E[s_k] = 0 (σ = 1/sqrt(3n)), E[s_k²] = 1/3 (σ = sqrt(4/45/n)). Five sigma.
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(mean[k], 0.0, 5.0 / std::sqrt(3.0 * n));
        EXPECT_NEAR(second[k], 1.0 / 3.0, 5.0 * std::sqrt(4.0 / 45.0 / n));
    }
}

TEST(SunScene, NormalizationIsThePlantsShortCircuitCurrentAtNormalIncidence) {
    // ssr_plant documents i_sc0 = 0.84754 A for a 10 Wp panel at 1367 W/m² (the estimator's default too).
    SceneGenerator g(SceneConfig{}, 1);
    EXPECT_NEAR(g.i_face_norm(), 0.84754, 1e-4);
}

TEST(SunScene, WithoutAlbedoOnlyFacesTowardTheSunCarryCurrent) {
    SceneConfig config;
    config.albedo = false;
    config.adc_bits = 0;
    config.response = ssr_plant::AngularResponse::cosine;
    SceneGenerator g(config, 3);
    for (int i = 0; i < 500; ++i) {
        const auto s = g.next();
        for (int k = 0; k < 6; ++k) {
            const double cos_beta = (k % 2 == 0 ? 1.0 : -1.0) * s.sun_body[k / 2];
            EXPECT_EQ(s.albedo[k], 0.0);
            if (cos_beta <= 0.0) {
                EXPECT_NEAR(s.i_face[k], 0.0, 1e-6) << "face " << k;
            } else {
                // The short-circuit current is proportional to the irradiance (eq. 2 at V = 0, R_s ≪ R_sh).
                EXPECT_NEAR(s.i_face[k], g.i_face_norm() * cos_beta, 2e-3 * g.i_face_norm()) << "face " << k;
            }
        }
    }
}

TEST(SunScene, AlbedoLightsTheFaceTowardNadir) {
    SceneConfig config;
    config.adc_bits = 0;
    SceneGenerator g(config, 11);
    int nadir_lit = 0, draws = 0;
    for (int i = 0; i < 2000; ++i) {
        const auto s = g.next();
        // The face closest to nadir; the albedo it gets is bounded by the reflectivity times the sun.
        int best = 0;
        for (int k = 1; k < 6; ++k) {
            const double c = (k % 2 == 0 ? 1.0 : -1.0) * s.nadir_body[k / 2];
            const double cb = (best % 2 == 0 ? 1.0 : -1.0) * s.nadir_body[best / 2];
            if (c > cb) best = k;
        }
        for (int k = 0; k < 6; ++k) {
            EXPECT_GE(s.albedo[k], 0.0);
            EXPECT_LE(s.albedo[k], config.reflectivity * config.irradiance);
            const double c = (k % 2 == 0 ? 1.0 : -1.0) * s.nadir_body[k / 2];
            // A face turned more than 90° + the Earth's angular radius (66.6° at 570 km) from nadir sees none of it.
            if (c < -0.95) {
                EXPECT_EQ(s.albedo[k], 0.0) << "face " << k;
            }
        }
        ++draws;
        if (s.albedo[best] > 0.0) ++nadir_lit;
    }
    // Sunlit positions are on the day side more often than not, so most nadir faces see reflected light.
    EXPECT_GT(nadir_lit, draws / 2);
}

}  // namespace
