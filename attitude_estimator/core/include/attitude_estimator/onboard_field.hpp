// The on-board computer's geomagnetic model: IGRF-14 (the table the environment's truth is generated from,
// ground/data/IGRF14.SHC) truncated to a degree N chosen by the user, 1 (the tilted dipole) to 13
// (the whole model). Spherical-harmonic synthesis with Schmidt semi-normalised Legendre functions by the
// standard recursions (Langel 1987; Wertz 1978 app. H), in the computer's float type, no heap, no
// exceptions. The cost grows as N²: (N+1)(N+2)/2 Legendre terms.
#pragma once

#include <array>
#include <cstdint>

#include "attitude_estimator/types.hpp"

namespace attitude_estimator {

inline constexpr std::int32_t kFieldMaxDegree = 13;  // IGRF-14's main field

template <class T>
struct FieldModel {
    std::int32_t degree = 8;
    T base_year = T(2025);  // the main field's epoch
    // nT and nT/year at [n][m], degree ≤ `degree` (the rest zero): g = g0 + ġ (year − base_year).
    std::array<std::array<T, kFieldMaxDegree + 1>, kFieldMaxDegree + 1> g{}, h{}, g_rate{}, h_rate{};
};

// The model of this degree from IGRF-14 (degree clamped to 1 … 13: the caller validates it).
template <class T>
FieldModel<T> make_field_model(std::int32_t degree) noexcept;

// The field (T) in Earth-fixed axes at r_ecef (m, geocentric, at least 1 km from the centre: the caller
// keeps it in orbit) at a decimal year; IGRF-14's secular variation is linear from 2025.0.
template <class T>
Vec3<T> field_ecef(const FieldModel<T>& model, const Vec3<T>& r_ecef, T year) noexcept;

// What a model of `degree` leaves out of IGRF-14 (the degrees above it, to 13), as the rms per axis over a sphere
// of radius `radius` (m, geocentric) at a decimal year, T. From the Lowes–Mauersberger spectrum (Lowes 1966):
// the mean of |B_n|² over the sphere of radius r is R_n = (n + 1) (a/r)^(2n+4) Σ_m (g_n^m² + h_n^m²), a the
// reference radius, and the degrees are orthogonal over the sphere, so the omitted field's mean square is
// their sum; a third of it per axis. Each degree falls as (a/r)^(n+2): from 420 to 650 km the omitted
// degrees above 8 fall from 40 to 28 nT per axis. The ground's number for the reference field's error along
// an orbit (MekfConfig::mag_ref_rms), not evaluated in flight.
double omitted_field_rms(std::int32_t degree, double radius, double year) noexcept;

extern template FieldModel<float> make_field_model(std::int32_t) noexcept;
extern template FieldModel<double> make_field_model(std::int32_t) noexcept;
extern template Vec3<float> field_ecef(const FieldModel<float>&, const Vec3<float>&, float) noexcept;
extern template Vec3<double> field_ecef(const FieldModel<double>&, const Vec3<double>&, double) noexcept;

}  // namespace attitude_estimator
