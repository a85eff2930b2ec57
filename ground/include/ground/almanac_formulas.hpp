#pragma once
// The published formulas the truth (environment) and the on-board computer (attitude_estimator/core, also
// flashed onto the Cortex-M4F firmware) both evaluate: the Astronomical Almanac's low-precision sun, the
// IAU 1982 Greenwich mean sidereal time (the Julian date of a calendar day is orbit/calendar.hpp's). Header-only, templated on the float type, no heap, no exceptions, no Eigen: one copy of each
// formula, for double (the environment) and float (the firmware). The IAU 1976 precession both use is
// orbit/frames.hpp's (mod_from_j2000).
#include <array>
#include <cmath>

namespace ground::formulas {

inline constexpr double kJ2000 = 2451545.0;  // Julian date of 2000-01-01 12:00
inline constexpr double kTwoPi = 6.28318530717958647692;

/// The sun from the Astronomical Almanac's low-precision formula (section C; US Naval Observatory,
/// "Approximate Solar Coordinates"), about 0.01 deg for 1950-2050. `days` = JD - 2451545.0.
///   L = 280.460 + 0.9856474 n, g = 357.528 + 0.9856003 n (deg)
///   lambda = L + 1.915 sin g + 0.020 sin 2g, eps = 23.439 - 0.0000004 n
///   R = 1.00014 - 0.01671 cos g - 0.00014 cos 2g (AU)
/// Direction in the mean equator and equinox of date: (cos lambda, cos eps sin lambda, sin eps sin lambda).
template <class T>
struct AlmanacSun {
    std::array<T, 3> direction{};  // unit vector, Earth centre -> Sun, mean of date
    T distance_au = T(1);
};

template <class T>
AlmanacSun<T> sun_almanac_of_date(T days) {
    // In float, n ~ 1e4 days in the 2020s is kept to 6e-4 day and 0.9856 n (~1e4 deg) to 1e-3 deg: both
    // below the formula's own 0.01 deg.
    constexpr T deg = T(3.14159265358979323846 / 180.0);
    const T L = (T(280.460) + T(0.9856474) * days) * deg;
    const T g = (T(357.528) + T(0.9856003) * days) * deg;
    const T lambda = L + (T(1.915) * std::sin(g) + T(0.020) * std::sin(T(2) * g)) * deg;
    const T eps = (T(23.439) - T(0.0000004) * days) * deg;
    AlmanacSun<T> s;
    s.direction = {std::cos(lambda), std::cos(eps) * std::sin(lambda), std::sin(eps) * std::sin(lambda)};
    s.distance_au = T(1.00014) - T(0.01671) * std::cos(g) - T(0.00014) * std::cos(T(2) * g);
    return s;
}

/// IAU 1982 Greenwich mean sidereal time (Aoki et al. 1982; Vallado eq. 3-47) in seconds of time within
/// the day, [0, 86400), at `centuries` of UT1 from J2000.
inline double gmst_seconds(double centuries) {
    const double t = centuries;
    double seconds = 67310.54841 + (876600.0 * 3600.0 + 8640184.812866) * t + 0.093104 * t * t - 6.2e-6 * t * t * t;
    seconds = std::fmod(seconds, 86400.0);
    if (seconds < 0.0) seconds += 86400.0;
    return seconds;
}

/// The Earth's sidereal rotation rate of the IAU 1982 GMST, rad per second of UT1 (1.00273790935 turns a day).
inline constexpr double kEarthRotationRate = 7.292115855306589e-5;

}  // namespace ground::formulas
