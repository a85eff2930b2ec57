#pragma once
// SGP4's TEME frame to J2000 (the mean equator and equinox of J2000.0, the frame of every *_eci output of
// this project), the route of Vallado's teme2eci (Vallado et al. 2006, AIAA 2006-6753, section "TEME"):
//   r_J2000 = P^T N^T R3(-Eq) r_TEME
// R3(-Eq): TEME -> true of date, Eq = dpsi cos(eps_mean) the equation of the equinoxes with its geometric
//          term only (TEME's equinox is the mean one projected on the true equator; the kinematic terms of
//          1994, < 0.003", belong to sidereal time, not to TEME);
// N: IAU 1980 nutation (106 terms; no IERS corrections, which SGP4's element sets do not know);
// P: IAU 1976 precession (Lieske et al. 1977).
// R1, R2, R3 are passive (frame) rotations. Templated on the floating type for the on-board computer,
// whose cheap variant truncates the nutation series (see nutation_iau1980's `terms`).
//
// Time: T in Julian centuries of TT from J2000. julian_centuries() takes a UTC Julian date as TT: the
// 69 s (TT - UTC since 2017) move precession by 1e-4" and nutation by < 1e-4", i.e. < 4 mm at 7000 km.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "orbit/iau1980_nutation.hpp"
#include "orbit/sgp4.hpp"  // Vector3, OrbitState

namespace orbit {

template <typename T>
using Matrix3 = Eigen::Matrix<T, 3, 3>;

inline constexpr double kJulianDateJ2000 = 2451545.0;  // 2000-01-01 12:00 TT
inline constexpr int kIau1980NutationTerms = 106;

/// Julian centuries from J2000 of a Julian date (see the header's note on UTC and TT).
inline double julian_centuries(double julian_date) noexcept {
    return (julian_date - kJulianDateJ2000) / 36525.0;
}

/// IAU 1976 precession angles (zeta, z, theta), rad (Lieske et al. 1977; Vallado eq. 3-88).
template <typename T>
Vector3<T> precession_angles_iau1976(T t) noexcept;

/// Precession: J2000 -> mean of date, R3(-z) R2(theta) R3(-zeta).
template <typename T>
Matrix3<T> mod_from_j2000(T t) noexcept;

template <typename T>
struct Nutation {
    T dpsi{};            // nutation in longitude (rad)
    T deps{};            // nutation in obliquity (rad)
    T mean_obliquity{};  // IAU 1980 mean obliquity of the ecliptic (rad)
};

/// IAU 1980 nutation from the first `terms` terms (1 to 106, clamped) of the series, largest first.
/// Truncation error over 2020-2035 against the full series (ERFA, measured in frames_test): the whole
/// TEME -> J2000 rotation is off by 0.78" with 1 term, 0.25" with 2, 0.10" (3.5 m at 7000 km) with 4,
/// 0.037" with 9, 0.019" with 13, 0.005" with 30 (dpsi itself: 1.75", 0.52", 0.26", 0.085", 0.034", 0.012").
template <typename T>
Nutation<T> nutation_iau1980(T t, int terms = kIau1980NutationTerms) noexcept;

/// Nutation: mean of date -> true of date, R1(-eps) R3(-dpsi) R1(eps_mean), eps = eps_mean + deps.
template <typename T>
Matrix3<T> tod_from_mod(const Nutation<T>& n) noexcept;

/// The equation of the equinoxes as TEME uses it: dpsi cos(eps_mean) (rad).
template <typename T>
T equation_of_equinoxes(const Nutation<T>& n) noexcept;

/// The whole rotation TEME -> J2000 at T (Julian centuries TT), nutation from its first `terms` terms.
template <typename T>
Matrix3<T> j2000_from_teme(T t, int nutation_terms = kIau1980NutationTerms) noexcept;

/// A TEME state (km, km/s) in J2000 (km, km/s). The frame's own rotation (precession and nutation,
/// < 1e-11 rad/s) adds < 1e-7 km/s to the velocity and is left out, as teme2eci does.
template <typename T>
OrbitState<T> teme_to_j2000(const OrbitState<T>& teme, T t, int nutation_terms = kIau1980NutationTerms) noexcept;

}  // namespace orbit

#include "orbit/frames_model.hpp"  // the templates' definitions (header-only for the firmware's float build)
