#include "environment/geomagnetic_field.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "environment/constants.hpp"
#include "ground/igrf_coefficients.hpp"

namespace environment {

namespace {
// The 2025.0 field and its change to 2030.0 laid out as Gauss coefficients once at load time: each evaluation
// then interpolates the same sums (k.at_2025 + f (k.at_2030 - k.at_2025)) without walking the table.
struct IgrfTable {
    GaussCoefficients at_2025, change;
};
// Built on first use: the table it reads is defined in another file (no order of initialization to rely on).
const IgrfTable& igrf_table() {
    static const IgrfTable table = [] {
        IgrfTable t;
        for (const ground::IgrfCoefficient& k : ground::kIgrf14Coefficients) {
            (k.is_h ? t.at_2025.h : t.at_2025.g)[k.n][k.m] = k.at_2025;
            (k.is_h ? t.change.h : t.change.g)[k.n][k.m] = k.at_2030 - k.at_2025;
        }
        return t;
    }();
    return table;
}
}  // namespace

GaussCoefficients igrf_coefficients(double year) {
    if (!(year >= ground::kIgrfFirstYear && year <= ground::kIgrfLastYear)) {
        throw std::domain_error("IGRF-14: date " + std::to_string(year) +
                                " outside the model's 2025.0-2030.0 validity");
    }
    // IGRF: main field at 2025.0 plus the constant predictive secular variation (2030 column = 2025 + 5 SV).
    const double f = (year - ground::kIgrfFirstYear) / (ground::kIgrfLastYear - ground::kIgrfFirstYear);
    const IgrfTable& t = igrf_table();
    GaussCoefficients c;
    for (int n = 1; n <= ground::kIgrfMaxDegree; ++n) {
        for (int m = 0; m <= n; ++m) {
            c.g[n][m] = t.at_2025.g[n][m] + f * t.change.g[n][m];
            c.h[n][m] = t.at_2025.h[n][m] + f * t.change.h[n][m];
        }
    }
    return c;
}

namespace {
// The recursions' constant factors, computed once at load time (square roots otherwise at every synthesis):
// sectoral[n] = sqrt((2n-1)/(2n)) (1 for n = 1); den_inv[n][m] = 1/sqrt(n^2 - m^2); k2[n][m] = sqrt((n-1)^2 - m^2).
struct Recursion {
    double sectoral[14]{};
    double den_inv[14][14]{};
    double k2[14][14]{};
};
const Recursion kRecursion = [] {
    Recursion r;
    for (int n = 1; n <= ground::kIgrfMaxDegree; ++n) {
        r.sectoral[n] = (n == 1) ? 1.0 : std::sqrt((2.0 * n - 1.0) / (2.0 * n));
        for (int m = 0; m < n; ++m) {
            r.den_inv[n][m] = 1.0 / std::sqrt(double(n * n - m * m));
            r.k2[n][m] = (n >= 2) ? std::sqrt(double((n - 1) * (n - 1) - m * m)) : 0.0;
        }
    }
    return r;
}();
}  // namespace

Eigen::Vector3d spherical_harmonic_field(const GaussCoefficients& c, int max_degree, const Eigen::Vector3d& r_ecef) {
    if (max_degree < 1 || max_degree > ground::kIgrfMaxDegree)
        throw std::invalid_argument("spherical_harmonic_field: degree 1..13");
    const double r = r_ecef.norm();
    if (!(r > 1000.0) || !std::isfinite(r))
        throw std::invalid_argument("spherical_harmonic_field: position below 1 km or not finite");
    const double rho = std::sqrt(r_ecef.x() * r_ecef.x() + r_ecef.y() * r_ecef.y());
    const double ct = r_ecef.z() / r;  // cos(colatitude)
    // sin(colatitude) kept away from 0 so B_phi (which divides by it) stays finite at the poles; the
    // error this makes is below 1e-9 relative since every P_n^m with m > 0 carries a factor sin theta.
    const double st = std::max(rho / r, 1e-12);
    // cos and sin of the longitude from the position itself (atan2(0, 0) = 0 on the axis: cos 1, sin 0).
    const double cl = rho > 0.0 ? r_ecef.x() / rho : 1.0;
    const double sl = rho > 0.0 ? r_ecef.y() / rho : 0.0;

    // Schmidt semi-normalised P_n^m(cos theta) and dP/dtheta by the standard recursions.
    const Recursion& k = kRecursion;
    double p[14][14] = {};
    double dp[14][14] = {};
    p[0][0] = 1.0;
    for (int n = 1; n <= max_degree; ++n) {
        // Sectoral terms: P_1^1 = sin theta; P_n^n = sqrt((2n-1)/(2n)) sin theta P_{n-1}^{n-1} for n >= 2.
        p[n][n] = k.sectoral[n] * st * p[n - 1][n - 1];
        dp[n][n] = k.sectoral[n] * (ct * p[n - 1][n - 1] + st * dp[n - 1][n - 1]);
        // P_n^m = [(2n-1) cos theta P_{n-1}^m - sqrt((n-1)^2 - m^2) P_{n-2}^m] / sqrt(n^2 - m^2)
        for (int m = 0; m < n; ++m) {
            const double pm2 = (n >= 2) ? p[n - 2][m] : 0.0;
            const double dpm2 = (n >= 2) ? dp[n - 2][m] : 0.0;
            p[n][m] = ((2.0 * n - 1.0) * ct * p[n - 1][m] - k.k2[n][m] * pm2) * k.den_inv[n][m];
            dp[n][m] = ((2.0 * n - 1.0) * (ct * dp[n - 1][m] - st * p[n - 1][m]) - k.k2[n][m] * dpm2) * k.den_inv[n][m];
        }
    }
    // cos(m lon), sin(m lon) by the angle-addition recurrence (m <= 13: a few ulp).
    double cos_m[14], sin_m[14];
    cos_m[0] = 1.0;
    sin_m[0] = 0.0;
    for (int m = 1; m <= max_degree; ++m) {
        cos_m[m] = cos_m[m - 1] * cl - sin_m[m - 1] * sl;
        sin_m[m] = sin_m[m - 1] * cl + cos_m[m - 1] * sl;
    }
    // B = -grad V (nT): B_r = sum (n+1)(a/r)^(n+2) ..., B_theta = -sum (a/r)^(n+2) ... dP/dtheta,
    // B_phi = sum (a/r)^(n+2) m (g sin - h cos) P / sin theta.
    const double ar = kIgrfReferenceRadius / r;
    double ratio = ar * ar;  // (a/r)^(n+2) for n = 0; multiplied up each degree
    double br = 0.0, bt = 0.0, bp = 0.0;
    for (int n = 1; n <= max_degree; ++n) {
        ratio *= ar;
        double sr = 0.0, stt = 0.0, sp = 0.0;
        for (int m = 0; m <= n; ++m) {
            const double gc = c.g[n][m] * cos_m[m] + c.h[n][m] * sin_m[m];
            sr += gc * p[n][m];
            stt += gc * dp[n][m];
            sp += m * (c.g[n][m] * sin_m[m] - c.h[n][m] * cos_m[m]) * p[n][m];
        }
        br += (n + 1) * ratio * sr;
        bt -= ratio * stt;
        bp += ratio * sp;
    }
    bp /= st;
    // Local spherical unit vectors in ECEF.
    const Eigen::Vector3d e_r(st * cl, st * sl, ct);
    const Eigen::Vector3d e_t(ct * cl, ct * sl, -st);
    const Eigen::Vector3d e_p(-sl, cl, 0.0);
    return 1e-9 * (br * e_r + bt * e_t + bp * e_p);
}

Eigen::Vector3d dipole_field(const GaussCoefficients& c, const Eigen::Vector3d& r_ecef) {
    const double r = r_ecef.norm();
    if (!(r > 1000.0) || !std::isfinite(r))
        throw std::invalid_argument("dipole_field: position below 1 km or not finite");
    const Eigen::Vector3d g1(c.g[1][1], c.h[1][1], c.g[1][0]);
    const double b0 = g1.norm();
    // V = a^3 (g1 . r)/r^3  =>  B = -grad V = (a/r)^3 [3 (g1 . r^) r^ - g1]; g10 < 0, so m points south.
    const Eigen::Vector3d m = g1 / b0;  // dipole moment direction
    const Eigen::Vector3d rh = r_ecef / r;
    const double ar = kIgrfReferenceRadius / r;
    return 1e-9 * b0 * ar * ar * ar * (3.0 * m.dot(rh) * rh - m);
}

}  // namespace environment
