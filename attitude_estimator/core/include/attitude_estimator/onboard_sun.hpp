// The on-board computer's sun: the Astronomical Almanac's low-precision formula (~0.01°, 1950–2050; the
// same source as the environment's truth, ground/almanac_formulas.hpp) at its own clock, rotated from
// the mean equator and equinox of date to J2000 by the IAU 1976 precession. Geocentric: the parallax of
// the satellite's position, 7000 km / 1 AU, is 0.003°.
#pragma once

#include "attitude_estimator/onboard_clock.hpp"
#include "attitude_estimator/types.hpp"

namespace attitude_estimator {

template <class T>
struct SunReference {
    Vec3<T> direction{};  // unit vector, J2000
    T distance = T(0);    // m
};

template <class T>
SunReference<T> onboard_sun(const OnboardClock<T>& clock, T t) noexcept;

// Rotations between J2000 and the Earth-fixed frame at time t, as the environment's truth makes them
// (r_ecef = R3(GMST) P r_J2000; nutation and polar motion neglected). Row-major.
template <class T>
Matrix3RowMajor<T> ecef_from_j2000(const OnboardClock<T>& clock, T t) noexcept;

extern template SunReference<float> onboard_sun(const OnboardClock<float>&, float) noexcept;
extern template SunReference<double> onboard_sun(const OnboardClock<double>&, double) noexcept;
extern template Matrix3RowMajor<float> ecef_from_j2000(const OnboardClock<float>&, float) noexcept;
extern template Matrix3RowMajor<double> ecef_from_j2000(const OnboardClock<double>&, double) noexcept;

}  // namespace attitude_estimator
