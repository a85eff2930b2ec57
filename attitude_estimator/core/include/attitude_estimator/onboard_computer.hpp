// One sample of the on-board computer as its flight software runs it, around estimate_sample
// (estimator.hpp): the panels' normalization scaled to the sun distance and corrected by the filter's
// panel-scale estimate, the magnetometer's set/reset sequence and offset (set_reset.hpp), the mean rate
// of 004 eq. 4 with its aliasing test (angular_rate.hpp), and the recursive filter (mekf.hpp).
// Templated on float/double, no heap, no exceptions: attitude_estimator.fmu runs it in double (or in
// float, `precision = float`), the firmware on the Cortex-M in float, from the same source. The spin-rate
// FFT (spin_spectrum.hpp, on FFTW) is not part of it: the FMU runs it beside, the firmware has none.
#pragma once

#include <array>
#include <cstdint>

#include "attitude_estimator/angular_rate.hpp"
#include "attitude_estimator/estimator.hpp"
#include "attitude_estimator/fault_detection.hpp"
#include "attitude_estimator/mag_calibration.hpp"
#include "attitude_estimator/mekf.hpp"
#include "attitude_estimator/onboard_references.hpp"
#include "attitude_estimator/set_reset.hpp"

namespace attitude_estimator {

// The distance at which the panels' normalizations hold (1367 W/m², seed 000 §4): 1 AU (IAU 2012).
inline constexpr double kAstronomicalUnit = 1.495978707e11;  // m

// The recursive filter beside the single-frame estimate.
enum class FilterKind : std::int32_t { none = 0, mekf = 1 };

template <class T>
struct OnboardSettings {
    EstimatorConfig<T> estimator{};  // the panels' normalizations (i_sc_norm, sun.i_face_norm) at 1 AU
    SetResetConfig set_reset{.period_samples = 0, .offset_window = 20};
    MeanAngularRateConfig<T> rate{};
    FilterKind filter = FilterKind::none;
    bool filter_scale = false;  // the filter's panel-scale estimate corrects the normalizations
    MekfConfig<T> mekf{};
    bool mag_calibration = false;  // calibrate the magnetometer in flight (mag_calibration.hpp) and apply it
    MagCalibrationConfig<T> mag_cal{};
    T sample_period = T(0.05);  // s
    T rate_interval = T(2);     // s, rate.min_interval
    // The reference vectors: the inputs' (sun_ref, mag_ref, sun_distance), or computed on board from the
    // computer's own element set, sun ephemeris and field model (onboard_references.hpp).
    ReferenceSource reference_source = ReferenceSource::inputs;
    OnboardReferenceConfig<T> references{};
    // Fault detection, isolation and recovery (fault_detection.hpp; off by default). Its predictive tests
    // need the filter; its bus test needs both i_sh and i_face wired.
    FaultDetectionConfig<T> faults{};
    // The field of each face's string current at the magnetometer per ampere (T/A, body axes; faces +x, −x, +y,
    // −y, +z, −z), uplinked: the field of the measured face currents, Σ K_f i_face[f], is taken out of the
    // reading before the calibration, the fault tests and the filter (SampleInputs::mag_known_field). Zero: none.
    std::array<Vec3<T>, 6> string_field_per_amp{};
};

template <class T>
struct OnboardInputs {
    Vec3<T> i_sh{};                         // A, sample/hold differential currents
    std::array<T, 6> i_face{};              // A, per-face sample/hold currents
    Vec3<T> v_mag{};                        // V, magnetometer outputs
    T v_mag_ref = T(2.5);                   // V, its zero-field reference
    Vec3<T> sun_ref{};                      // sun direction, inertial frame (any length)
    Vec3<T> mag_ref{};                      // T, field, inertial frame
    T sun_distance = T(kAstronomicalUnit);  // m
};

// Everything the computer remembers between samples: trivially copyable (an FMU state is its bytes).
template <class T>
struct OnboardState {
    SunMethodState<T> sun{};           // cones' panel-cube tracking
    MeanAngularRate<T> rate{};         // eq. 4 increments
    MekfState<T> filter{};             // the recursive filter
    SetResetState<T> set_reset{};      // the polarity commanded last, the offset estimate
    MagCalibrationState<T> mag_cal{};  // the in-flight magnetometer calibration
    // The turn between successive valid estimates one sample apart, smoothed: the mean rate's increments
    // span rate_interval and alias when the turn over one of them nears π.
    Quaternion<T> last_q{};
    T last_t = T(0);
    bool has_last = false;
    T step_turn = T(0);  // rad per sample (exponential average)
    std::int32_t samples = 0;
    ReferenceState<T> references{};   // the on-board models' last two evaluations
    FaultDetectionState<T> faults{};  // the tests' evidence and the faults declared (latched)
    // The filter as it was at least kFilterHoldInterval ago (onboard_computer.cpp, rewind_filter): a bias
    // jump pulls the filter's attitude until it is declared; the held state, from before the jump, is taken
    // back at the declaration. pending is the copy taken at the last checkpoint (filter_checkpoint_t).
    MekfState<T> filter_held{};
    MekfState<T> filter_pending{};
    T filter_checkpoint_t = T(0);
    // The calibration as it was 30 to 60 s ago (onboard_computer.cpp, hold_calibration): the equations taken
    // between a bias jump and its declaration hold the jump with the old offset, and are dropped with it.
    MagCalibrationState<T> mag_cal_held{};
    MagCalibrationState<T> mag_cal_pending{};
    T mag_cal_checkpoint_t = T(0);
    std::int32_t mag_cal_copies = 0;  // copies taken since the start or the last jump (held is usable from 2)
};

template <class T>
struct OnboardOutputs {
    SampleResult<T> sample{};   // the single-frame estimate
    std::int32_t samples = 0;   // samples taken, this one included (saturates at 2^31 − 1)
    bool mag_set_reset = true;  // the pulse commanded now: true set, false reset
    Vec3<T> mag_offset{};       // V, the offset taken out of the field
    T rate_mean = T(0);         // rad/s
    T rate_window_time = T(0);  // s
    bool rate_valid = false;
    Quaternion<T> q_filt{};     // identity until the filter runs
    Vec3<T> omega_filt{};       // rad/s
    Vec3<T> mag_offset_filt{};  // V, the filter's offset left after mag_offset, as read after a set pulse
    T panel_scale_filt = T(0);  // 1
    T attitude_bound = T(0);    // rad, 3σ
    // rad: the lower Cholesky factor L of the filter's attitude error covariance, P_θθ = L Lᵀ (row-major, 0
    // until it runs): |L⁻¹ δθ|²/3 is the normalized error per degree of freedom of an error δθ.
    Matrix3RowMajor<T> attitude_cov_sqrt{};
    bool filter_valid = false;
    std::int32_t filter_resets = 0;
    References<T> references{};  // the reference vectors this sample used (the inputs', or the on-board ones)
    bool mag_cal_valid = false;  // an in-flight calibration is applied
    Matrix3RowMajor<T> mag_cal_gain{1, 0, 0, 0, 1, 0, 0, 0, 1};  // its I + D
    Vec3<T> mag_cal_offset{};                                    // its b, T
    // Declared faults (fault_detection.hpp): a word per face and per magnetometer axis (0: healthy) and
    // when each was first declared (s; −1: never); the field-norm test (detection only).
    std::array<std::uint32_t, 6> fault_face{};
    std::array<T, 6> fault_face_time{T(-1), T(-1), T(-1), T(-1), T(-1), T(-1)};
    std::array<std::uint32_t, 3> fault_mag_axis{};
    std::array<T, 3> fault_mag_axis_time{T(-1), T(-1), T(-1)};
    std::uint32_t fault_mag_norm = 0;
    T fault_mag_norm_time = T(-1);
    std::array<T, 6> fault_face_scale{T(1), T(1), T(1), T(1), T(1), T(1)};  // panel faults: kFaultFaceScale's scale
    // The magnetometer's spikes so far per axis (one-sample outliers skipped; fault_detection.hpp).
    std::array<std::int32_t, 3> fault_mag_spikes{};
    Vec3<T> fault_mag_bias{};                // T: the bias-jump test's mean innovation per axis (sensor axes)
    T fault_mag_strap_cleared_time = T(-1);  // s: when a failed strap was last seen working again (−1: never)
};

// Power-up: nothing remembered, the sensor set, and no pulse at the first sample (a host re-reads the
// sensor while it initializes; a pulse there would land in the very reading this sample takes).
template <class T>
void onboard_start(OnboardState<T>& state, const OnboardSettings<T>& settings) noexcept;

// The sample at time t (s) of the inputs present then.
template <class T>
OnboardOutputs<T> onboard_sample(OnboardState<T>& state, const OnboardInputs<T>& in, const OnboardSettings<T>& settings,
                                 T t) noexcept;

extern template void onboard_start(OnboardState<float>&, const OnboardSettings<float>&) noexcept;
extern template void onboard_start(OnboardState<double>&, const OnboardSettings<double>&) noexcept;
extern template OnboardOutputs<float> onboard_sample(OnboardState<float>&, const OnboardInputs<float>&,
                                                     const OnboardSettings<float>&, float) noexcept;
extern template OnboardOutputs<double> onboard_sample(OnboardState<double>&, const OnboardInputs<double>&,
                                                      const OnboardSettings<double>&, double) noexcept;

}  // namespace attitude_estimator
