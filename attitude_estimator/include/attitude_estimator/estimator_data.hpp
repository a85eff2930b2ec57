// The variables of attitude_estimator.fmu as one plain struct, and the three conversions between it and the
// on-board computer (onboard_computer.hpp): settings from the parameters, inputs, outputs back. FMI-free:
// the FMU block (estimator_block.hpp) and the Cortex-M firmware (attitude_estimator/firmware) both hold
// an EstimatorData and run the same conversions, so a parameter means the same on either.
#pragma once

#include <array>
#include <cstdint>

#include "attitude_estimator/onboard_computer.hpp"
#include "attitude_estimator/string_field.hpp"
#include "fmu/fixed_string.hpp"  // a plain fixed-capacity string (the TLE lines; not sent to the firmware)
#include "orbit/tle.hpp"         // the Tle struct (its parser is called by the block only)

namespace attitude_estimator {

using Vec3d = std::array<double, 3>;
using Faces = std::array<double, 6>;  // one value per face: +x, −x, +y, −y, +z, −z

// Longest sun-vector history the spin-rate FFT can analyse (samples; 102 s at 20 Hz). The history is part
// of the FMU state, so it has a fixed size inside the data struct.
inline constexpr std::int32_t kMaxSpinWindow = 2048;

// The numbers of a two-line element set (tle_elements): epoch, n, e, i, node, perigee, M, B*.
inline constexpr std::size_t kElementCount = orbit::kTleElementCount;

// The panels' angular response the sun methods invert (the `angular_response` choice).
enum class AngularResponse : std::int32_t { cosine = 0, kelly = 1 };
// The arithmetic of the on-board computer (the `precision` choice): double, or float as the firmware on
// a Cortex-M4F computes (attitude_estimator/firmware).
enum class Precision : std::int32_t { double_precision = 0, single_precision = 1 };

// Every variable of the block (double precision throughout; the on-board computer's own state in the
// precision it runs in). No FMI type here: the firmware keeps its parameters, inputs and outputs in one
// of these too, set through the wire table generated from the block's table. Defaults of the sensor chain match the other
// blocks: i_sc_norm is ssr_plant's short-circuit current of one panel at normal incidence and 1367 W/m²,
// the voltage channel and sensitivity are the HMC2003's (magnetometer block).
// Where the on-board computer's core has a default of its own, the parameter starts from it (written once,
// in the core: EstimatorConfig, SunMethodConfig, MekfConfig, SetResetConfig, MagCalibrationConfig); the
// block's own choices (the current channels' range, the face noise, the set/reset period) are written here,
// and four the core keeps in structs holding the field model's tables (sample_period, rate_interval,
// field_degree, reference_period: a 6 kB temporary each, which the firmware's stack should not carry).
struct EstimatorData {
    // inputs. Their start values describe a consistent, lit, identity attitude (+x face towards the sun,
    // a 30 µT field along +z), so the block alone, unconnected, produces a valid estimate.
    Vec3d i_sh{kPanelCurrentAt1Au<double>, 0.0, 0.0};  // A, held differential currents I_sc+k − I_sc−k
    Faces i_face{kPanelCurrentAt1Au<double>, 0.0, 0.0, 0.0, 0.0, 0.0};  // A, per-face sample/holds (i_face_sh)
    Vec3d v_mag{2.5, 2.5, 2.8};                                         // V, magnetometer outputs X, Y, Z
    double v_mag_ref = 2.5;                                             // V, magnetometer zero-field reference output
    Vec3d sun_ref{1.0, 0.0, 0.0};                                       // 1, sun direction, inertial frame (any length)
    Vec3d mag_ref{0.0, 0.0, 30e-6};           // T, geomagnetic field, inertial frame (any length)
    double sun_distance = kAstronomicalUnit;  // m, satellite to sun (on-board ephemeris; environment sun_distance)

    // parameters
    double sample_period = 0.05;  // s: 20 Hz, the seed asks for more than 10 Hz
    Vec3d i_sc_norm{kPanelCurrentAt1Au<double>, kPanelCurrentAt1Au<double>,
                    kPanelCurrentAt1Au<double>};               // A: ssr_plant's i_sc0 (000 eq. 5 denominators)
    double mag_sensitivity = kHmc2003Sensitivity<double>;      // V/T: 1 V/gauss
    double weight_sun = EstimatorConfig<double>{}.sun_weight;  // a_1 of 000 eq. 8 (normalized with weight_mag)
    double weight_mag = EstimatorConfig<double>{}.mag_weight;  // a_2
    std::int32_t adc_bits =
        static_cast<std::int32_t>(EstimatorConfig<double>{}.mag_ref_adc.bits);  // TMS320F2808: 12; 0 = ideal
    double i_adc_min = -1.2;  // A: current channels' full-scale range, ±1.4 i_sc0
    double i_adc_max = 1.2;
    double v_adc_min = EstimatorConfig<double>{}.mag_ref_adc.min;  // V: voltage channels (HMC2003 outputs 0…5 V)
    double v_adc_max = EstimatorConfig<double>{}.mag_ref_adc.max;
    SolverKind solver = EstimatorConfig<double>{}.solver;          // qmethod (the seeds' method) or fast
    double min_sun_norm = kDefaultMinSunNorm<double>;              // 1: eclipse threshold on |s|
    double mag_rail_margin = kDefaultRailMargin<double>;           // V: saturation margin at the range ends
    double min_field = kDefaultMinField<double>;                   // T
    double min_separation_sin = kDefaultMinSeparationSin<double>;  // 1: sin 5°
    // Sun sensing (sun_methods.hpp, docs/sun_methods.md).
    SunMethod sun_method = SunMethodConfig<double>{}.method;     // difference | inverse_response | cones | three_faces
    AngularResponse angular_response = AngularResponse::cosine;  // cosine (000 eq. 1) | kelly (the table below)
    Faces kelly_angle{0.0, 30.0, 50.0, 60.0, 80.0, 85.0};        // deg: ssr_plant's Kelly table (000 fig. 4)
    Faces kelly_value{1.0, 0.866, 0.635, 0.450, 0.100, 0.0};     // 1: relative response at those angles
    Faces i_face_norm = SunMethodConfig<double>{}.i_face_norm;   // A: face current at β = 0
    double face_dark_threshold = SunMethodConfig<double>{}.dark_threshold;  // 1: lit above this fraction of i_face_norm
    double i_face_adc_max = EstimatorConfig<double>{}.face_adc[0].max;      // A: face-current channels span 0 … this
    double cone_tolerance = SunMethodConfig<double>{}.cone_tolerance;  // 1: cones' agreement on the relative response
    double cube_max_step =
        SunMethodConfig<double>{}.cube_max_step;  // rad: cones may cross forbidden cube edges by this
    double orbit_altitude =
        570e3;  // m: cones' Earth-albedo model's height (reference_source = inputs; onboard: its set's)
    double cone_fit_tolerance =
        SunMethodConfig<double>{}.cone_fit_tolerance;  // 1: albedo fit's RMS misfit bound (0: off)
    double cone_albedo_max =
        SunMethodConfig<double>{}.cone_albedo_max;  // 1: largest fitted albedo of a face toward nadir
    // Rates (rates.md): spin frequencies from the FFT of sun_meas; mean |ω| from successive q_est (004 eq. 4).
    std::int32_t spin_window = 512;  // samples per FFT window (0: off)
    double rate_interval = 2.0;      // s: shortest time between two attitudes in one eq. 4 increment
    std::int32_t rate_window = 8;    // increments averaged (1 = eq. 4 alone)
    // Recursive filter (mekf.hpp, docs/filter.md): none (the seeds' single-frame estimate only) or mekf.
    FilterKind filter = FilterKind::none;
    Precision precision = Precision::double_precision;         // double, or float as on the Cortex-M firmware
    double filter_sun_sigma = MekfConfig<double>{}.sun_sigma;  // rad: sun vector noise and model error, 1σ per axis
    double filter_mag_sigma = MekfConfig<double>{}.mag_sigma;  // T: field vector noise and model error, 1σ per axis
    // The sun's noise model per sun method (difference, inverse_response, cones, three_faces): 1σ per axis
    // (rad; 0: filter_sun_sigma) and the error's correlation time (s; 0: white). docs/filter.md.
    std::array<double, 4> filter_sun_sigma_method{};
    std::array<double, 4> filter_sun_correlation{};
    bool filter_sun_turn = false;                                      // MekfConfig::sun_turn_correlation
    double filter_mag_ref_sigma = MekfConfig<double>{}.mag_ref_sigma;  // T: 1σ per axis of the reference field's error
    // MekfConfig::mag_ref_rms and mag_ref_correlation: the reference's error along the orbit, rms per axis (T; 0:
    // with the on-board references, what the on-board field model's degree leaves of IGRF-14 at the on-board
    // orbit's semi-major axis, omitted_field_rms, as the ground computes it for the uplink) and its correlation
    // time (s; 0: not modelled, filter_mag_ref_sigma alone).
    double filter_mag_ref_rms = 0.0;
    double filter_mag_ref_correlation = 0.0;
    double filter_mag_ref_rms_used = 0.0;   // calculated at configure: the rms the filter weighs (derived or given)
    double filter_mag_ref_tilt = 0.0;       // rad, about the orbit's normal; 0: derived (MekfConfig::mag_ref_tilt)
    double filter_mag_ref_tilt_used = 0.0;  // calculated at configure: the tilt the filter considers
    double filter_mag_sigma_calibrated = MekfConfig<double>{}.mag_sigma_calibrated;  // T: once calibrated (0: the same)
    double filter_mag_sigma_eclipse =
        MekfConfig<double>{}.mag_sigma_calibrated_eclipse;                   // T: calibrated, no sun (0: the same)
    double filter_mag_hard_iron = MekfConfig<double>{}.mag_hard_iron_sigma;  // T: hard-iron prior (0: none)
    double filter_start_rate = MekfConfig<double>{}.start_rate_sigma;    // rad/s: 1σ rate prior at the start (0: none)
    double filter_rate_noise = MekfConfig<double>{}.rate_noise;          // rad/s: 1σ rate change over 1 s (rad/s/√s)
    double filter_attitude_noise = MekfConfig<double>{}.attitude_noise;  // rad: 1σ attitude drift over 1 s (rad/√s)
    bool filter_offset = MekfConfig<double>{}.estimate_offset;           // estimate the magnetometer offset (3 states)
    bool filter_scale = MekfConfig<double>{}.estimate_scale;  // estimate a common panel scale (face-based methods)
    double filter_face_sigma = 0.02;                          // 1: relative face response noise and model error, 1σ
    std::array<double, 9> inertia{};                          // kg m², row-major; all zero = kinematic rate model
    std::array<double, 3> filter_dipole{};  // A m², body: the uplinked residual dipole whose torque the filter models
    bool filter_gravity_gradient = false;   // the filter models the gravity-gradient torque
    double filter_torque_noise = 0.0;       // N m √s: the unmodelled torques as white noise (through the inertia)
    // The drag torque (MekfConfig::drag), on with filter_drag: the box as the computer knows it (the design's,
    // uplinked), its belief of the density against its table, and that density's uncertainty.
    bool filter_drag = false;
    std::array<double, 3> body_size{};                                            // m: edges along body x, y, z
    std::array<double, 3> centre_of_mass{};                                       // m: from the box's geometric centre
    double drag_coefficient = 0.0;                                                // 1
    double filter_drag_density_scale = MekfConfig<double>{}.drag_density_scale;   // 1: on-board density / table
    double filter_drag_density_sigma = MekfConfig<double>{}.drag_density_sigma;   // 1: its relative 1σ
    double filter_drag_correlation = MekfConfig<double>{}.drag_correlation_time;  // s: that error's persistence
    std::int32_t filter_reset_after = MekfConfig<double>{}.reset_after;           // samples all refused before a reset
    double filter_watch_time = MekfConfig<double>{}.watch_time;          // s: the divergence watch's averaging (0: off)
    double filter_watch_gate = MekfConfig<double>{}.watch_gate;          // its ratio above which the filter is lost
    bool filter_watch_sun = MekfConfig<double>{}.watch_sun;              // MekfConfig::watch_sun
    bool filter_hold_field_axis = MekfConfig<double>{}.hold_field_axis;  // MekfConfig::hold_field_axis
    // HMC2003 set/reset (set_reset.hpp): pulse every this many samples and average the offset over this
    // many set/reset pairs. 0 (default): no pulses, the offset stays in the field — the safe default for a
    // magnetometer whose set_reset_command is not wired to mag_set_reset (its readings never flip).
    std::int32_t mag_set_reset_samples = 0;
    std::int32_t mag_offset_window = SetResetConfig{}.offset_window;
    // The reference vectors (onboard_references.hpp): the inputs sun_ref, mag_ref, sun_distance, or the
    // computer's own models from its element set at its clock.
    ReferenceSource reference_source = ReferenceSource::inputs;
    fmu::FixedString<80> tle_line1{};  // the computer's own two-line element set (uplinked)
    fmu::FixedString<80> tle_line2{};
    std::int32_t field_degree = 8;         // IGRF-14 truncated to this degree on board (1 = dipole … 13)
    std::int32_t clock_epoch_year = 2026;  // the computer's clock: UTC at t = 0
    std::int32_t clock_epoch_month = 3;
    std::int32_t clock_epoch_day = 20;
    std::int32_t clock_epoch_hour = 0;
    std::int32_t clock_epoch_minute = 0;
    double clock_epoch_second = 0.0;
    // The uplink's errors (docs/onboard_references.md): the computer's clock at t = 0 is clock_epoch_* plus
    // clock_offset, and its element set is the given one (tle_lines or tle_elements: the scenario's set)
    // made uplink_age older along SGP4's secular rates (orbit/element_age.hpp). 0, 0: the given values as
    // they are (a recorded uplink).
    double clock_offset = 0.0;       // s
    double uplink_age = 0.0;         // s
    double reference_period = 10.0;  // s between two evaluations of the on-board orbit, sun and field
    // The same element set as numbers, in the set's own units: epoch (Julian date, UTC), mean motion
    // (rev/day), eccentricity, inclination, right ascension of the node, argument of perigee, mean anomaly
    // (deg), B* (1/Earth radii). Used when tle_line1 and tle_line2 are empty: the firmware gets its set this
    // way, as the bridge's configure frames carry numbers only.
    std::array<double, kElementCount> tle_elements{};
    // The set the computer uses, parsed from tle_line1/2 by the orbit library in the block's configure()
    // (not declared: the block never parses text; all zero on the firmware, which then uses tle_elements).
    std::array<double, kElementCount> parsed_elements{};
    // In-flight magnetometer calibration (mag_calibration.hpp, docs/filter.md): scale, non-orthogonality and
    // offset against the reference field's magnitude; an equation every this many samples, applied once
    // this many equations are in; σ per axis of one field reading.
    bool mag_calibration = false;
    double mag_calibration_sigma = MagCalibrationConfig<double>{}.sigma;  // T (the 12-bit steps alone: 0.035 µT rms)
    std::int32_t mag_calibration_every = MagCalibrationConfig<double>{}.every;        // samples
    std::int32_t mag_calibration_min = MagCalibrationConfig<double>{}.min_equations;  // equations
    // The ground calibration uplinked before flight (docs/filter.md, "The ground calibration"), with
    // mag_calibration: the spacecraft's own field at the sensor, derived from the scenario's magnetic budget
    // (the residual dipole mag_prior_dipole at mag_prior_dipole_position, seen at mag_prior_sensor_position:
    // the magnetometer's layout) plus the ground calibration's error mag_prior_offset_error, weighed with
    // mag_prior_offset_sigma per axis (0: no ground calibration).
    std::array<double, 3> mag_prior_dipole{};                           // A m², body axes
    std::array<double, 3> mag_prior_dipole_position{0.0, 0.0, 0.0};     // m, body axes (magnetometer default)
    std::array<double, 3> mag_prior_sensor_position{0.01, 0.01, 0.11};  // m, body axes (magnetometer default)
    // T: what the ground measurement got wrong, about 1σ of a clean-room measurement of a small satellite's
    // own field (power system off) per axis, with signs of no pattern: the residual a filter must expect.
    std::array<double, 3> mag_prior_offset_error{0.4e-6, -0.3e-6, 0.5e-6};
    double mag_prior_offset_sigma = 0.0;  // T, 1σ per axis the computer gives its ground calibration
    double mag_prior_field_sigma = 0.0;   // T: the field's σ in the filter meanwhile (0: filter_mag_sigma_calibrated)
    // Or (above 0) that σ from the field's turn through the uncalibrated sensor: 1σ per axis (T) correlated over one
    // radian of the tumble, at most the correlation (s) (docs/filter.md, "The field before the calibration").
    double mag_prior_field_fluctuation = 0.0;
    double mag_prior_field_correlation = 300.0;
    // The panels' string currents' field at the sensor, taken out of the field with mag_string_field (docs/filter.md,
    // "The strings' field"): each face's string a loop (string_field.hpp; 3 numbers per face, +x, −x, +y, −y, +z,
    // −z; zero sides: no loop) seen from mag_prior_sensor_position, its field per ampere times (1 +
    // mag_string_field_error), the uplinked knowledge's named error; the core gets the six per-ampere fields.
    bool mag_string_field = false;
    std::array<double, 18> mag_string_loop_center{};  // m, body axes
    std::array<double, 18> mag_string_loop_side_a{};  // m
    std::array<double, 18> mag_string_loop_side_b{};  // m
    double mag_string_field_error = 0.05;             // 1: the per-ampere fields the computer is given, relative

    // outputs (discrete: set at sample instants, held in between). Before the first sample: identity.
    std::array<double, 4> q_est{0.0, 0.0, 0.0, 1.0};                           // scalar-last [x, y, z, w], w >= 0
    std::array<double, 9> A_est{1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0};  // row-major, w_body = A v_ref
    Vec3d sun_meas{};       // 1, unit sun vector in body axes (zero when sun_valid is false)
    Vec3d mag_meas{};       // 1, unit field vector in body axes (zero when mag_valid is false)
    Vec3d mag_field{};      // T, measured field in body axes
    double sun_norm = 0.0;  // 1, |s| of 000 eq. 5 before normalization
    double loss = 0.0;      // 1, L(A) of 000 eq. 8
    bool valid = false;
    bool sun_valid = false;
    bool mag_valid = false;
    std::int32_t samples = 0;             // samples taken so far (saturates at 2^31 − 1)
    std::int32_t lit_faces = 0;           // bit k: face k above the dark threshold (face-based methods)
    std::int32_t rejected_faces = 0;      // bit k: lit face k not used (albedo)
    std::int32_t cube_state = kCubeDark;  // cones: panel-cube state 9(x+1) + 3(y+1) + (z+1)
    double spin_theta_dot = 0.0;          // rad/s, θ̇ of the seed's spin (FFT of sun_meas, 000 §4)
    double spin_phi_dot = 0.0;            // rad/s, φ̇
    double spin_bin_width = 0.0;          // rad/s, frequency resolution 2π/(N T)
    double spin_window_time = 0.0;        // s, N T
    bool spin_valid = false;
    double rate_mean = 0.0;         // rad/s, mean |ω| from successive estimates (004 eq. 4)
    double rate_window_time = 0.0;  // s, time the averaged increments span
    bool rate_valid = false;
    std::array<double, 4> q_filt{0.0, 0.0, 0.0, 1.0};  // filter attitude, scalar-last, w >= 0
    Vec3d omega_filt{};                                // rad/s, filter body rate
    Vec3d mag_offset_filt{};        // V: the filter's estimate of the offset left after mag_offset is taken out
    double panel_scale_filt = 0.0;  // 1: estimated common panel scale error ε (currents (1 + ε) × nominal)
    double attitude_bound = 0.0;    // rad: 3σ bound on the filter's attitude error
    std::array<double, 6> attitude_cov_sqrt{};  // rad: L of P_θθ = L Lᵀ, lower triangle by rows
    bool filter_valid = false;
    std::int32_t filter_resets = 0;  // divergence resets so far
    bool mag_set_reset = true;       // the set/reset pulse commanded last: true set, false reset (to the sensor)
    Vec3d mag_offset{};              // V, the sensor offset estimated from set/reset pairs
    Vec3d ref_sun{};                 // 1, the sun reference the last sample used (J2000)
    Vec3d ref_mag{};                 // T, the field reference the last sample used (J2000)
    bool mag_cal_valid = false;      // an in-flight calibration is applied

    // Fault detection, isolation and recovery (fault_detection.hpp, docs/faults.md): parameters and outputs.
    bool detect_faults = false;
    double detect_confirm_time = 5.0;                // s: a test fails this long before a fault is declared
    double detect_face_min_response = 0.4;           // 1: face tests where the predicted response is at least this
    double detect_face_deficit = 0.3;                // 1: a face reading this far below the prediction fails
    double detect_face_excess = 0.6;                 // 1: ... this far above it (albedo adds up to ~0.4)
    double detect_face_direct_min = 0.5;             // 1: a face reading more has the sun itself on it
    double detect_irradiance_min = 0.5;              // 1: face tests while the other faces show this much sun
    double detect_bus_tolerance = 0.02;              // A: |i_sh[k] − (i_face[2k] − i_face[2k+1])|
    double detect_flip_min_field_calibrated = 3e-6;  // T: the same once the calibration's hard iron is in
    double detect_flip_min_field = 15e-6;            // T: flip test where the predicted field along the axis is this
    double detect_flip_fraction = 0.25;              // 1: an axis flipping by less than this fraction of it fails
    double detect_norm_tolerance = 12e-6;            // T: | |B| − |B_ref| |
    // Panel faults: the ratio test for faces low in the sun (once the calibration applies).
    double detect_face_ratio_min_response = 0.1;  // 1: tested where irradiance × predicted response is this
    double detect_face_ratio = 0.3;               // 1: a face reading below this fraction of it fails
    double detect_face_scale_min = 0.2;           // 1: a deficit reading at least this fraction is a lower scale
    double detect_face_dark_max = 0.03;           // 1: most a face may read in the predicted umbra
    double detect_face_stuck_change = 0.15;  // 1: a reading that does not move while the prediction spans this fails
    double detect_face_stuck_tolerance = 0.003;            // 1: ... "does not move": within this of where it started
    Faces fault_face_scale{1.0, 1.0, 1.0, 1.0, 1.0, 1.0};  // 1: a kFaultFaceScale face's scale (1: none)
    std::array<std::int32_t, 6> fault_face{};              // declared faults per face (kFaultFace* bits), 0: healthy
    Faces fault_face_time{-1.0, -1.0, -1.0, -1.0, -1.0, -1.0};  // s, when declared (−1: never)
    std::array<std::int32_t, 3> fault_mag_axis{};               // per magnetometer axis (kFaultAxis* bits)
    Vec3d fault_mag_axis_time{-1.0, -1.0, -1.0};
    std::int32_t fault_mag_norm = 0;  // 1: the field-norm test confirmed a fault (names no axis)
    double fault_mag_norm_time = -1.0;
    // The magnetometer's further tests and recovery (fault_detection.hpp, docs/faults.md "Magnetometer").
    double detect_frozen_min_field = 1e-6;     // T: frozen test where the predicted field along the axis is this
    double detect_frozen_tolerance = 0.02e-6;  // T: an axis flipping by less than this fails it
    double detect_spike_sigma = 0.5e-6;        // T: a healthy axis' spread about the prediction (besides attitude)
    double detect_spike_gate = 6.0;            // 1: an outlier is this many of its σ from the prediction
    double detect_spike_window = 60.0;         // s: spikes are counted over windows this long
    std::int32_t detect_spike_count = 5;       // spikes in one window that declare the axis spiking
    double detect_bias_window = 60.0;          // s: the bias-jump test's averaging time
    double detect_bias_threshold = 1e-6;       // T: an axis' mean innovation beyond this fails it
    double detect_bias_noise_factor = 1.0;     // 1: the filter's field noise factor while the offset re-learns
    std::array<std::int32_t, 3> fault_mag_spikes{};  // spikes skipped so far per axis
    Vec3d fault_mag_bias{};                          // T: the mean innovation per axis
    double fault_mag_strap_cleared_time = -1.0;      // s: a failed strap seen working again (−1: never)

    // discrete state
    double t_start = 0.0;  // s, the start time: sample k is due at t_start + k·sample_period
    // Index k of the next sample. 64 bits (not an FMI Integer, so not declared): never overflows, and
    // t_start + k·sample_period is computed from it afresh each time, so sample instants never drift.
    std::int64_t next_index = 0;
    std::array<Vec3d, kMaxSpinWindow> sun_history{};  // ring of sun_meas for the FFT
    std::int32_t history_head = 0;                    // next write position
    std::int32_t history_filled = 0;                  // consecutive valid samples in the ring (≤ spin_window)
    OnboardState<double> onboard{};                   // the computer's memory (onboard_computer.hpp), double
    OnboardState<float> onboard_float{};              // the same in float (precision = float)
};

// The on-board computer's settings from the block's parameters, in T (float: each value rounded once).
template <class T>
OnboardSettings<T> onboard_settings_from(const EstimatorData& d);
// The inputs of a sample, in T.
template <class T>
OnboardInputs<T> onboard_inputs_from(const EstimatorData& d);
// The computer's own element set: the given one (parsed_elements, else tle_elements; orbit's
// tle_from_elements) made uplink_age older (orbit::older_set).
orbit::Tle onboard_element_set(const EstimatorData& d) noexcept;

// The ground calibration's offset the computer starts from (MagCalibrationConfig::prior_offset, T, body axes):
// the field of the scenario's residual dipole (mag_prior_dipole at mag_prior_dipole_position) at the sensor
// (mag_prior_sensor_position), plus the named error mag_prior_offset_error.
Vec3<double> ground_calibration_offset(const EstimatorData& d) noexcept;
// Face k's string loop (0: +x … 5: −z) as the parameters give it (mag_string_loop_*).
StringLoop string_loop(const EstimatorData& d, std::size_t face) noexcept;
// The field per ampere of each face's string at the sensor the computer is given (OnboardSettings::
// string_field_per_amp, T/A, body axes): the loop's field at mag_prior_sensor_position times (1 +
// mag_string_field_error); all zero without mag_string_field.
std::array<Vec3<double>, kStringFaces> string_field_per_ampere(const EstimatorData& d) noexcept;
// The computer's clock at t = 0: clock_epoch_* plus clock_offset.
CalendarInstant onboard_clock_epoch(const EstimatorData& d) noexcept;
// The fault detection's settings from the parameters (fault_data.cpp) and its outputs back.
template <class T>
FaultDetectionConfig<T> fault_settings_from(const EstimatorData& d);
template <class T>
void store_fault_outputs(EstimatorData& d, const OnboardOutputs<T>& out);
// A sample's outputs into the block's output variables (double).
template <class T>
void store_outputs(EstimatorData& d, const OnboardOutputs<T>& out);

extern template OnboardSettings<float> onboard_settings_from(const EstimatorData&);
extern template OnboardSettings<double> onboard_settings_from(const EstimatorData&);
extern template OnboardInputs<float> onboard_inputs_from(const EstimatorData&);
extern template OnboardInputs<double> onboard_inputs_from(const EstimatorData&);
extern template void store_outputs(EstimatorData&, const OnboardOutputs<float>&);
extern template void store_outputs(EstimatorData&, const OnboardOutputs<double>&);

}  // namespace attitude_estimator
