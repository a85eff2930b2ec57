// Sun direction in body axes from the three sample/hold differential currents of the Sequential Shunt
// Regulator's Hall transducers (000 §4 eq. 5, 001 §3 eq. 2 and fig. 5).
#pragma once

#include "attitude_estimator/types.hpp"

namespace attitude_estimator {

template <class T>
struct SunMeasurement {
    Vec3<T> unit{};  // normalized sun direction in body axes (zero when invalid)
    T norm = T(0);   // |s| before normalization: 1 in full sun with ideal cosine panels
    bool valid = false;
};

// Default validity threshold on |s|. With the cosine law every lit attitude gives |s| = 1 (the
// components are the direction cosines), and the Kelly cosine trims that by some percent at grazing
// incidence; Earth albedo alone (eclipse) gives at most about 0.3–0.4 of full sun. Half of full sun
// separates the two with margin on both sides.
template <class T>
inline constexpr T kDefaultMinSunNorm = T(0.5);

// s = (i_sh[1]/i_sc_norm[1], i_sh[2]/i_sc_norm[2], i_sh[3]/i_sc_norm[3])        (000 eq. 5)
// where i_sh[k] = I_sc+k − I_sc−k is the held differential current of axis k and i_sc_norm[k] the
// short-circuit current of one panel facing the sun squarely (the denominators of eq. 5). Valid when every
// value is finite, every i_sc_norm > 0 and |s| >= min_norm; the unit vector is s/|s|.
template <class T>
SunMeasurement<T> sun_vector_from_currents(const Vec3<T>& i_sh, const Vec3<T>& i_sc_norm,
                                           T min_norm = kDefaultMinSunNorm<T>) noexcept;

extern template SunMeasurement<float> sun_vector_from_currents(const Vec3<float>&, const Vec3<float>&, float) noexcept;
extern template SunMeasurement<double> sun_vector_from_currents(const Vec3<double>&, const Vec3<double>&,
                                                                double) noexcept;

}  // namespace attitude_estimator
