#include "attitude_estimator/onboard_field.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ground/igrf_coefficients.hpp"

namespace attitude_estimator {

namespace {
constexpr double kReferenceRadius = 6371200.0;  // m, IGRF's magnetic reference sphere
constexpr int kSize = kFieldMaxDegree + 1;
}  // namespace

template <class T>
FieldModel<T> make_field_model(std::int32_t degree) noexcept {
    FieldModel<T> model;
    model.degree = std::clamp(degree, std::int32_t{1}, kFieldMaxDegree);
    model.base_year = static_cast<T>(ground::kIgrfFirstYear);
    const double span = ground::kIgrfLastYear - ground::kIgrfFirstYear;
    for (const ground::IgrfCoefficient& k : ground::kIgrf14Coefficients) {
        if (k.n > model.degree) continue;
        const T value = static_cast<T>(k.at_2025);
        const T rate = static_cast<T>((k.at_2030 - k.at_2025) / span);
        (k.is_h ? model.h : model.g)[k.n][k.m] = value;
        (k.is_h ? model.h_rate : model.g_rate)[k.n][k.m] = rate;
    }
    return model;
}

double omitted_field_rms(std::int32_t degree, double radius, double year) noexcept {
    // From the coefficients themselves, not a model of degree 13: a 6 kB temporary the firmware's stack should
    // not carry.
    const double dt = year - ground::kIgrfFirstYear, ratio = kReferenceRadius / radius;
    const double span = ground::kIgrfLastYear - ground::kIgrfFirstYear;
    double mean_square = 0.0;  // nT²
    for (const ground::IgrfCoefficient& k : ground::kIgrf14Coefficients) {
        if (k.n <= degree) continue;
        const double value = k.at_2025 + (k.at_2030 - k.at_2025) / span * dt;
        mean_square += (k.n + 1) * std::pow(ratio, 2 * k.n + 4) * value * value;
    }
    return 1e-9 * std::sqrt(mean_square / 3.0);
}

template <class T>
Vec3<T> field_ecef(const FieldModel<T>& model, const Vec3<T>& r_ecef, T year) noexcept {
    const int degree = model.degree;
    const T r = std::sqrt(r_ecef[0] * r_ecef[0] + r_ecef[1] * r_ecef[1] + r_ecef[2] * r_ecef[2]);
    const T rho = std::sqrt(r_ecef[0] * r_ecef[0] + r_ecef[1] * r_ecef[1]);
    const T ct = r_ecef[2] / r;  // cos(colatitude)
    // sin(colatitude) kept off 0 so that B_phi (divided by it) stays finite over a pole; every P_n^m with
    // m > 0 carries a factor sin θ, so the error is of that order.
    const T st = std::max(rho / r, T(16) * std::numeric_limits<T>::epsilon());
    const T cl = rho > T(0) ? r_ecef[0] / rho : T(1);  // cos, sin of the longitude
    const T sl = rho > T(0) ? r_ecef[1] / rho : T(0);

    // Schmidt semi-normalised P_n^m(cos θ) and dP/dθ.
    T p[kSize][kSize] = {};
    T dp[kSize][kSize] = {};
    p[0][0] = T(1);
    for (int n = 1; n <= degree; ++n) {
        // P_n^n = sqrt((2n−1)/(2n)) sin θ P_{n−1}^{n−1} (the factor is 1 for n = 1).
        const T k = n == 1 ? T(1) : std::sqrt(T(2 * n - 1) / T(2 * n));
        p[n][n] = k * st * p[n - 1][n - 1];
        dp[n][n] = k * (ct * p[n - 1][n - 1] + st * dp[n - 1][n - 1]);
        // P_n^m = [(2n−1) cos θ P_{n−1}^m − sqrt((n−1)² − m²) P_{n−2}^m] / sqrt(n² − m²)
        for (int m = 0; m < n; ++m) {
            const T den = std::sqrt(T(n * n - m * m));
            const T k2 = n >= 2 ? std::sqrt(T((n - 1) * (n - 1) - m * m)) : T(0);
            const T pm2 = n >= 2 ? p[n - 2][m] : T(0);
            const T dpm2 = n >= 2 ? dp[n - 2][m] : T(0);
            p[n][m] = (T(2 * n - 1) * ct * p[n - 1][m] - k2 * pm2) / den;
            dp[n][m] = (T(2 * n - 1) * (ct * dp[n - 1][m] - st * p[n - 1][m]) - k2 * dpm2) / den;
        }
    }
    // cos mφ, sin mφ by the angle-sum recursion (no trigonometric call per order).
    T cos_m[kSize], sin_m[kSize];
    cos_m[0] = T(1);
    sin_m[0] = T(0);
    for (int m = 1; m <= degree; ++m) {
        cos_m[m] = cos_m[m - 1] * cl - sin_m[m - 1] * sl;
        sin_m[m] = sin_m[m - 1] * cl + cos_m[m - 1] * sl;
    }
    // B = −grad V: B_r = Σ (n+1)(a/r)^(n+2) Σ_m (g cos + h sin) P, B_θ = −Σ (a/r)^(n+2) Σ_m (…) dP/dθ,
    // B_φ = Σ (a/r)^(n+2) Σ_m m (g sin − h cos) P / sin θ.
    const T dt = year - model.base_year;
    const T ar = T(kReferenceRadius) / r;
    T ratio = ar * ar;
    T br = T(0), bt = T(0), bp = T(0);
    for (int n = 1; n <= degree; ++n) {
        ratio *= ar;
        T sr = T(0), stt = T(0), sp = T(0);
        for (int m = 0; m <= n; ++m) {
            const T g = model.g[n][m] + model.g_rate[n][m] * dt;
            const T h = model.h[n][m] + model.h_rate[n][m] * dt;
            const T gc = g * cos_m[m] + h * sin_m[m];
            sr += gc * p[n][m];
            stt += gc * dp[n][m];
            sp += T(m) * (g * sin_m[m] - h * cos_m[m]) * p[n][m];
        }
        br += T(n + 1) * ratio * sr;
        bt -= ratio * stt;
        bp += ratio * sp;
    }
    bp /= st;
    // Local spherical unit vectors in Earth-fixed axes; nT → T.
    const T e_r[3] = {st * cl, st * sl, ct};
    const T e_t[3] = {ct * cl, ct * sl, -st};
    const T e_p[3] = {-sl, cl, T(0)};
    Vec3<T> b;
    for (int i = 0; i < 3; ++i) b[i] = T(1e-9) * (br * e_r[i] + bt * e_t[i] + bp * e_p[i]);
    return b;
}

template FieldModel<float> make_field_model(std::int32_t) noexcept;
template FieldModel<double> make_field_model(std::int32_t) noexcept;
template Vec3<float> field_ecef(const FieldModel<float>&, const Vec3<float>&, float) noexcept;
template Vec3<double> field_ecef(const FieldModel<double>&, const Vec3<double>&, double) noexcept;

}  // namespace attitude_estimator
