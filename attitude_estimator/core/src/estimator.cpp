#include "attitude_estimator/estimator.hpp"

#include "attitude_estimator/vec3_math.hpp"

#include <cmath>

namespace attitude_estimator {

namespace {

// The sun vector by the configured method: eq. 5 on the per-axis Hall currents (the seed's hardware), or
// one of the face-based methods on the six digitized face currents.
template <class T>
void measure_sun(const SampleInputs<T>& in, const EstimatorConfig<T>& config, SunMethodState<T>& state,
                 SampleResult<T>& r) noexcept {
    if (config.sun.method == SunMethod::difference) {
        Vec3<T> i_digital{};
        for (int k = 0; k < 3; ++k) i_digital[k] = convert(config.sun_adc[k], in.i_sh[k]).value;
        const SunMeasurement<T> sun = sun_vector_from_currents(i_digital, config.i_sc_norm, config.min_sun_norm);
        r.sun_meas = sun.unit;
        r.sun_norm = sun.norm;
        r.sun_valid = sun.valid;
        return;
    }
    std::array<T, 6> i_digital{};
    for (std::size_t k = 0; k < 6; ++k) i_digital[k] = convert(config.face_adc[k], in.i_face[k]).value;
    const SunMethodResult<T> sun = sun_from_faces(i_digital, config.sun, state);
    r.sun_valid = sun.valid;
    r.sun_meas = sun.valid ? sun.unit : Vec3<T>{};
    r.sun_norm = sun.norm;
    r.lit_faces = sun.lit_faces;
    r.rejected_faces = sun.rejected_faces;
    r.face_albedo = sun.face_albedo;
    r.cube_state = sun.cube_state;
}

// The in-flight calibration's correction, gain · B − offset (identity and zero when none is applied);
// the unit vector and the minimum-field test follow the corrected field.
template <class T>
void calibrate_field(const SampleInputs<T>& in, T min_field, FieldMeasurement<T>& mag) noexcept {
    if (mag.at_rail) return;
    const Vec3<T> b = mag.field;
    for (std::size_t i = 0; i < 3; ++i)
        mag.field[i] = in.mag_gain[3 * i] * b[0] + in.mag_gain[3 * i + 1] * b[1] + in.mag_gain[3 * i + 2] * b[2] -
                       in.mag_cal_offset[i];
    const T n = std::sqrt(squared_norm(mag.field));
    mag.valid = mag.valid && n >= min_field && n > T(0);
    mag.unit = mag.valid ? scaled(mag.field, T(1) / n) : Vec3<T>{};
}

}  // namespace

template <class T>
SampleResult<T> estimate_sample(const SampleInputs<T>& in, const EstimatorConfig<T>& config,
                                SunMethodState<T>& sun_state) noexcept {
    SampleResult<T> r;

    Vec3<T> v_digital{};
    for (int k = 0; k < 3; ++k) v_digital[k] = convert(config.mag_adc[k], in.v_mag[k]).value;
    const T v_ref_digital = convert(config.mag_ref_adc, in.v_mag_ref).value;

    measure_sun(in, config, sun_state, r);

    Vec3<T> rail_low{};
    Vec3<T> rail_high{};
    for (int k = 0; k < 3; ++k) {
        rail_low[k] = config.mag_adc[k].min;  // a saturated sensor shows up at its converter's range ends
        rail_high[k] = config.mag_adc[k].max;
    }
    FieldMeasurement<T> mag =
        field_vector_from_set_reset(v_digital, v_ref_digital, config.mag_sensitivity, in.mag_polarity, in.mag_offset,
                                    rail_low, rail_high, config.mag_rail_margin, config.min_field);
    // The spacecraft's own field the computer knows (the strings' currents) goes before the calibration, which
    // sees the reading as the sensor's axes take it (a field at the sensor, through its scale and coupling).
    if (!mag.at_rail)
        for (std::size_t k = 0; k < 3; ++k) mag.field[k] -= in.mag_known_field[k];
    r.mag_field_uncalibrated = mag.field;
    calibrate_field(in, config.min_field, mag);
    r.mag_reading_usable = !mag.at_rail && std::isfinite(v_ref_digital);
    for (int k = 0; k < 3; ++k) {
        r.mag_reading[k] = v_digital[k] - v_ref_digital;
        r.mag_reading_usable = r.mag_reading_usable && std::isfinite(r.mag_reading[k]);
    }
    r.mag_meas = mag.unit;
    r.mag_field = mag.field;
    r.mag_valid = mag.valid;

    if (!r.sun_valid || !r.mag_valid) return r;

    ObservationSet<T> set;
    set.add(in.sun_ref, r.sun_meas, config.sun_weight);
    set.add(in.mag_ref, r.mag_meas, config.mag_weight);
    const WahbaSolution<T> s = solve_wahba(set, config.solver, WahbaOptions<T>{config.min_separation_sin});
    r.q = s.q;
    r.a = s.a;
    r.loss = s.loss;
    r.valid = s.valid;
    return r;
}

template <class T>
SampleResult<T> estimate_sample(const SampleInputs<T>& in, const EstimatorConfig<T>& config) noexcept {
    SunMethodState<T> fresh;
    return estimate_sample(in, config, fresh);
}

template SampleResult<float> estimate_sample(const SampleInputs<float>&, const EstimatorConfig<float>&,
                                             SunMethodState<float>&) noexcept;
template SampleResult<double> estimate_sample(const SampleInputs<double>&, const EstimatorConfig<double>&,
                                              SunMethodState<double>&) noexcept;
template SampleResult<float> estimate_sample(const SampleInputs<float>&, const EstimatorConfig<float>&) noexcept;
template SampleResult<double> estimate_sample(const SampleInputs<double>&, const EstimatorConfig<double>&) noexcept;

}  // namespace attitude_estimator
