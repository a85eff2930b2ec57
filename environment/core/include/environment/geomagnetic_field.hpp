#pragma once
// Geomagnetic field models. Positions and fields here are Earth-fixed (ECEF); environment.cpp rotates
// them to and from ECI. Field in tesla.
#include <array>

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

namespace environment {

/// Gauss coefficients g_n^m, h_n^m (nT) of IGRF-14 at one instant, index [n][m].
struct GaussCoefficients {
    std::array<std::array<double, 14>, 14> g{};
    std::array<std::array<double, 14>, 14> h{};
};

/// IGRF-14 coefficients at a decimal year in [2025, 2030]: linear between the 2025.0 main field and its
/// secular variation (the IGRF definition). Throws std::domain_error outside that interval.
GaussCoefficients igrf_coefficients(double decimal_year);

/// Spherical-harmonic synthesis of the internal field, degree 1..max_degree, at r_ecef (m), geocentric
/// spherical coordinates, reference radius 6371.2 km:
///   V = a sum_n (a/r)^(n+1) sum_m (g cos m phi + h sin m phi) P_n^m(cos theta),  B = -grad V,
/// with Schmidt semi-normalised P_n^m from the standard recursions (e.g. Langel 1987; Wertz 1978 app. H).
/// Returns B in ECEF (T). Throws std::invalid_argument for r below 1 km.
Eigen::Vector3d spherical_harmonic_field(const GaussCoefficients& c, int max_degree, const Eigen::Vector3d& r_ecef);

/// Tilted centred dipole from the degree-1 coefficients: with B0 = sqrt(g10^2 + g11^2 + h11^2) and the
/// dipole-moment direction m = (g11, h11, g10)/B0 (ECEF; from V = a^3 (g.r)/r^3, points south),
///   B = B0 (a/r)^3 [3 (m . r^) r^ - m]
/// so |B| = B0 (a/r)^3 on the dipole equator and 2 B0 (a/r)^3 on its axis. Returns T.
Eigen::Vector3d dipole_field(const GaussCoefficients& c, const Eigen::Vector3d& r_ecef);

}  // namespace environment
