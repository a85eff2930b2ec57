#include "ssr_plant/angular_response.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ssr_plant {
namespace {

constexpr double deg = std::numbers::pi / 180.0;

// Knots of the cubic section (30°…85°) and their slopes (per degree), computed once.
struct KellySpline {
    static constexpr std::size_t n = kelly_table.size() - 1;  // knots from 30° on
    std::array<double, n> x{};
    std::array<double, n> y{};
    std::array<double, n> d{};

    KellySpline() {
        for (std::size_t i = 0; i < n; ++i) {
            x[i] = kelly_table[i + 1].angle_deg;
            y[i] = kelly_table[i + 1].response;
        }
        // The table's 0.866 at 30° is cos 30° rounded; use the exact value so the join with the
        // cosine section is continuous.
        y[0] = std::cos(30.0 * deg);
        d[0] = -std::sin(30.0 * deg) * deg;  // slope of cos at 30°, per degree: C¹ join
        d[n - 1] = 0.0;                      // flat into the zero response beyond 85°: C¹ join
        for (std::size_t i = 1; i + 1 < n; ++i) {
            const double h0 = x[i] - x[i - 1];
            const double h1 = x[i + 1] - x[i];
            const double s0 = (y[i] - y[i - 1]) / h0;
            const double s1 = (y[i + 1] - y[i]) / h1;
            // Fritsch–Butland weighted harmonic mean: keeps the interpolant monotone between knots.
            d[i] = (s0 * s1 <= 0.0) ? 0.0 : 3.0 * (h0 + h1) / ((2.0 * h1 + h0) / s0 + (h1 + 2.0 * h0) / s1);
        }
    }

    double operator()(double a) const {
        std::size_t i = 0;
        while (i + 2 < n && a > x[i + 1]) ++i;
        const double h = x[i + 1] - x[i];
        const double t = (a - x[i]) / h;
        const double t2 = t * t;
        const double t3 = t2 * t;
        return (2 * t3 - 3 * t2 + 1) * y[i] + (t3 - 2 * t2 + t) * h * d[i] + (-2 * t3 + 3 * t2) * y[i + 1] +
               (t3 - t2) * h * d[i + 1];
    }
};

const KellySpline& kelly_spline() {
    static const KellySpline spline;
    return spline;
}

}  // namespace

double cosine_response(double cos_beta) { return std::clamp(cos_beta, 0.0, 1.0); }  // eq. 1

double kelly_response(double beta) {
    const double a = std::abs(beta) / deg;
    if (a <= 30.0) return std::cos(a * deg);
    if (a >= 85.0) return 0.0;
    return std::max(0.0, kelly_spline()(a));
}

double angular_response(AngularResponse law, double cos_beta) {
    const double c = std::clamp(cos_beta, -1.0, 1.0);
    if (law == AngularResponse::cosine) return cosine_response(c);
    // Below 30° the Kelly cosine is the cosine itself: return c directly (acos is ill-conditioned there).
    if (c >= std::cos(30.0 * deg)) return c;
    return kelly_response(std::acos(c));
}

}  // namespace ssr_plant
