#include "attitude_estimator/sun_vector.hpp"

#include <cmath>

#include "attitude_estimator/vec3_math.hpp"

namespace attitude_estimator {

template <class T>
SunMeasurement<T> sun_vector_from_currents(const Vec3<T>& i_sh, const Vec3<T>& i_sc_norm, T min_norm) noexcept {
    SunMeasurement<T> m;
    Vec3<T> s{};
    for (int k = 0; k < 3; ++k) {
        if (!(i_sc_norm[k] > T(0)) || !std::isfinite(i_sc_norm[k]) || !std::isfinite(i_sh[k])) return m;
        s[k] = i_sh[k] / i_sc_norm[k];  // (I_sc+k − I_sc−k) / I_sc,k at normal incidence   (000 eq. 5)
    }
    m.norm = std::sqrt(squared_norm(s));
    // Too little light (eclipse, albedo only, a dead Hall channel): the direction would be noise.
    if (!(m.norm >= min_norm) || !(m.norm > T(0))) return m;
    m.unit = scaled(s, T(1) / m.norm);
    m.valid = true;
    return m;
}

template SunMeasurement<float> sun_vector_from_currents(const Vec3<float>&, const Vec3<float>&, float) noexcept;
template SunMeasurement<double> sun_vector_from_currents(const Vec3<double>&, const Vec3<double>&, double) noexcept;

}  // namespace attitude_estimator
