// Relative angular response of a PV panel's short-circuit current to the sun's incidence angle β
// (0 = normal incidence), and its inverse: seed 000 eq. 1 (the cosine law) and the Kelly cosine of fig. 4
// (Patel 1999) as a table of knots. Header-only, allocation-free, noexcept, templated on float and double,
// so that the plant (ssr_plant) and the on-board estimator (attitude_estimator, -fno-exceptions) share one
// definition of the curve.
//
// The table law is the plant's function exactly: cos β up to the second knot (30°, whose tabulated 0.866 is
// replaced by the exact cos 30° so the join is continuous), then a cubic Hermite through the remaining knots
// with Fritsch–Butland slopes (monotone between knots), the slope of cos at the first join and slope 0 at the
// last knot (C¹ at both ends), and 0 from the last knot (85°) on.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

namespace panel_response {

enum class Law { cosine, table };

template <class T>
struct Knot {
    T angle_deg;
    T response;
};

// Kelly cosine as tabulated by Patel (1999), reproduced as fig. 4 of seed 000 (the plant's table).
template <class T>
inline constexpr std::array<Knot<T>, 6> kKellyTable = {
    {{T(0), T(1)}, {T(30), T(0.866)}, {T(50), T(0.635)}, {T(60), T(0.450)}, {T(80), T(0.100)}, {T(85), T(0)}}};

// Largest number of Hermite knots a Response can hold (from the cosine join to the last knot).
inline constexpr std::size_t kMaxKnots = 8;

namespace detail {
inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kDeg = kPi / 180.0;
// cos and sin by their Taylor series, for constant evaluation of the knot data (|x| ≤ π/2 here; 30 terms
// reach double precision). Run-time code uses <cmath>.
constexpr double cos_series(double x) noexcept {
    double term = 1.0, sum = 1.0;
    for (int k = 1; k < 30; ++k) {
        term *= -x * x / ((2.0 * k - 1.0) * (2.0 * k));
        sum += term;
    }
    return sum;
}
constexpr double sin_series(double x) noexcept {
    double term = x, sum = x;
    for (int k = 1; k < 30; ++k) {
        term *= -x * x / ((2.0 * k) * (2.0 * k + 1.0));
        sum += term;
    }
    return sum;
}
}  // namespace detail

// One angular response law. For Law::table: x[i] (degrees), y[i] (relative response) and d[i] (slope per
// degree) for i < n are the Hermite knots from the cosine join x[0] to the zero x[n-1]; cos_join = cos x[0].
template <class T>
struct Response {
    Law law = Law::cosine;
    std::size_t n = 0;
    std::array<T, kMaxKnots> x{};
    std::array<T, kMaxKnots> y{};
    std::array<T, kMaxKnots> d{};
    T cos_join = T(1);
};

// eq. 1 of seed 000: I_sc = I_sc|β=0 · cos β.
template <class T>
constexpr Response<T> cosine() noexcept {
    return Response<T>{};
}

// A table law from knots (angle_deg, response): knot 0 must be (0°, 1), the cosine holds up to knot 1, the
// last knot is where the response reaches its final value (0 for the Kelly cosine). Needs 3 ≤ N ≤ kMaxKnots+1
// knots with increasing angles below 90°; anything else yields the cosine law. Slopes are computed in double
// whatever T is, exactly as ssr_plant computes them.
template <class T, std::size_t N>
constexpr Response<T> table(const std::array<Knot<T>, N>& knots) noexcept {
    Response<T> r{};
    if constexpr (N < 3 || N - 1 > kMaxKnots) {
        return r;
    } else {
        for (std::size_t i = 1; i < N; ++i)
            if (!(knots[i].angle_deg > knots[i - 1].angle_deg) || !(knots[i].angle_deg < T(90))) return r;
        constexpr std::size_t n = N - 1;
        std::array<double, n> x{}, y{}, d{};
        for (std::size_t i = 0; i < n; ++i) {
            x[i] = static_cast<double>(knots[i + 1].angle_deg);
            y[i] = static_cast<double>(knots[i + 1].response);
        }
        // The tabulated value at the join is cos rounded: use the exact cosine (continuous join).
        y[0] = detail::cos_series(x[0] * detail::kDeg);
        d[0] = -detail::sin_series(x[0] * detail::kDeg) * detail::kDeg;  // slope of cos, per degree: C¹ join
        d[n - 1] = 0.0;                                                  // flat into the final value: C¹ join
        for (std::size_t i = 1; i + 1 < n; ++i) {
            const double h0 = x[i] - x[i - 1];
            const double h1 = x[i + 1] - x[i];
            const double s0 = (y[i] - y[i - 1]) / h0;
            const double s1 = (y[i + 1] - y[i]) / h1;
            // Fritsch–Butland weighted harmonic mean: monotone between knots.
            d[i] = (s0 * s1 <= 0.0) ? 0.0 : 3.0 * (h0 + h1) / ((2.0 * h1 + h0) / s0 + (h1 + 2.0 * h0) / s1);
        }
        r.law = Law::table;
        r.n = n;
        for (std::size_t i = 0; i < n; ++i) {
            r.x[i] = static_cast<T>(x[i]);
            r.y[i] = static_cast<T>(y[i]);
            r.d[i] = static_cast<T>(d[i]);
        }
        r.cos_join = static_cast<T>(y[0]);
        return r;
    }
}

// The plant's Kelly cosine (kKellyTable).
template <class T>
constexpr Response<T> kelly() noexcept {
    return table<T>(kKellyTable<T>);
}

// The cubic Hermite section of a table law at a_deg (degrees, within [x[0], x[n-1]]).
template <class T>
constexpr T hermite(const Response<T>& r, T a) noexcept {
    std::size_t i = 0;
    while (i + 2 < r.n && a > r.x[i + 1]) ++i;
    const T h = r.x[i + 1] - r.x[i];
    const T t = (a - r.x[i]) / h;
    const T t2 = t * t;
    const T t3 = t2 * t;
    return (2 * t3 - 3 * t2 + 1) * r.y[i] + (t3 - 2 * t2 + t) * h * r.d[i] + (-2 * t3 + 3 * t2) * r.y[i + 1] +
           (t3 - t2) * h * r.d[i + 1];
}

// Relative response at the incidence angle β (radians; the sign is ignored): 1 at normal incidence.
template <class T>
inline T response_from_angle(const Response<T>& r, T beta) noexcept {
    constexpr T deg = static_cast<T>(detail::kDeg);
    if (r.law == Law::cosine) {
        const T c = std::cos(beta);
        return c > T(0) ? c : T(0);
    }
    const T a = std::abs(beta) / deg;
    if (a <= r.x[0]) return std::cos(a * deg);
    if (a >= r.x[r.n - 1]) return r.y[r.n - 1] > T(0) ? r.y[r.n - 1] : T(0);
    const T v = hermite(r, a);
    return v > T(0) ? v : T(0);
}

// Relative response as a function of cos β (the dot product of the sun direction and the face normal); 0
// for a face turned away. Identical operations to ssr_plant::angular_response.
template <class T>
inline T response_from_cos(const Response<T>& r, T cos_beta) noexcept {
    T c = cos_beta < T(-1) ? T(-1) : (cos_beta > T(1) ? T(1) : cos_beta);
    if (std::isnan(c)) return T(0);  // NaN: no light
    if (r.law == Law::cosine) return c > T(0) ? c : T(0);
    // Below the join the response is cos β itself: return c directly (acos is ill-conditioned there).
    if (c >= r.cos_join) return c;
    return response_from_angle(r, std::acos(c));
}

// The inverse: cos β from a relative response `resp`. Monotone non-decreasing in resp; resp ≥ 1 gives 1
// (normal incidence; a brighter-than-full-sun reading is clipped), resp ≤ 0 or NaN gives 0. On the flat zero
// tail of a table law (85°…90° for Kelly) the response is 0 for every cos β in [0, cos x[n-1]]: a reading of
// 0 cannot say where in that range the face is, and the inverse returns 0 (use `dark_cos` for the bound).
// Inside the Hermite section the angle is found by Newton's method safeguarded by bisection on the bracketing
// knot interval, where the curve is monotone.
template <class T>
inline T cos_from_response(const Response<T>& r, T resp) noexcept {
    if (!(resp > T(0))) return T(0);
    if (resp >= T(1)) return T(1);
    if (r.law == Law::cosine) return resp;
    if (resp >= r.cos_join) return resp;
    const std::size_t last = r.n - 1;
    if (!(resp > r.y[last])) return static_cast<T>(std::cos(static_cast<T>(detail::kDeg) * r.x[last]));
    // Bracket: y[i] ≥ resp > y[i+1] on a decreasing curve.
    std::size_t i = 0;
    while (i + 1 < last && resp <= r.y[i + 1]) ++i;
    T lo = r.x[i], hi = r.x[i + 1];  // f(lo) ≥ 0 > f(hi) for f(a) = hermite(a) − resp
    T a = lo + (hi - lo) * (r.y[i] - resp) / (r.y[i] - r.y[i + 1]);  // secant start
    for (int iter = 0; iter < 100; ++iter) {
        const T f = hermite(r, a) - resp;
        if (f == T(0)) break;
        if (f > T(0))
            lo = a;
        else
            hi = a;
        // Derivative of the Hermite cubic on segment i (per degree).
        const T h = r.x[i + 1] - r.x[i];
        const T t = (a - r.x[i]) / h;
        const T df = ((6 * t * t - 6 * t) * r.y[i] + (3 * t * t - 4 * t + 1) * h * r.d[i] +
                      (-6 * t * t + 6 * t) * r.y[i + 1] + (3 * t * t - 2 * t) * h * r.d[i + 1]) /
                     h;
        T next = (df < T(0)) ? a - f / df : (lo + hi) / 2;
        if (!(next > lo && next < hi)) next = (lo + hi) / 2;  // Newton left the bracket: bisect
        if (next == a || hi - lo <= T(4) * std::numeric_limits<T>::epsilon() * hi) {
            a = next;
            break;
        }
        a = next;
    }
    return std::cos(a * static_cast<T>(detail::kDeg));
}

// Incidence angle β (radians, in [0, π/2]) from a relative response: acos of cos_from_response.
template <class T>
inline T angle_from_response(const Response<T>& r, T resp) noexcept {
    return std::acos(cos_from_response(r, resp));
}

// The largest cos β a face can have while its response stays at or below `threshold`: a face read as dark
// (relative response ≤ threshold) has its sun component in [−1, dark_cos]. With the cosine law this is the
// threshold itself; with the Kelly cosine it is at least cos 85° = 0.0872 (the flat zero tail).
template <class T>
inline T dark_cos(const Response<T>& r, T threshold) noexcept {
    if (r.law == Law::table && !(threshold > r.y[r.n - 1]))
        return static_cast<T>(std::cos(static_cast<T>(detail::kDeg) * r.x[r.n - 1]));
    return cos_from_response(r, threshold);
}

}  // namespace panel_response
