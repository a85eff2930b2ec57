#include "environment/earth_albedo.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "environment/constants.hpp"
#include "panel_response/kelly.hpp"

namespace environment {

namespace {
// Gauss-Legendre nodes and weights on [-1, 1] (Newton iteration on P_n; Golub-Welsch would do too).
// The integrand is smooth in gamma up to the horizon (the emission cosine goes linearly to zero), so
// Gauss-Legendre in gamma converges much faster than a midpoint rule; only the terminator adds a kink.
void gauss_legendre(int n, std::vector<double>& x, std::vector<double>& w) {
    x.resize(n);
    w.resize(n);
    for (int i = 0; i < n; ++i) {
        double z = std::cos(kPi * (i + 0.75) / (n + 0.5));
        double dp = 1.0;
        for (int iter = 0; iter < 100; ++iter) {
            double p0 = 1.0, p1 = z;
            for (int k = 2; k <= n; ++k) {
                const double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            if (n == 1) p0 = 1.0;
            dp = n * (z * p1 - p0) / (z * z - 1.0);
            const double step = p1 / dp;
            z -= step;
            if (std::abs(step) < 1e-15) break;
        }
        x[i] = z;
        w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
    }
}
// The Kelly response f(cos θ) tabulated once, at load time (panel_response's curve, acos and a Hermite per call
// otherwise) on a uniform grid in cos θ; linear interpolation between 1025 points is within 3e-6 of the curve.
constexpr int kKellyGrid = 1024;
const std::array<double, kKellyGrid + 1> kKellyTable = [] {
    constexpr auto law = panel_response::kelly<double>();
    std::array<double, kKellyGrid + 1> t{};
    for (int i = 0; i <= kKellyGrid; ++i)
        t[i] = panel_response::response_from_cos(law, static_cast<double>(i) / kKellyGrid);
    return t;
}();
double kelly_of_cos(double c) {
    const double x = std::clamp(c, 0.0, 1.0) * kKellyGrid;
    const int i = std::min(static_cast<int>(x), kKellyGrid - 1);
    return kKellyTable[i] + (x - i) * (kKellyTable[i + 1] - kKellyTable[i]);
}

void check(const AlbedoParams& params) {
    if (params.model == ReflectivityModel::zonal &&
        !(params.reflectivity_equator >= 0.0 && params.reflectivity_equator <= 1.0 && params.reflectivity_pole >= 0.0 &&
          params.reflectivity_pole <= 1.0))
        throw std::invalid_argument("earth_albedo: zonal reflectivities must be in [0, 1]");
    if (params.rings < 1 || params.sectors < 3) throw std::invalid_argument("earth_albedo: rings >= 1, sectors >= 3");
}

bool dark(const AlbedoParams& params, double solar_irradiance) {
    if (!params.enabled || solar_irradiance <= 0.0) return true;
    return params.model == ReflectivityModel::uniform && params.reflectivity <= 0.0;
}

}  // namespace

namespace {
// The sunlit visible cap as quadrature elements: visit(a, d, inv_l) for every element with a the radiance
// times cos(emission) times area over l^2 and times cos(solar zenith) (W/m^2 on a face squarely facing it),
// d the unnormalised direction satellite -> element in the axes of `frame` (frame = A: body axes) and inv_l
// its 1/length. Polar grid about the sub-satellite point; the visible cap ends where the line of sight is
// tangent.
template <class Visit>
void visit_sunlit_cap(const AlbedoParams& params, CapScratch& scratch, const Eigen::Vector3d& r_sat,
                      const Eigen::Vector3d& sun_direction, double solar_irradiance, const Eigen::Matrix3d& frame,
                      Visit&& visit) {
    const bool zonal = params.model == ReflectivityModel::zonal;
    const double r = r_sat.norm();
    if (!(r > kEarthRadius)) throw std::invalid_argument("earth_albedo: satellite below the Earth's surface");
    const Eigen::Vector3d e3 = r_sat / r;
    Eigen::Vector3d e1 = e3.unitOrthogonal();
    const Eigen::Vector3d e2 = e3.cross(e1);
    const double gamma_max = std::acos(kEarthRadius / r);
    if (scratch.rings != params.rings || scratch.sectors != params.sectors) {
        gauss_legendre(params.rings, scratch.node, scratch.weight);
        scratch.cos_psi.resize(params.sectors);
        scratch.sin_psi.resize(params.sectors);
        const double step = 2.0 * kPi / params.sectors;
        for (int j = 0; j < params.sectors; ++j) {
            scratch.cos_psi[j] = std::cos((j + 0.5) * step);
            scratch.sin_psi[j] = std::sin((j + 0.5) * step);
        }
        scratch.horizontal.resize(params.sectors);
        scratch.sun_horizontal.resize(params.sectors);
        scratch.polar_horizontal.resize(params.sectors);
        scratch.rings = params.rings;
        scratch.sectors = params.sectors;
    }
    const double dpsi = 2.0 * kPi / params.sectors;
    const double s_dot_e3 = sun_direction.dot(e3);
    const double s_dot_e1 = sun_direction.dot(e1);
    const double s_dot_e2 = sun_direction.dot(e2);
    // Radiance per unit cos(zenith): L = rho E cos z / pi (zonal: rho applied per element below).
    const double radiance_scale = (zonal ? 1.0 : params.reflectivity) * solar_irradiance / kPi;
    const double rho_eq = params.reflectivity_equator,
                 rho_step = params.reflectivity_pole - params.reflectivity_equator;

    // Per sector, the horizontal direction psi in the frame's axes and the sun's component along it (the
    // same on every ring).
    const Eigen::Vector3d b1 = frame * e1, b2 = frame * e2, b3 = frame * e3;
    for (int j = 0; j < params.sectors; ++j) {
        scratch.horizontal[j] = scratch.cos_psi[j] * b1 + scratch.sin_psi[j] * b2;
        scratch.sun_horizontal[j] = scratch.cos_psi[j] * s_dot_e1 + scratch.sin_psi[j] * s_dot_e2;
        scratch.polar_horizontal[j] = scratch.cos_psi[j] * e1.z() + scratch.sin_psi[j] * e2.z();
    }
    for (int i = 0; i < params.rings; ++i) {
        const double gamma = 0.5 * gamma_max * (scratch.node[i] + 1.0);
        const double cg = std::cos(gamma), sg = std::sin(gamma);
        const double area = kEarthRadius * kEarthRadius * sg * (0.5 * gamma_max * scratch.weight[i]) * dpsi;
        // Satellite -> element: d = R p^ - r e3; its length depends on gamma only.
        const double l2 = kEarthRadius * kEarthRadius + r * r - 2.0 * kEarthRadius * r * cg;
        const double l = std::sqrt(l2);
        // cos of the emission angle at the element: -p^ . d/l = (r cos gamma - R)/l
        const double cos_emit = (r * cg - kEarthRadius) / l;
        if (cos_emit <= 0.0) continue;
        const double ring_scale = radiance_scale * cos_emit * area / l2;
        // d in the frame's axes (unnormalised): (R cos gamma - r) b3 + R sin gamma h(psi)
        const Eigen::Vector3d vertical = (kEarthRadius * cg - r) * b3;
        const double radial = kEarthRadius * sg;
        const double inv_l = 1.0 / l;
        for (int j = 0; j < params.sectors; ++j) {
            // cos of the solar zenith angle at the element
            const double cos_z = cg * s_dot_e3 + sg * scratch.sun_horizontal[j];
            if (cos_z <= 0.0) continue;
            // Zonal: sin(latitude) of the element is the ECI z of its unit position cg e3 + sg h(psi).
            double ring_weight = ring_scale;
            if (zonal) {
                const double sin_lat = cg * e3.z() + sg * scratch.polar_horizontal[j];
                ring_weight *= rho_eq + rho_step * sin_lat * sin_lat;
            }
            visit(ring_weight * cos_z, vertical + radial * scratch.horizontal[j], inv_l);
        }
    }
}

}  // namespace

std::array<double, 6> earth_albedo(const AlbedoParams& params, const Eigen::Vector3d& r_sat,
                                   const Eigen::Vector3d& sun_direction, double solar_irradiance,
                                   const Eigen::Matrix3d& body_from_eci) {
    std::array<double, 6> e{};
    if (dark(params, solar_irradiance)) return e;
    check(params);
    // Work in body axes: the six face normals are then just +/- the coordinate axes.
    thread_local CapScratch scratch;  // the per-sector directions, reused (this path is the reference one)
    const bool kelly = params.response == AlbedoResponse::kelly;
    visit_sunlit_cap(params, scratch, r_sat, sun_direction, solar_irradiance, body_from_eci,
                     [&](double a, const Eigen::Vector3d& d, double inv_l) {
                         for (int k = 0; k < 3; ++k) {
                             const double c = d(k) * inv_l;  // cos of incidence on face ±k
                             const double f = kelly ? kelly_of_cos(std::abs(c)) : std::abs(c);
                             e[c > 0.0 ? 2 * k : 2 * k + 1] += a * f;
                         }
                     });
    return e;
}

// ---------------------------------------------------------------------------------------------------------
// The spherical-harmonic form (header). Real orthonormal harmonics, index l^2 + l + m (m = -l … l):
//   Y_l0 = K_l0 P_l(z),  Y_lm = sqrt2 K_lm P_l^m(z) cos(m phi),  Y_l,-m = sqrt2 K_lm P_l^m(z) sin(m phi),
//   K_lm = sqrt((2l+1)/(4 pi) (l-m)!/(l+m)!)
// computed without trigonometry: P_l^m(z) = Q_l^m(z) sin^m(theta), and sin^m(theta) (cos, sin)(m phi) are the
// real and imaginary parts of (x + i y)^m; Q by the standard three-term recursion in l,
//   Q_mm = (2m-1)!!,  Q_m+1,m = (2m+1) z Q_mm,  Q_lm = ((2l-1) z Q_l-1,m - (l+m-1) Q_l-2,m)/(l-m).
// Any orthonormal basis of each degree satisfies the addition theorem the expansion rests on.

AlbedoHarmonics::AlbedoHarmonics(const AlbedoParams& params, int degree)
    : params_(params), degree_(degree), size_(static_cast<std::size_t>((degree + 1) * (degree + 1))) {
    if (degree < 0 || degree > kMaxDegree)
        throw std::invalid_argument("AlbedoHarmonics: degree must be 0.." + std::to_string(kMaxDegree));
    check(params);
    const int n = degree + 1;
    norm_.assign(size_, 0.0);
    up_.assign(size_, 0.0);
    down_.assign(size_, 0.0);
    basis_.assign(size_, 0.0);
    for (int l = 0; l <= degree; ++l) {
        for (int m = 0; m <= l; ++m) {
            double ratio = 1.0;  // (l-m)!/(l+m)!
            for (int k = l - m + 1; k <= l + m; ++k) ratio /= k;
            double q_mm = 1.0;  // (2m-1)!!
            for (int k = 1; k <= 2 * m - 1; k += 2) q_mm *= k;
            const double k_lm = std::sqrt((2.0 * l + 1.0) / (4.0 * kPi) * ratio) * (m > 0 ? std::sqrt(2.0) : 1.0);
            norm_[index(l, m)] = k_lm * q_mm;  // the recursion below runs from Q_mm = 1: (2m-1)!! comes here
            if (l > m) {
                up_[index(l, m)] = (2.0 * l - 1.0) / (l - m);
                down_[index(l, m)] = (l + m - 1.0) / (l - m);
            }
        }
    }
    // The face response's Legendre moments f_l = 2 pi integral_0^1 f(t) P_l(t) dt (f = 0 for t < 0):
    // composite 4-point Gauss-Legendre on the Kelly table's 1024 intervals (exact for the cosine and for
    // the table's piecewise-linear curve up to degree 6 on each interval; far below the truncation error
    // beyond).
    response_.assign(static_cast<std::size_t>(n), 0.0);
    std::vector<double> x, w;
    gauss_legendre(4, x, w);
    std::vector<double> p(static_cast<std::size_t>(n));
    const bool kelly = params.response == AlbedoResponse::kelly;
    for (int seg = 0; seg < kKellyGrid; ++seg) {
        for (std::size_t q = 0; q < x.size(); ++q) {
            const double h = 1.0 / kKellyGrid;
            const double t = (seg + 0.5 * (x[q] + 1.0)) * h;
            const double f = kelly ? kelly_of_cos(t) : t;
            p[0] = 1.0;
            if (n > 1) p[1] = t;
            for (int l = 2; l < n; ++l) p[l] = ((2.0 * l - 1.0) * t * p[l - 1] - (l - 1.0) * p[l - 2]) / l;
            for (int l = 0; l < n; ++l) response_[l] += 2.0 * kPi * 0.5 * h * w[q] * f * p[l];
        }
    }
}

void AlbedoHarmonics::harmonics(const Eigen::Vector3d& u, double* y) const {
    // (x + i y)^m accumulated as m grows; Q_l^m down each column m.
    double cm = 1.0, sm = 0.0;
    for (int m = 0; m <= degree_; ++m) {
        double q_prev = 0.0, q = 0.0;  // Q_l-2,m and Q_l-1,m over (2m-1)!! (which is in norm_)
        for (int l = m; l <= degree_; ++l) {
            double q_l;
            if (l == m) {
                q_l = 1.0;
            } else {
                q_l = up_[index(l, m)] * u.z() * q - down_[index(l, m)] * q_prev;
            }
            q_prev = q;
            q = q_l;
            const double v = norm_[index(l, m)] * q_l;
            if (m == 0) {
                y[index(l, 0)] = v;
            } else {
                y[index(l, m)] = v * cm;
                y[index(l, -m)] = v * sm;
            }
        }
        const double c = cm * u.x() - sm * u.y();
        sm = sm * u.x() + cm * u.y();
        cm = c;
    }
}

void AlbedoHarmonics::project(const Eigen::Vector3d& r_sat, const Eigen::Vector3d& sun_direction,
                              double solar_irradiance, double* c) {
    std::fill(c, c + size_, 0.0);
    if (dark(params_, solar_irradiance)) return;
    visit_sunlit_cap(params_, scratch_, r_sat, sun_direction, solar_irradiance, Eigen::Matrix3d::Identity(),
                     [&](double a, const Eigen::Vector3d& d, double inv_l) {
                         harmonics(d * inv_l, basis_.data());
                         for (std::size_t i = 0; i < size_; ++i) c[i] += a * basis_[i];
                     });
}

std::array<double, 6> AlbedoHarmonics::faces(const double* c, const Eigen::Matrix3d& body_from_eci) {
    std::array<double, 6> e{};
    for (int k = 0; k < 3; ++k) {
        // Face +k's normal in ECI is row k of A; face -k's is its opposite, and Y_lm(-n) = (-1)^l Y_lm(n).
        harmonics(body_from_eci.row(k).transpose(), basis_.data());
        double even = 0.0, odd = 0.0;
        for (int l = 0; l <= degree_; ++l) {
            double s = 0.0;
            for (int m = -l; m <= l; ++m) s += c[index(l, m)] * basis_[index(l, m)];
            (l % 2 == 0 ? even : odd) += response_[l] * s;
        }
        // The truncated series rings a little about zero where a face sees none of the cap: never negative.
        e[2 * k] = std::max(0.0, even + odd);
        e[2 * k + 1] = std::max(0.0, even - odd);
    }
    return e;
}

}  // namespace environment
