#include "attitude_estimator/field_vector.hpp"

#include <cmath>

#include "attitude_estimator/vec3_math.hpp"

namespace attitude_estimator {

template <class T>
FieldMeasurement<T> field_vector_from_set_reset(const Vec3<T>& v_mag, T v_mag_ref, T sensitivity, T polarity,
                                                const Vec3<T>& offset, const Vec3<T>& rail_low,
                                                const Vec3<T>& rail_high, T rail_margin, T min_field) noexcept {
    FieldMeasurement<T> m;
    if (!(sensitivity > T(0)) || !std::isfinite(sensitivity) || !std::isfinite(v_mag_ref)) return m;
    if (!(polarity == T(1) || polarity == T(-1))) return m;
    for (int k = 0; k < 3; ++k) {
        if (!std::isfinite(v_mag[k]) || !std::isfinite(offset[k])) return m;
        // A saturated channel reads its rail whatever the field: the direction would be wrong, not noisy.
        if (v_mag[k] <= rail_low[k] + rail_margin || v_mag[k] >= rail_high[k] - rail_margin) m.at_rail = true;
        // 2.5 V reference output = zero field; 1 V/gauss for the HMC2003 (000 §5, 001 §5).
        m.field[k] = polarity * (v_mag[k] - v_mag_ref - offset[k]) / sensitivity;
    }
    if (m.at_rail) return m;
    const T n = std::sqrt(squared_norm(m.field));
    if (!(n >= min_field) || !(n > T(0))) return m;
    m.unit = scaled(m.field, T(1) / n);
    m.valid = true;
    return m;
}

template <class T>
FieldMeasurement<T> field_vector_from_voltages(const Vec3<T>& v_mag, T v_mag_ref, T sensitivity,
                                               const Vec3<T>& rail_low, const Vec3<T>& rail_high, T rail_margin,
                                               T min_field) noexcept {
    return field_vector_from_set_reset(v_mag, v_mag_ref, sensitivity, T(1), Vec3<T>{}, rail_low, rail_high, rail_margin,
                                       min_field);
}

template FieldMeasurement<float> field_vector_from_set_reset(const Vec3<float>&, float, float, float,
                                                             const Vec3<float>&, const Vec3<float>&, const Vec3<float>&,
                                                             float, float) noexcept;
template FieldMeasurement<double> field_vector_from_set_reset(const Vec3<double>&, double, double, double,
                                                              const Vec3<double>&, const Vec3<double>&,
                                                              const Vec3<double>&, double, double) noexcept;
template FieldMeasurement<float> field_vector_from_voltages(const Vec3<float>&, float, float, const Vec3<float>&,
                                                            const Vec3<float>&, float, float) noexcept;
template FieldMeasurement<double> field_vector_from_voltages(const Vec3<double>&, double, double, const Vec3<double>&,
                                                             const Vec3<double>&, double, double) noexcept;

}  // namespace attitude_estimator
