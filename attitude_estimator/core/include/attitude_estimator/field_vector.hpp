// Geomagnetic field in body axes from the HMC2003 magnetometer output voltages (000 §5, 001 §5: outputs
// X, Y, Z in 0…5 V, +2.5 V reference output for zero field, 1 V/gauss).
#pragma once

#include "attitude_estimator/types.hpp"

namespace attitude_estimator {

template <class T>
struct FieldMeasurement {
    Vec3<T> field{};       // B in tesla, body axes
    Vec3<T> unit{};        // B/|B| (zero when invalid)
    bool at_rail = false;  // some channel within the rail margin of its range end: saturated sensor
    bool valid = false;
};

// HMC2003 sensitivity: 1 V/gauss = 1e4 V/T.
template <class T>
inline constexpr T kHmc2003Sensitivity = T(1e4);
// Rail margin: 0.05 V is about 41 LSB of a 12-bit converter over 0…5 V, wider than the converter's
// offset and gain errors, and 5 µT of field — a channel that close to an end is taken as saturated.
template <class T>
inline constexpr T kDefaultRailMargin = T(0.05);
// Below 1 µT the direction is noise (low-Earth-orbit fields are 20…60 µT).
template <class T>
inline constexpr T kDefaultMinField = T(1e-6);

// B = (v_mag − v_mag_ref) / sensitivity, then normalized.
// rail_low[k]/rail_high[k] are channel k's range ends (its converter's min and max); the measurement is
// invalid when any channel k is <= rail_low[k] + rail_margin or >= rail_high[k] − rail_margin,
// when |B| < min_field, when sensitivity <= 0, or when any value is not finite.
template <class T>
FieldMeasurement<T> field_vector_from_voltages(const Vec3<T>& v_mag, T v_mag_ref, T sensitivity,
                                               const Vec3<T>& rail_low, const Vec3<T>& rail_high,
                                               T rail_margin = kDefaultRailMargin<T>,
                                               T min_field = kDefaultMinField<T>) noexcept;

// The same for a reading taken after a set (polarity = +1) or reset (−1) pulse of the HMC2003: the pulse
// flips the field term, the offset stays (set_reset.hpp), so B = polarity·(v_mag − v_mag_ref − offset)/S.
// The rail test is on the raw v_mag. The function above is this one with polarity +1 and no offset.
template <class T>
FieldMeasurement<T> field_vector_from_set_reset(const Vec3<T>& v_mag, T v_mag_ref, T sensitivity, T polarity,
                                                const Vec3<T>& offset, const Vec3<T>& rail_low,
                                                const Vec3<T>& rail_high, T rail_margin = kDefaultRailMargin<T>,
                                                T min_field = kDefaultMinField<T>) noexcept;

extern template FieldMeasurement<float> field_vector_from_set_reset(const Vec3<float>&, float, float, float,
                                                                    const Vec3<float>&, const Vec3<float>&,
                                                                    const Vec3<float>&, float, float) noexcept;
extern template FieldMeasurement<double> field_vector_from_set_reset(const Vec3<double>&, double, double, double,
                                                                     const Vec3<double>&, const Vec3<double>&,
                                                                     const Vec3<double>&, double, double) noexcept;
extern template FieldMeasurement<float> field_vector_from_voltages(const Vec3<float>&, float, float, const Vec3<float>&,
                                                                   const Vec3<float>&, float, float) noexcept;
extern template FieldMeasurement<double> field_vector_from_voltages(const Vec3<double>&, double, double,
                                                                    const Vec3<double>&, const Vec3<double>&, double,
                                                                    double) noexcept;

}  // namespace attitude_estimator
