// Fault detection and isolation on board (issue 28): the computer checks its measurements against each
// other and against the filter's prediction, and declares a fault on a face or a magnetometer axis once a
// test has failed for a confirmation time. A declared fault is latched: the face or axis stays excluded
// (onboard_computer.cpp applies the exclusion to the single-frame solution and the filter).
//
// The tests (docs/faults.md, "Detection"):
//  - face deficit / excess: a face's relative current r_k = i_k / i_face_norm_k against the response the
//    filter predicts from its attitude and the sun reference, R(n_k · Â ŝ_ref), scaled by the irradiance the
//    other faces show (eclipse and penumbra: the largest of their measured-to-predicted ratios; full sun when
//    none is well lit and the on-board orbit puts the spacecraft clear of the shadow); albedo only
//    adds current, so the deficit test ignores it and the excess test allows for it;
//  - bus: the per-axis Hall sample/hold i_sh[k] against the difference of its two faces' channels
//    (ssr_plant: i_sh[k] = i_face_sh[2k] − i_face_sh[2k+1] exactly when healthy);
//  - axis rail: a magnetometer channel within the rail margin of its converter's range ends;
//  - axis flip: with set/reset pulses, two readings of opposite polarity differ by 2 S B_k; an axis that
//    does not flip (stuck) shows no difference where the predicted field along it is large;
//  - strap: the half difference of the three axes together, |p (r_k − r_{k−1})/2S|, against the field any
//    two axes would still show; it fails only when no axis flips (the strap, common to the three, failed).
//    A failed strap is not excluded: the film stays in one polarity, so the computer reads the field in
//    that polarity with the offset the set/reset estimate held before the test started failing;
//  - field norm: |B| measured against |B_ref| (detection only: it names no axis).
//  Panel faults (fault_detection_faces.cpp; docs/faults.md, "Panel faults"):
//  - face ratio: once the calibration applies, a face low in the sun reading a small fraction of its
//    expectation (an open string as soon as the face turns a little toward the sun); same bit as the deficit;
//  - face scale: a confirmed deficit that read a steady fraction of the expectation (a shadow, degraded
//    cells) is that fraction, compensated (the face read divided by it), not excluded;
//  - face dark: current on a face while the on-board orbit puts the spacecraft in the umbra (a Hall offset);
//  - face stuck: a reading that stands still while the predicted response moves (a stuck Hall channel).
// Float or double, fixed sizes, no heap, no exceptions (the firmware runs it).
#pragma once

#include <array>
#include <cstdint>

#include "attitude_estimator/types.hpp"
#include "panel_response/kelly.hpp"

namespace attitude_estimator {

// Bits of a face's fault word.
inline constexpr std::uint32_t kFaultFaceDeficit = 1u;  // reads well below the predicted response
inline constexpr std::uint32_t kFaultFaceExcess = 2u;   // reads well above it (more than albedo can add)
inline constexpr std::uint32_t kFaultFaceBus = 4u;      // its axis' Hall current disagrees with the face pair
// Panel faults: a face reading a steady fraction of its light (shadow, degradation) is
// compensated, not excluded (FaultDetectionState::face_scale); a Hall channel reading current in the Earth's
// umbra (offset, stuck) or not moving while the light on it does (stuck) is excluded.
inline constexpr std::uint32_t kFaultFaceScale = 8u;   // reads face_scale of the prediction: divided by it
inline constexpr std::uint32_t kFaultFaceDark = 16u;   // reads current in the predicted umbra
inline constexpr std::uint32_t kFaultFaceStuck = 32u;  // its reading does not move while the prediction does
// Bits of a magnetometer axis' fault word.
inline constexpr std::uint32_t kFaultAxisRail = 1u;    // at a rail of its converter
inline constexpr std::uint32_t kFaultAxisNoFlip = 2u;  // does not flip with the set/reset polarity
// The set/reset strap failed (set on the three axes at once). Not an exclusion: the axes are read in the
// polarity the film stayed in (FaultDetectionState::strap_polarity, strap_offset).
inline constexpr std::uint32_t kFaultAxisStrap = 4u;
// Spikes: one-sample outliers against the prediction come faster than spike_count per spike_window. Not an
// exclusion: each outlier's sample is skipped (FaultDetectionState::spike_now), the axis stays in use.
inline constexpr std::uint32_t kFaultAxisSpiking = 8u;
// A bias jump: a new field at the sensor (it flips with the set/reset polarity as the earth's does, so the
// set/reset difference keeps it) seen as the axis' mean innovation. Not an exclusion: the calibration's
// offset takes the jump and re-learns it (FaultDetectionState::bias_jump_now, bias_jump).
inline constexpr std::uint32_t kFaultAxisBias = 16u;

// cos β of face k (+x, −x, +y, −y, +z, −z: the order of every per-face array) for a unit sun direction in body axes.
template <class T>
constexpr T face_cos(const Vec3<T>& sun_body, std::size_t k) noexcept {
    return (k % 2 == 0 ? T(1) : T(-1)) * sun_body[k / 2];
}

template <class T>
struct FaultDetectionConfig {
    bool enabled = false;
    T confirm_time = T(5);  // s: a test must fail this long (not interrupted by a pass) before a declaration
    // Face tests: applied where the predicted relative response is at least face_min_response and the sun
    // is bright enough: the irradiance, the largest measured-to-predicted ratio of the other faces the
    // prediction puts at others_min_predicted or more, must be at least others_min_irradiance (not in
    // eclipse, not deep in penumbra). The deficit test compares with the prediction times that irradiance.
    T face_min_response = T(0.4);
    T face_deficit = T(0.3);  // fail below (irradiance × predicted − this), relative to full sun
    // Panel faults (issue 28): the ratio test, a second deficit test for faces low in the sun.
    // Once the in-flight magnetometer calibration applies (the filter's attitude then within about a degree), a
    // face is also tested where irradiance × predicted is only face_ratio_min_response, and fails when it reads
    // below face_ratio of that: an open string (0) is seen as soon as the face turns a little toward the sun.
    T face_ratio_min_response = T(0.1);
    T face_ratio = T(0.3);
    // A confirmed deficit whose mean measured-to-expected ratio over its failing samples (those expected at
    // others_min_predicted or more) is at least face_scale_min is a lower scale (a shadow over part of the face,
    // degraded cells), not a dead face: declared kFaultFaceScale with that ratio, and the face read divided by it.
    // A face already scaled is failing on its compensated reading: its scale is then the product, and a product
    // below face_scale_min is a dead face (excluded) however many steps it took.
    T face_scale_min = T(0.2);
    // In the predicted umbra no face is lit (no sun, and the Earth below is dark): a face reading more than this
    // (relative to full sun) fails the dark test.
    T face_dark_max = T(0.03);
    // Stuck test, in the sun: a reading that stays within face_stuck_tolerance (relative) of where it started
    // while the predicted response certainly spans face_stuck_change (the band the filter's covariance allows
    // the prediction, kFacePredictionSigmas wide, taken out) fails. A reading stuck below
    // face_dark_max is left to the deficit test (an open string's).
    T face_stuck_change = T(0.15);
    T face_stuck_tolerance = T(0.003);
    T face_excess = T(0.6);  // fail above (predicted + this): albedo adds at most ~0.4 on a nadir face
    // A face reading more than this (relative to full sun) has the sun itself on it: albedo adds at most ~0.4 on
    // a face toward nadir. Its opposite face is then dark (cos β at most about −0.1), which tells an excluded face
    // dark without a prediction: after a reset the sun is formed from the faces left, and the filter can restart
    // (onboard_computer.cpp).
    T face_direct_min = T(0.5);
    T others_min_irradiance = T(0.5);
    T others_min_predicted = T(0.3);
    T bus_tolerance = T(0.02);  // A: |i_sh[k] − (i_face[2k] − i_face[2k+1])|
    // Flip test: applied where the predicted field along the axis is at least flip_min_field; fails when
    // the measured half difference along the predicted sign is below flip_fraction of it and the difference
    // did not move (within frozen_tolerance of zero: a stuck axis; one that moved holds a field at the sensor,
    // the bias test's, fault_detection_mag.cpp). The strap test
    // uses the same two numbers on the field left without its largest component (the least any two axes
    // show): applied where that is at least flip_min_field, failing below flip_fraction of it.
    T flip_min_field = T(15e-6);  // T
    // The same once a calibration's hard iron is in the prediction (FaultObservation::field_offset_known: the
    // ground calibration from the first sample, the in-flight one once it applies): the spacecraft's own
    // field, 7.3 µT at the sensor in leo_orbit, is what the 15 µT bar allows for.
    T flip_min_field_calibrated = T(3e-6);  // T
    T flip_fraction = T(0.25);
    T norm_tolerance = T(12e-6);  // T: | |B| − |B_ref| |
    // Magnetometer (fault_detection_mag.cpp). Frozen test: an axis stuck at its last value reads exactly the
    // same across a set/reset flip, a healthy one flips by 2 S B_k. Where the flip test's bar is not reached
    // (a weak field along the axis) but the calibrated prediction is at least frozen_min_field and 4 σ of
    // its own uncertainty (FaultObservation::field_sigma), the axis fails when its half difference is below
    // frozen_tolerance (the sensor's noise is a few 10 nT: a healthy axis crosses that band in a fraction
    // of a second).
    T frozen_min_field = T(1e-6);     // T
    T frozen_tolerance = T(0.02e-6);  // T
    // The reading's own steps (issue 39): a stuck output read through the converter can still toggle a code
    // on its channel and on the reference's (FaultObservation::mag_reading_step, one step of each), so two
    // readings of a stuck axis differ by up to that much. The difference counts as moved (the flip test) and
    // as not frozen (the frozen test) only above frozen_steps of it: half difference
    // max(frozen_tolerance, frozen_steps × mag_reading_step / 2S).
    T frozen_steps = T(2);  // 1
    // Spike test: an axis' measured field (before the calibration) further from the prediction than
    // spike_gate × √(field_sigma_k² + spike_sigma²) is an outlier; spike_sigma is what a healthy axis
    // strays besides the attitude's uncertainty (noise, the on-board field model's truncation, the
    // calibration's residual). At most two outliers in a row are spikes (skipped; ten once the axis is
    // declared spiking); a longer run is a change of the field or of the filter, not a spike, and is let
    // through.
    T spike_sigma = T(0.5e-6);     // T
    T spike_gate = T(6);           // 1
    T spike_window = T(60);        // s
    std::int32_t spike_count = 5;  // spikes in one window that declare the axis spiking
    // Bias-jump test: the innovation (measured minus predicted field, before the calibration, spikes left
    // out) averaged per axis with an exponential window of bias_window; an axis fails while |mean| >
    // bias_threshold (the attitude error's share turns with the tumble and averages out; a field fixed in
    // the sensor does not).
    T bias_window = T(60);       // s
    T bias_threshold = T(1e-6);  // T
    // The jump's size is the same innovation averaged over this much (s, exponential): by the declaration,
    // at least the confirmation time after the onset, it has caught up with the step to e^(−5 s/τ). At 3 s it
    // was 10 % short when a large jump was declared 6.8 s after its onset (38.5 µT: a 4 µT residual); at 1 s
    // the step is caught to 0.7 % and the noise averaged over 40 samples at 20 Hz (docs/faults.md).
    T bias_recent_window = T(1);  // s
    T bias_noise_factor = T(1);   // the filter's field noise is raised this much until the offset is re-learnt
};

// What one sample offers the tests. Predictions are those of the filter (zero / false when it is not
// running): then only the bus, rail and norm tests can run.
template <class T>
struct FaultObservation {
    T t = T(0);
    std::array<T, 6> face_r{};   // 1: digitized face currents over their normalization (at the sun distance)
    std::array<T, 6> i_face{};   // A: digitized face currents
    Vec3<T> i_sh{};              // A: digitized per-axis differential currents
    bool bus_available = false;  // both i_sh and i_face are read (the bus test needs both)
    bool predicted = false;      // the filter runs: the two predictions below hold
    Vec3<T> sun_body{};          // unit sun direction predicted in body axes
    // 1σ of each component of sun_body from the filter's attitude covariance (0: exact). The face tests compare
    // with the response the prediction gives within kFacePredictionSigmas of it (fault_detection_faces.cpp).
    Vec3<T> sun_sigma{};
    // The filter calls its attitude valid (running, its 3σ bound below MekfConfig::valid_bound): the face tests
    // (deficit, ratio, excess, stuck) judge a reading against the prediction only then. The band above assumes
    // the covariance is honest, and a filter lost from its start can be further off than its covariance allows
    // while that is still wide: robustness seed 42's run 23 started 86° off with about 12° allowed, and its
    // healthy faces were declared one after another until none was left to restart the filter from
    // (docs/faults.md, "A lost start: the face tests wait for a valid filter").
    bool prediction_valid = false;
    Vec3<T> field_body{};           // T: field predicted at the sensor, in body axes
    Vec3<T> field_sigma{};          // T: 1σ of field_body per axis from the filter's attitude covariance
    bool field_calibrated = false;  // field_body includes the in-flight calibration's hard iron and scale
    // field_body includes the spacecraft's own field at the sensor: a calibration's hard-iron estimate, the
    // in-flight one or the uplinked ground calibration's (its error 0.5 µT per axis in leo_orbit, not 7.3 µT)
    bool field_offset_known = false;
    Vec3<T> mag_reading{};  // V: digitized v_mag − v_mag_ref (offset and polarity still in)
    T polarity = T(1);      // the set/reset polarity the reading was taken in
    // The polarity the computer commanded for it (differs from `polarity` once a failed strap is declared:
    // the recovery test pairs readings by the command).
    T commanded_polarity = T(1);
    Vec3<T> mag_offset{};  // V: the sensor offset the computer takes out of this reading
    // V: the most two readings of a stuck axis differ by through the converter alone, one step of the axis'
    // channel plus one of the reference's (each may toggle between two codes); 0 for ideal converters.
    Vec3<T> mag_reading_step{};
    T sensitivity = T(1e4);         // V/T
    std::array<bool, 3> at_rail{};  // each channel within the rail margin of its converter's ends
    bool field_usable = false;      // the measured field below is complete (no axis excluded or at a rail)
    Vec3<T> field{};                // T: measured field (offset removed, calibrated when the calibration applies)
    bool field_measured = false;    // field_uncalibrated holds this sample's reading (each axis: !at_rail)
    Vec3<T> field_uncalibrated{};   // T: measured field at the sensor, set/reset offset removed, no calibration
    T field_ref_norm = T(0);        // T: |B_ref| (0: no reference)
    T sample_period = T(0.05);      // s
    const panel_response::Response<T>* response = nullptr;  // the panels' angular law
    // Panel faults, from the on-board orbit and sun: deep in the Earth's umbra (no face lit), or near or in its
    // shadow (penumbra: the irradiance changes faster than the other faces can tell, no deficit or stuck test).
    bool umbra = false;
    bool near_shadow = false;
    // The on-board orbit (a position from the computer's own element set) puts the spacecraft clear of the
    // shadow (not near_shadow): the sun is full. Where no other face can tell the irradiance (only one face
    // well lit), the face tests take it as full sun.
    bool clear_of_shadow = false;
};

// Trivially copyable (part of the FMU state and of the firmware's memory).
template <class T>
struct FaultDetectionState {
    // Seconds each test has been failing without a pass in between: faces (deficit, excess, bus), axes
    // (rail, flip), norm.
    std::array<std::array<T, 3>, 6> face_failing{};
    std::array<std::array<T, 2>, 3> axis_failing{};
    T norm_failing = T(0);
    std::array<std::uint32_t, 6> face_word{};  // declared faults (kFaultFace* bits), latched
    std::array<T, 6> face_time{T(-1), T(-1), T(-1), T(-1), T(-1), T(-1)};  // s, when declared (−1: never)
    std::array<std::uint32_t, 3> axis_word{};                              // kFaultAxis* bits, latched
    std::array<T, 3> axis_time{T(-1), T(-1), T(-1)};
    std::uint32_t norm_word = 0;  // 1 once the field-norm test has been confirmed
    T norm_time = T(-1);
    Vec3<T> last_reading{};  // the previous sample's mag_reading and polarity (flip test)
    T last_polarity = T(0);
    T last_t = T(0);
    bool has_last = false;
    // The strap test: its evidence, the offset at its last pass (the estimate from before a failure: the
    // set/reset mean follows a failed strap's readings within a second), and once it is declared, the
    // polarity the film stayed in (+1 set, −1 reset).
    T strap_failing = T(0);
    Vec3<T> strap_offset{};
    bool strap_failed = false;
    T strap_polarity = T(1);
    // Panel faults. The deficit test's mean measured-to-expected ratio (sum and count over
    // its failing samples); the scale a kFaultFaceScale face is read divided by (1: none); the stuck test's
    // window: the reading it started at and, since, the least of the response's upper bounds (stuck_low) and the
    // greatest of its lower bounds (stuck_high): the prediction's band, fault_detection_faces.cpp.
    std::array<T, 6> deficit_ratio_sum{};
    std::array<T, 6> deficit_ratio_count{};
    std::array<T, 6> face_scale{T(1), T(1), T(1), T(1), T(1), T(1)};
    std::array<T, 6> stuck_anchor{};
    std::array<T, 6> stuck_low{};
    std::array<T, 6> stuck_high{};
    std::array<bool, 6> stuck_started{};
    std::array<T, 6> stuck_failing{};  // seconds failing: stuck and dark tests
    std::array<T, 6> dark_failing{};
    // Recovery: once failed, the strap test goes on pairing readings by the commanded polarity; passing
    // for the confirmation time clears strap_failed (the kFaultAxisStrap bits stay as the record).
    T strap_passing = T(0);
    T last_commanded_polarity = T(0);
    T strap_cleared_time = T(-1);  // s, when the strap was last seen working again (−1: never)
    // Spike test: this sample's spikes (bit k = axis k: its field is to be skipped), outliers in a row,
    // spikes so far, and the current window's start and count.
    std::uint8_t spike_now = 0;
    std::array<std::int32_t, 3> outlier_run{};
    std::array<std::int32_t, 3> spikes{};
    std::array<T, 3> spike_window_start{T(-1), T(-1), T(-1)};
    std::array<std::int32_t, 3> spike_window_count{};
    // Bias-jump test: the innovation's mean per axis, its evidence; a jump declared at this sample (the
    // computer moves the calibration's offset by bias_jump, the means at the declaration) and, until the
    // calibration has re-learnt its offset, bias_recovering.
    Vec3<T> bias_mean{};
    Vec3<T> bias_recent{};  // the same over a twentieth of the window: the jump's size at the declaration
    std::array<T, 3> bias_failing{};
    bool bias_jump_now = false;
    Vec3<T> bias_jump{};
    bool bias_recovering = false;
};

// One sample of every test that the observation allows; declares faults whose test has failed for
// config.confirm_time (at that sample's t).
template <class T>
void fault_detect(FaultDetectionState<T>& s, const FaultObservation<T>& o, const FaultDetectionConfig<T>& c) noexcept;

// Faces excluded (bit k = face k) and axes excluded (bit k = axis k: rail or no flip; a failed strap
// excludes nothing) by the faults declared so far.
template <class T>
std::uint8_t excluded_faces(const FaultDetectionState<T>& s) noexcept;
template <class T>
std::uint8_t excluded_axes(const FaultDetectionState<T>& s) noexcept;

// How deep the spacecraft is in the Earth's shadow cylinder (km): the Earth's radius less its distance from the
// Earth–sun line when it is behind the Earth along the sun, so positive inside; −1e9 on the sun's side or with no
// position (zero). At LEO the umbra cone is ~30 km narrower than the cylinder and the penumbra as wide outside it.
// position_km any Earth-centred inertial frame, sun_unit the same frame.
template <class T>
T shadow_depth_km(const Vec3<T>& position_km, const Vec3<T>& sun_unit) noexcept;

extern template void fault_detect(FaultDetectionState<float>&, const FaultObservation<float>&,
                                  const FaultDetectionConfig<float>&) noexcept;
extern template void fault_detect(FaultDetectionState<double>&, const FaultObservation<double>&,
                                  const FaultDetectionConfig<double>&) noexcept;
extern template std::uint8_t excluded_faces(const FaultDetectionState<float>&) noexcept;
extern template std::uint8_t excluded_faces(const FaultDetectionState<double>&) noexcept;
extern template std::uint8_t excluded_axes(const FaultDetectionState<float>&) noexcept;
extern template std::uint8_t excluded_axes(const FaultDetectionState<double>&) noexcept;
extern template float shadow_depth_km(const Vec3<float>&, const Vec3<float>&) noexcept;
extern template double shadow_depth_km(const Vec3<double>&, const Vec3<double>&) noexcept;

}  // namespace attitude_estimator
