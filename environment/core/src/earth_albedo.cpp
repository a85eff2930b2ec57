#include "environment/earth_albedo.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
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
// The quadrature depends on (rings, sectors) only: computed once per thread for the last pair asked
// (the environment asks with the same pair at every evaluation).
struct Quadrature {
    int rings = 0, sectors = 0;
    std::vector<double> node, weight, cos_psi, sin_psi;
};

const Quadrature& quadrature(int rings, int sectors) {
    thread_local Quadrature q;
    if (q.rings == rings && q.sectors == sectors) return q;
    gauss_legendre(rings, q.node, q.weight);
    const double dpsi = 2.0 * kPi / sectors;
    q.cos_psi.resize(sectors);
    q.sin_psi.resize(sectors);
    for (int j = 0; j < sectors; ++j) {
        q.cos_psi[j] = std::cos((j + 0.5) * dpsi);
        q.sin_psi[j] = std::sin((j + 0.5) * dpsi);
    }
    q.rings = rings;
    q.sectors = sectors;
    return q;
}

// The Kelly response f(cos θ) tabulated once (panel_response's curve, acos and a Hermite per call otherwise)
// on a uniform grid in cos θ; linear interpolation between 1025 points is within 3e-6 of the curve.
constexpr int kKellyGrid = 1024;
double kelly_of_cos(double c) {
    static const std::array<double, kKellyGrid + 1> table = [] {
        constexpr auto law = panel_response::kelly<double>();
        std::array<double, kKellyGrid + 1> t{};
        for (int i = 0; i <= kKellyGrid; ++i)
            t[i] = panel_response::response_from_cos(law, static_cast<double>(i) / kKellyGrid);
        return t;
    }();
    const double x = std::clamp(c, 0.0, 1.0) * kKellyGrid;
    const int i = std::min(static_cast<int>(x), kKellyGrid - 1);
    return table[i] + (x - i) * (table[i + 1] - table[i]);
}

}  // namespace

std::array<double, 6> earth_albedo(const AlbedoParams& params, const Eigen::Vector3d& r_sat,
                                   const Eigen::Vector3d& sun_direction, double solar_irradiance,
                                   const Eigen::Matrix3d& body_from_eci) {
    std::array<double, 6> e{};
    const bool zonal = params.model == ReflectivityModel::zonal;
    if (!params.enabled || solar_irradiance <= 0.0) return e;
    if (!zonal && params.reflectivity <= 0.0) return e;
    if (zonal && !(params.reflectivity_equator >= 0.0 && params.reflectivity_equator <= 1.0 &&
                   params.reflectivity_pole >= 0.0 && params.reflectivity_pole <= 1.0))
        throw std::invalid_argument("earth_albedo: zonal reflectivities must be in [0, 1]");
    if (params.rings < 1 || params.sectors < 3) throw std::invalid_argument("earth_albedo: rings >= 1, sectors >= 3");
    const double r = r_sat.norm();
    if (!(r > kEarthRadius)) throw std::invalid_argument("earth_albedo: satellite below the Earth's surface");

    // Polar grid about the sub-satellite point; the visible cap ends where the line of sight is tangent.
    const Eigen::Vector3d e3 = r_sat / r;
    Eigen::Vector3d e1 = e3.unitOrthogonal();
    const Eigen::Vector3d e2 = e3.cross(e1);
    const double gamma_max = std::acos(kEarthRadius / r);
    const Quadrature& q = quadrature(params.rings, params.sectors);
    const double dpsi = 2.0 * kPi / params.sectors;
    const double s_dot_e3 = sun_direction.dot(e3);
    const double s_dot_e1 = sun_direction.dot(e1);
    const double s_dot_e2 = sun_direction.dot(e2);
    // Radiance per unit cos(zenith): L = rho E cos z / pi (zonal: rho applied per element below).
    const double radiance_scale = (zonal ? 1.0 : params.reflectivity) * solar_irradiance / kPi;
    const double rho_eq = params.reflectivity_equator,
                 rho_step = params.reflectivity_pole - params.reflectivity_equator;

    // Work in body axes: the six face normals are then just +/- the coordinate axes. Per sector, the
    // horizontal direction psi in body axes and the sun's component along it (the same on every ring).
    const Eigen::Vector3d b1 = body_from_eci * e1, b2 = body_from_eci * e2, b3 = body_from_eci * e3;
    thread_local std::vector<Eigen::Vector3d> horizontal;
    thread_local std::vector<double> sun_horizontal;
    thread_local std::vector<double> polar_horizontal;  // z (ECI) of the horizontal direction psi
    horizontal.resize(params.sectors);
    sun_horizontal.resize(params.sectors);
    polar_horizontal.resize(params.sectors);
    for (int j = 0; j < params.sectors; ++j) {
        horizontal[j] = q.cos_psi[j] * b1 + q.sin_psi[j] * b2;
        sun_horizontal[j] = q.cos_psi[j] * s_dot_e1 + q.sin_psi[j] * s_dot_e2;
        polar_horizontal[j] = q.cos_psi[j] * e1.z() + q.sin_psi[j] * e2.z();
    }
    for (int i = 0; i < params.rings; ++i) {
        const double gamma = 0.5 * gamma_max * (q.node[i] + 1.0);
        const double cg = std::cos(gamma), sg = std::sin(gamma);
        const double area = kEarthRadius * kEarthRadius * sg * (0.5 * gamma_max * q.weight[i]) * dpsi;
        // Satellite -> element: d = R p^ - r e3; its length depends on gamma only.
        const double l2 = kEarthRadius * kEarthRadius + r * r - 2.0 * kEarthRadius * r * cg;
        const double l = std::sqrt(l2);
        // cos of the emission angle at the element: -p^ . d/l = (r cos gamma - R)/l
        const double cos_emit = (r * cg - kEarthRadius) / l;
        if (cos_emit <= 0.0) continue;
        const double ring_scale = radiance_scale * cos_emit * area / l2;
        // d in body axes (unnormalised): (R cos gamma - r) b3 + R sin gamma h(psi)
        const Eigen::Vector3d vertical = (kEarthRadius * cg - r) * b3;
        const double radial = kEarthRadius * sg;
        for (int j = 0; j < params.sectors; ++j) {
            // cos of the solar zenith angle at the element
            const double cos_z = cg * s_dot_e3 + sg * sun_horizontal[j];
            if (cos_z <= 0.0) continue;
            // Zonal: sin(latitude) of the element is the ECI z of its unit position cg e3 + sg h(psi).
            double ring_weight = ring_scale;
            if (zonal) {
                const double sin_lat = cg * e3.z() + sg * polar_horizontal[j];
                ring_weight *= rho_eq + rho_step * sin_lat * sin_lat;
            }
            if (params.response == AlbedoResponse::kelly) {
                const double a = ring_weight * cos_z, inv_l = 1.0 / l;
                for (int k = 0; k < 3; ++k) {
                    const double c = (vertical(k) + radial * horizontal[j](k)) * inv_l;  // cos of incidence on face ±k
                    if (c > 0.0) {
                        e[2 * k] += a * kelly_of_cos(c);
                    } else {
                        e[2 * k + 1] += a * kelly_of_cos(-c);
                    }
                }
                continue;
            }
            const double w = ring_weight * cos_z / l;  // 1/l normalises d below
            for (int k = 0; k < 3; ++k) {
                const double c = w * (vertical(k) + radial * horizontal[j](k));
                if (c > 0.0) {
                    e[2 * k] += c;
                } else {
                    e[2 * k + 1] -= c;
                }
            }
        }
    }
    return e;
}

}  // namespace environment
