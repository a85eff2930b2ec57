// The cones method's albedo shape G(cos θ) (cone_albedo_shape.hpp): the table integrated for a response
// against the closed-form view factor (cosine) and against an independent integral of the Kelly response
// in the angle parametrization (Kelly).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "attitude_estimator/cone_albedo_shape.hpp"
#include "panel_response/kelly.hpp"

namespace {

using namespace attitude_estimator;

constexpr double kSinRadius = 0.91788;  // 570 km

// G by midpoint quadrature in the polar angle γ ∈ [0, λ] (dΩ = sin γ dγ dφ, φ over the full circle) and the
// response as a function of the incidence angle — a parametrization and an entry point the table does not use.
double reference_g(const panel_response::Response<double>& r, double cos_t, int n) {
    const double pi = std::numbers::pi;
    const double lambda = std::asin(kSinRadius);
    const double sin_t = std::sqrt(1.0 - cos_t * cos_t);
    const double dg = lambda / n, dp = 2.0 * pi / (2 * n);
    double sum = 0.0;
    for (int a = 0; a < n; ++a) {
        const double g = (a + 0.5) * dg;
        for (int b = 0; b < 2 * n; ++b) {
            const double phi = (b + 0.5) * dp;
            const double c = sin_t * std::sin(g) * std::cos(phi) + cos_t * std::cos(g);
            if (c <= 0.0) continue;
            sum += panel_response::response_from_angle(r, std::acos(std::min(1.0, c))) * std::sin(g);
        }
    }
    return sum * dg * dp / (pi * kSinRadius * kSinRadius);
}

TEST(EstimatorCoreConeAlbedo, CosineTableMatchesTheClosedFormViewFactor) {
    const auto table = cone_albedo_shape_table(panel_response::cosine<double>(), kSinRadius);
    ASSERT_TRUE(table.valid);
    double worst = 0.0;
    for (int i = 0; i <= 400; ++i) {
        const double c = -1.0 + i * 0.005;
        worst = std::max(worst,
                         std::abs(cone_albedo_shape(table, c, kSinRadius) - cone_albedo_shape_cosine(c, kSinRadius)));
    }
    EXPECT_LT(worst, 2e-3);
    EXPECT_NEAR(cone_albedo_shape_cosine(1.0, kSinRadius), 1.0, 1e-15);
    EXPECT_EQ(cone_albedo_shape_cosine(-0.95, kSinRadius), 0.0);
    // G(c) − G(−c) = c: the net flux through a plate is linear in its normal.
    for (double c : {0.1, 0.4, 0.8})
        EXPECT_NEAR(cone_albedo_shape_cosine(c, kSinRadius) - cone_albedo_shape_cosine(-c, kSinRadius), c, 1e-12);
}

TEST(EstimatorCoreConeAlbedo, KellyTableMatchesAnIndependentIntegral) {
    const auto kelly = panel_response::kelly<double>();
    const auto table = cone_albedo_shape_table(kelly, kSinRadius);
    ASSERT_TRUE(table.valid);
    for (double c : {-0.9, -0.6, -0.3, 0.0, 0.2, 0.5, 0.8, 0.95, 1.0})
        EXPECT_NEAR(cone_albedo_shape(table, c, kSinRadius), reference_g(kelly, c, 300), 2e-3) << "cos θ = " << c;
    // The Kelly panels see the disc's grazing part weaker than a cosine plate: less everywhere, and the
    // side faces (θ = 90°) lose far more than the nadir face.
    const double nadir = cone_albedo_shape(table, 1.0, kSinRadius);
    const double side = cone_albedo_shape(table, 0.0, kSinRadius);
    EXPECT_LT(nadir, 1.0);
    EXPECT_LT(side / cone_albedo_shape_cosine(0.0, kSinRadius), nadir);
}

TEST(EstimatorCoreConeAlbedo, FloatTableAgreesAndAMismatchedRadiusFallsBackToTheClosedForm) {
    const auto d = cone_albedo_shape_table(panel_response::kelly<double>(), kSinRadius);
    const auto f = cone_albedo_shape_table(panel_response::kelly<float>(), static_cast<float>(kSinRadius));
    for (int i = 0; i < kConeAlbedoShapePoints; ++i) EXPECT_NEAR(f.g[i], d.g[i], 2e-5);
    // A table built for another altitude is not used for this one.
    EXPECT_EQ(cone_albedo_shape(d, 0.3, 0.9), cone_albedo_shape_cosine(0.3, 0.9));
    EXPECT_FALSE(cone_albedo_shape_table(panel_response::kelly<double>(), 1.0).valid);
}

}  // namespace
