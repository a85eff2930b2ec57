// One whole sample of the on-board attitude computer (000 §7, fig. 11): digitize the sample/hold currents
// and the magnetometer voltages, form the sun and field vectors, solve Wahba's problem against their
// reference directions. Plain structs in, plain struct out, no heap, no exceptions — what an FMU's doStep
// or a DSP's timer interrupt calls once per sample. The only memory between samples is the sun method's
// (SunMethodState: the cones method's panel-cube tracking), owned by the caller.
#pragma once

#include "attitude_estimator/adc.hpp"
#include "attitude_estimator/field_vector.hpp"
#include "attitude_estimator/set_reset.hpp"
#include "attitude_estimator/sun_methods.hpp"
#include "attitude_estimator/sun_vector.hpp"
#include "attitude_estimator/types.hpp"
#include "attitude_estimator/wahba.hpp"

namespace attitude_estimator {

template <class T>
struct EstimatorConfig {
    // Denominators of 000 eq. 5: held differential current of one axis when one panel of that axis faces
    // the sun squarely, in A. Must match the power plant's panels; 1 A is a placeholder of the right order
    // for a 10 Wp panel at 1367 W/m².
    Vec3<T> i_sc_norm{T(1), T(1), T(1)};
    T mag_sensitivity = kHmc2003Sensitivity<T>;  // V/T (HMC2003: 1 V/gauss = 1e4 V/T)
    T sun_weight = T(0.5);                       // a_1, a_2 of 000 eq. 8; any nonnegative scale, normalized to sum 1
    T mag_weight = T(0.5);
    // Converters. Currents: ±2 A around zero (differential current of the axis). Voltages: 0…5 V, the
    // HMC2003 output range of 000 §5; the zero-field reference goes through its own channel of the same kind.
    std::array<AdcConfig<T>, 3> sun_adc{{{12, T(-2), T(2)}, {12, T(-2), T(2)}, {12, T(-2), T(2)}}};
    std::array<AdcConfig<T>, 3> mag_adc{{{12, T(0), T(5)}, {12, T(0), T(5)}, {12, T(0), T(5)}}};
    AdcConfig<T> mag_ref_adc{12, T(0), T(5)};
    SolverKind solver = SolverKind::qmethod;             // the seeds' method; fast is the flight-code choice
    T min_sun_norm = kDefaultMinSunNorm<T>;              // sun_vector.hpp
    T mag_rail_margin = kDefaultRailMargin<T>;           // V, field_vector.hpp; rails = each mag_adc's min/max
    T min_field = kDefaultMinField<T>;                   // T, field_vector.hpp
    T min_separation_sin = kDefaultMinSeparationSin<T>;  // wahba.hpp
    // How the sun vector is formed (sun_methods.hpp). `difference` is eq. 5 on the three per-axis Hall
    // sample/holds i_sh (the seed's hardware, through sun_adc and i_sc_norm above); every other method reads
    // the six per-face currents i_face through face_adc, normalized by sun.i_face_norm.
    SunMethodConfig<T> sun{};
    // Face-current channels: 0 … 1.2 A (a face's current is never negative; 1.4 × i_sc0 of full scale
    // leaves room for albedo on top of normal incidence).
    std::array<AdcConfig<T>, 6> face_adc{{{12, T(0), T(1.2)},
                                          {12, T(0), T(1.2)},
                                          {12, T(0), T(1.2)},
                                          {12, T(0), T(1.2)},
                                          {12, T(0), T(1.2)},
                                          {12, T(0), T(1.2)}}};
};

template <class T>
struct SampleInputs {
    Vec3<T> i_sh{};             // A, sample/hold differential currents I_sc+k − I_sc−k
    std::array<T, 6> i_face{};  // A, per-face sample/hold currents +x, −x, +y, −y, +z, −z (not `difference`)
    Vec3<T> v_mag{};            // V, magnetometer outputs X, Y, Z
    T v_mag_ref = T(2.5);       // V, magnetometer zero-field reference output
    Vec3<T> sun_ref{};          // sun direction in the reference (inertial) frame, any nonzero length
    Vec3<T> mag_ref{};          // geomagnetic field in the reference frame, any nonzero length
    // The HMC2003's set/reset state when v_mag was read (set_reset.hpp): +1 after a set pulse, −1 after a
    // reset pulse — the polarity the computer itself last commanded (SetResetState::polarity before the
    // sample), not anything the sensor reports. It multiplies the field term of the reading.
    T mag_polarity = T(1);
    Vec3<T> mag_offset{};  // V, the sensor offset to take out (SetResetState::offset; 0: none known)
    // The in-flight calibration (mag_calibration.hpp): the field becomes mag_gain · B − mag_polarity ·
    // mag_cal_offset (T). Identity and zero (default): none.
    Matrix3RowMajor<T> mag_gain{1, 0, 0, 0, 1, 0, 0, 0, 1};
    Vec3<T> mag_cal_offset{};
    // A field at the sensor the computer knows from its own measurements (the panels' string currents': T, body
    // axes), taken out of the reading before the calibration: mag_field_uncalibrated is the reading less this.
    Vec3<T> mag_known_field{};
};

template <class T>
struct SampleResult {
    Quaternion<T> q{};                                // scalar-last, w >= 0
    Matrix3RowMajor<T> a{1, 0, 0, 0, 1, 0, 0, 0, 1};  // w_body = A v_ref, row-major
    Vec3<T> sun_meas{};                               // unit sun vector in body axes (zero when sun_valid is false)
    Vec3<T> mag_meas{};                               // unit field vector in body axes (zero when mag_valid is false)
    Vec3<T> mag_field{};                              // field in body axes, T
    Vec3<T> mag_field_uncalibrated{};                 // the same before the in-flight calibration, T
    Vec3<T> mag_reading{};  // V, digitized v_mag − v_mag_ref, offset and polarity still in (for set_reset.hpp)
    bool mag_reading_usable = false;  // every channel finite and off its rails
    T sun_norm = T(0);                // |s| of 000 eq. 5 before normalization
    T loss = T(0);                    // L(A), 000 eq. 8
    bool sun_valid = false;
    bool mag_valid = false;
    bool valid = false;               // both vectors valid, separated (min_separation_sin) and the solve succeeded
    std::uint8_t lit_faces = 0;       // face-based methods: faces above the dark threshold (bit k = face k)
    std::uint8_t rejected_faces = 0;  // face-based methods: lit faces the method did not use (albedo)
    int cube_state = kCubeDark;       // cones: the panel-cube state of this sample (sun_methods.hpp)
    std::array<T, 6> face_albedo{};   // cones' fitted albedo per face, relative (SunMethodResult::face_albedo)
};
// When sun or field is invalid no attitude is computed: q and A are the identity, loss 0, valid false.

template <class T>
SampleResult<T> estimate_sample(const SampleInputs<T>& in, const EstimatorConfig<T>& config,
                                SunMethodState<T>& sun_state) noexcept;
// The same with no memory between samples (a fresh SunMethodState: as after darkness).
template <class T>
SampleResult<T> estimate_sample(const SampleInputs<T>& in, const EstimatorConfig<T>& config) noexcept;

extern template SampleResult<float> estimate_sample(const SampleInputs<float>&, const EstimatorConfig<float>&,
                                                    SunMethodState<float>&) noexcept;
extern template SampleResult<double> estimate_sample(const SampleInputs<double>&, const EstimatorConfig<double>&,
                                                     SunMethodState<double>&) noexcept;
extern template SampleResult<float> estimate_sample(const SampleInputs<float>&, const EstimatorConfig<float>&) noexcept;
extern template SampleResult<double> estimate_sample(const SampleInputs<double>&,
                                                     const EstimatorConfig<double>&) noexcept;

}  // namespace attitude_estimator
