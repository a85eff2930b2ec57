// A recursive attitude estimator beside the single-frame Wahba solution: a multiplicative extended Kalman
// filter (MEKF; Lefferts, Markley and Shuster 1982) on the attitude quaternion with the body rate as a state
// — this satellite has no gyro — plus the magnetometer's bridge offset and a common scale error of the
// panels' current normalization. Plain structs, fixed sizes, no heap, no exceptions, float and double, like
// the rest of the core: MekfState is trivially copyable so that an FMU can keep it in its state bytes.
//
// Error state (10): δθ (attitude error, rad, A_true = (I − [δθ×]) Â), δω (rad/s, body), δb (magnetometer
// offset, T, body/sensor axes), δε (panel scale). The estimate lives in q, omega, mag_offset, panel_scale;
// only the error covariance P is 10 × 10. Equations and tuning: attitude_estimator/docs/filter.md.
#pragma once

#include <array>
#include <cstdint>

#include "attitude_estimator/drag_torque.hpp"
#include "attitude_estimator/types.hpp"
#include "panel_response/kelly.hpp"

namespace attitude_estimator {

inline constexpr int kMekfStates = 10;
// Index of each block in the error state (and in the rows/columns of P).
inline constexpr int kMekfAttitude = 0;
inline constexpr int kMekfRate = 3;
inline constexpr int kMekfOffset = 6;
inline constexpr int kMekfScale = 9;

template <class T>
struct MekfConfig {
    // --- process noise (spectral densities of white noises driving random walks)
    T attitude_noise = T(1e-6);  // rad/√s: unmodelled attitude motion beyond the rate state
    T rate_noise = T(2e-5);      // rad/s/√s: rate random walk (disturbance torques, inertia error)
    T offset_noise = T(1e-11);   // T/√s: magnetometer offset drift (temperature)
    T scale_noise = T(1e-6);     // 1/√s: panel scale drift (temperature, degradation)
    // --- measurement noise (1σ per axis; each includes the model error of its sensor chain)
    T sun_sigma = T(0.02);    // rad: sun unit vector
    T mag_sigma = T(0.3e-6);  // T: field vector (noise, quantization, field-model error)
    T face_sigma = T(0.01);   // relative response of one face (face update for the panel scale)
    // The sun vector's error is not white: a face geometry and an albedo pattern persist for minutes. An
    // error of 1σ sun_sigma correlated over sun_correlation_time (s) carries, over a time t ≫ that, the
    // information of t/(2 τ) independent vectors, so each update is weighted as one of σ² max(1, 2τ/Δt)
    // (Δt the time since the previous sun update). 0: white (each vector independent).
    T sun_correlation_time = T(0);
    // The sun's error as what it is on a tumbling box: the albedo on the faces and the faces' response errors
    // follow the faces as the body turns, so the error stays put for about one radian of the tumble: τ = 1/|ω̂|
    // (ω̂ the filter's rate), at most sun_correlation_time (a slow tumble: the orbit's own turn of the Earth's
    // direction sets it). Measured over ten robustness runs from 0.26 to 4.3 °/s: τ 0.2–2.3 × 1/|ω| per axis
    // (median 0.8; docs/filter.md, "The sun's correlation from the tumble"). false: τ = sun_correlation_time.
    bool sun_turn_correlation = false;
    // 1σ per axis of the reference field model (the on-board model against the real field), T: adds in
    // quadrature to mag_sigma.
    T mag_ref_sigma = T(0);
    // The reference field's error as what it is along an orbit (docs/filter.md, "The reference's error by the
    // orbit"): rms mag_ref_rms per axis (T), correlated over mag_ref_correlation (s; 0: not modelled). Weighted as
    // white noise of the same information, σ² 2τ/Δt, a correlated error is right only for a filter whose memory
    // is long against τ. For any memory T the error of an exponentially weighted average of a first-order
    // Gauss–Markov error is σ² τ/(T + τ), and white noise of variance R per Δt leaves R Δt/(2T); each field update
    // therefore weighs it as σ² (2τ/Δt) T/(T + τ), never below σ², T the filter's own memory (MekfState::memory).
    // With a short memory (a strong process noise) the white equivalent alone overstates the error the
    // estimate keeps, and the covariance turns cautious. Adds in quadrature to mag_ref_sigma.
    T mag_ref_rms = T(0);
    T mag_ref_correlation = T(0);
    // The reference's tilt (rad; reference_error.hpp): the on-board orbit lags the true one along the track (the
    // aged set misses the drag over its age), and the field the computer expects is the true pattern turned
    // about the orbit's normal, by about twice the lag's angle (a near-dipole field turns twice per orbit). The
    // same turn at every sample: a bias of the attitude about the normal that no memory averages (the filter
    // keeps the direction of a fast tumble's angular momentum for hours) and the sun (degrees) cannot tell. It is
    // considered, not estimated: the filter's weights and covariance are its own, what it reports and judges its
    // validity by (mekf_attitude_covariance, the bound) adds tilt² along the normal, from the on-board orbit
    // (MekfSampleInputs::position, air_velocity; isotropic, tilt²/3 per axis, while it has none; docs/filter.md,
    // "The reference's tilt"). 0: none.
    T mag_ref_tilt = T(0);
    // mag_sigma once the field comes calibrated in flight (MekfSampleInputs::mag_calibrated; 0: mag_sigma):
    // an uncalibrated HMC2003 carries its 0.3 % cross-axis coupling (0.1 µT), a calibrated one little more
    // than its 12-bit steps (0.12 µT / √12).
    T mag_sigma_calibrated = T(0);
    // mag_sigma_calibrated in a sample without a sun vector (eclipse: T; 0: mag_sigma_calibrated). In sunlight
    // the field carries the panels' and shunts' currents' field, correlated with the sun's geometry over the
    // tumble, which the calibration cannot take out; in eclipse those currents are zero. One σ for both leaves
    // the filter overconfident in sunlight and underconfident in eclipse (docs/filter.md, "Per phase").
    T mag_sigma_calibrated_eclipse = T(0);
    // The uncalibrated field's error as what it is before the in-flight calibration: the sensor's scale, coupling
    // and misalignment acting on a field that turns in body axes, 1σ mag_turn_fluctuation (T) per axis correlated
    // over about one radian of that turn, τ = 1/|ω̂| but at most mag_turn_correlation (s; the orbit's own turn of
    // the field sets it for a slow tumble). Weighed as the white noise of the same information, σ √(2τ/Δt), Δt
    // the sample's step (as the sun's correlated error). 0: mag_sigma as set. Only while !mag_calibrated.
    T mag_turn_fluctuation = T(0);
    T mag_turn_correlation = T(0);
    // The spacecraft's own field at the sensor before the in-flight calibration applies (the uplinked prior
    // of its hard iron, 1σ per axis, T; 0: not modelled). Fixed in body axes, it is no white noise: weighed
    // as one, thousands of readings pin the attitude to a field that is several µT off (NEES/dof 4 over the
    // first half hour of leo_orbit). With it, the offset state holds that body-fixed field (its sign no
    // longer follows the polarity) from this prior until the calibration applies, so that the filter
    // estimates it with the attitude and the covariance carries what is not yet known of it.
    T mag_hard_iron_sigma = T(0);
    // --- initial uncertainty (at the Q-method initialisation)
    T init_attitude_sigma = T(0.05);  // rad, per axis
    T init_rate_sigma = T(0.02);      // rad/s, per axis, after the two-sample rate
    T init_offset_sigma = T(3e-6);    // T, per axis
    T init_scale_sigma = T(0.05);     // 1
    // The rate the spacecraft can have at the start, 1σ per axis (rad/s; 0: none): its design's largest tumble
    // (after separation, before any detumbling). Two single-frame attitudes one sample apart give a rate whose
    // variance, 2 σ₀²/Δt², is (2.9°·√2/0.05 s)² = 1.4 rad/s per axis at 20 Hz: the filter would propagate that
    // into its attitude and hold its 3σ bound above 100° for seconds. With this prior the difference is fused
    // with the rate known beforehand (zero ± this), per axis, at the start (docs/filter.md, "The start's rate").
    T start_rate_sigma = T(0);
    // --- optional states (a state not estimated keeps its value and zero covariance)
    bool estimate_offset = true;
    bool estimate_scale = false;
    // --- rate propagation. Inertia (kg m², row-major, body axes): all zero = kinematic (the rate is a
    // random walk); otherwise Euler's equations J ω̇ = −ω × J ω + τ propagate the rate, τ the torques modelled
    // below (none: torque-free).
    std::array<T, 9> inertia{};
    // --- the disturbance torques the propagation models (with the inertia only; docs/filter.md, "Torques"):
    // the residual dipole's m × B, B the reference field turned into the body by the estimate, and the gravity
    // gradient 3μ/r⁵ r_b × J r_b, r_b the on-board orbit's position turned into the body. m is the spacecraft's
    // uplinked magnetic budget (body axes, A m²; zero: no magnetic torque); what the models leave (their
    // errors, drag, solar pressure) is rate_noise's.
    std::array<T, 3> dipole{};
    bool gravity_gradient = false;
    // The torques not modelled as white noise (N m √s: 1σ of the angular momentum they add over 1 s), turned
    // into rate noise through the inertia, Q_ωω += σ² h J⁻¹ J⁻ᵀ: an axis of small inertia (a 3U's long axis)
    // is pushed harder by the same torque. Adds to rate_noise; only with the inertia.
    T torque_noise = T(0);
    // The aerodynamic torque (docs/filter.md, "Drag"; drag_torque.hpp): the box as the computer knows it (zero:
    // not modelled) in the wind of its own orbit against the co-rotating air (MekfSampleInputs::air_velocity), at
    // the density its table gives at that orbit's altitude (air_density) times drag_density_scale, its belief of
    // the solar activity (1: the table's mean activity). Its derivative by the attitude error enters Φ_ωθ.
    DragGeometry<T> drag{};
    T drag_density_scale = T(1);
    // What the density's uncertainty leaves of the modelled torque (1σ, relative: the solar cycle moves the
    // thermosphere's density by a factor of several at 400 km, which a mean-activity table does not follow), as
    // white torque noise of the same information through the inertia: (σ |τ_drag|)² 2 τ_c per second, τ_c =
    // drag_correlation_time (s), the time over which that torque error stays put in body axes. 0: none.
    T drag_density_sigma = T(0);
    T drag_correlation_time = T(0);
    // --- innovation test and divergence reset
    T gate = T(16.27);       // chi² with 3 degrees of freedom at 0.999: a vector update beyond it is refused
    T face_gate = T(10.83);  // chi² with 1 degree of freedom at 0.999: a face update beyond it is refused
    int reset_after = 40;    // consecutive samples with every offered update refused → reset to the Q-method
    // The divergence watch (mekf.cpp, docs/filter.md "The watch"): the field's innovation before each update,
    // turned into inertial axes (where an attitude error of the filter stays put however the body tumbles) and
    // averaged over watch_time (s, exponential weights; 0: off), against the size that average has when the
    // filter is consistent: the measurement noise R as weighted (a correlated error weighted as white noise of
    // the same information averages down as that white noise would) and the filter's own attitude and offset
    // covariance. Its squared size per expected squared size above watch_gate means the filter is lost while
    // its innovation test still accepts everything (each field weighted as 10 µT white noise cannot refuse a
    // 4 µT error); it then resets to the single-frame attitude like a refused run of reset_after samples.
    T watch_time = T(0);
    T watch_gate = T(16);
    // A watch on the sun too (docs/filter.md, "The watch on the sun"): the sun's squared innovation over its size
    // for a consistent filter (the sun's own error at its correlated σ and the filter's covariance), averaged over
    // watch_time from each start until the filter has been valid for watch_time; above watch_gate the filter is
    // lost and resets. The field's watch cannot see an error about the field itself, and the sun, weighted as the
    // white noise of its correlated error (σ a few rad per sample at 20 Hz), is never refused by the innovation
    // test: a filter that has learnt a wrong rate about the field from its start keeps the field and turns away
    // from the sun (robustness seed 42's run 23: valid while 90-165 deg off, 3σ below 10 deg).
    bool watch_sun = false;
    // The attitude about the field held uncertain until the sun has seen it (docs/filter.md, "The axis about the
    // field"). Before the sun has fixed the turn about the field, only the field's own slow turn in inertial axes
    // could, and that needs the rate across it, which the filter learns from that same field: the pair (a turn e
    // about the field, a rate error e dB/dt across it) predicts the same field, and a filter linearized at its
    // estimate counts it as information (robustness runs with the sun within 25 deg of the field's line: valid
    // and 24-63 deg off for minutes). With this on, from the start the filter sums the sun's own information in
    // inertial axes, Σ (I - s sᵀ)/σ_s² (σ_s each update's as weighted, the start's sun_sigma: the single-frame
    // attitude's own), and holds its attitude variance about the field's direction at no less than the inverse of
    // that sum along it, until 3 σ of it is below valid_bound (then off until a reset).
    bool hold_field_axis = false;
    T valid_bound = T(0.17453293);  // rad: filter_valid while the 3σ attitude bound is below this (10°)
    // Two single-frame attitudes further apart than this cannot give the initial rate (it could alias).
    T max_init_gap = T(0.5);  // s
};

// One vector's divergence watch (MekfConfig::watch_time, mekf.cpp): exponentially weighted sums since the start
// of its innovation in inertial axes, of the weights, of the squared weights times R (per axis), and of the
// weights times the filter's own expected squared error of that vector.
template <class T>
struct MekfWatch {
    std::array<T, 3> sum{};
    T weight = T(0);
    T noise = T(0);
    T spread = T(0);
    T t = T(0);      // time of the last vector the watch took
    T ratio = T(0);  // the last statistic: squared average over its expected size (1: consistent)
};

// The sun's watch (MekfConfig::watch_sun, mekf.cpp): the exponentially weighted average since the start of the
// sun's squared innovation over its expected size, and how long the filter has been valid since the start.
template <class T>
struct MekfSunWatch {
    T ratio = T(0);      // the average (below 1: consistent), from 0 at the start
    T t = T(0);          // time of the last sun the watch took
    T valid_for = T(0);  // s valid since the start; the watch stops at watch_time
};

// Everything the filter remembers between samples (trivially copyable, no pointers).
template <class T>
struct MekfState {
    Quaternion<T> q{};                             // attitude estimate, scalar-last, A(q) maps inertial to body
    Vec3<T> omega{};                               // rad/s, body rate
    Vec3<T> mag_offset{};                          // T: after polarity p a reading is A B_ref + p·mag_offset
                                                   // (+ mag_offset, body-fixed, while the hard iron is held)
    T panel_scale = T(0);                          // ε: face currents are (1 + ε) × the nominal normalization
    std::array<T, kMekfStates * kMekfStates> p{};  // error covariance, row-major
    // 0: nothing yet; 1: one single-frame attitude held (q_first at t_first), waiting for a second one
    // to difference into the initial rate; 2: running.
    std::int32_t stage = 0;
    Quaternion<T> q_first{};
    T t_first = T(0);
    T t_last = T(0);                  // time of the last propagation
    std::int32_t refused_in_row = 0;  // consecutive samples whose every update was refused
    std::int32_t resets = 0;          // divergence resets so far
    T t_sun = T(0);                   // time of the last sun update (sun_correlation_time)
    std::int32_t has_sun = 0;         // 1 once a sun update was offered since the start
    std::int32_t mag_calibrated = 0;  // 1 when the last field offered came with the in-flight calibration
    // The torque models' surroundings, from the last sample (MekfSampleInputs::mag_ref, position): the
    // reference field (T) and the orbit position (m), inertial; zero: not known (that torque is left out).
    Vec3<T> torque_field{};
    Vec3<T> torque_position{};
    // The drag model's (MekfSampleInputs::air_velocity, air_density): the wind, inertial, m/s; the table's density.
    Vec3<T> torque_air_velocity{};
    T torque_air_density = T(0);
    // The divergence watch (MekfConfig::watch_time): the field's innovation in inertial axes (µT), and with
    // MekfConfig::watch_sun the sun's squared innovation over its expected size.
    MekfWatch<T> watch{};
    MekfSunWatch<T> sun_watch{};
    // MekfConfig::hold_field_axis: the sun's information since the start, inertial axes (rad⁻²; xx, xy, xz, yy, yz,
    // zz), summed until it has fixed the turn about the field; then field_axis_seen is 1 and the hold off until a
    // reset (the sum stops: it cannot grow over a mission).
    std::array<T, 6> sun_information{};
    std::int32_t field_axis_seen = 0;
    // s: the filter's memory, its attitude variance (tr P_θθ) over the rate the last propagation added to it
    // (what the process noise forgets per second); 0 while not known or not forgetting (MekfConfig::mag_ref_rms
    // then counts as white noise of the same information).
    T memory = T(0);
};

// The outcome of one measurement update.
template <class T>
struct MekfUpdate {
    bool accepted = false;
    T nis = T(0);  // normalized innovation squared νᵀ S⁻¹ ν
};

// Starts the filter at attitude q with rate omega, offsets and scale as given, covariance from config.
template <class T>
void mekf_start(MekfState<T>& s, const Quaternion<T>& q, const Vec3<T>& omega, T t,
                const MekfConfig<T>& config) noexcept;

// Propagates estimate and covariance by dt (s): q by the exact rotation of the rate over dt (kinematic) or
// by RK4 substeps of Euler's equations (inertia given); P by the transition matrix and the process noise.
template <class T>
void mekf_propagate(MekfState<T>& s, T dt, const MekfConfig<T>& config) noexcept;

// Sun update: sun_ref (inertial) and sun_body (measured), both unit vectors.
template <class T>
MekfUpdate<T> mekf_update_sun(MekfState<T>& s, const Vec3<T>& sun_ref, const Vec3<T>& sun_body,
                              const MekfConfig<T>& config) noexcept;

// Field update: field_ref (inertial, T) and field_body (measured, T); polarity p = ±1 is the sign the
// offset takes in this reading (the set/reset state the reading was taken in). Only the axes in `axes`
// (bit k = axis k) are used: an excluded axis (a declared fault, fault_detection.hpp) adds nothing.
template <class T>
MekfUpdate<T> mekf_update_field(MekfState<T>& s, const Vec3<T>& field_ref, const Vec3<T>& field_body, T polarity,
                                const MekfConfig<T>& config, std::uint8_t axes = 7) noexcept;

// Face update (the panel scale): relative responses r[k] = i_face[k] / i_face_norm[k] (nominal
// normalization) of the faces in `use` (bit k = face k), predicted as (1 + ε) (R(n_k · A sun_ref) + a_k)
// with a_k the Earth albedo on the face relative to full sun (the cones fit's; zero when unknown).
// Returns the number of faces accepted.
template <class T>
int mekf_update_faces(MekfState<T>& s, const Vec3<T>& sun_ref, const std::array<T, 6>& r,
                      const std::array<T, 6>& albedo, std::uint8_t use, const panel_response::Response<T>& response,
                      const MekfConfig<T>& config) noexcept;

// 3σ bound on the attitude error angle: 3 √(trace P_θθ) (rad). |δθ|² is a sum of the three variances'
// worth of χ²₁ terms, so this bound holds with probability ≥ 99.7 % whatever the covariance's shape.
template <class T>
T mekf_attitude_bound(const MekfState<T>& s) noexcept;
// The same with MekfConfig::mag_ref_tilt considered: 3 √(tr P_θθ + tilt²).
template <class T>
T mekf_attitude_bound(const MekfState<T>& s, const MekfConfig<T>& c) noexcept;
// The attitude's covariance as the filter reports it (rad², body axes): P_θθ and the considered tilt
// (MekfConfig::mag_ref_tilt).
template <class T>
Matrix3RowMajor<T> mekf_attitude_covariance(const MekfState<T>& s, const MekfConfig<T>& c) noexcept;

// The filter calls its attitude valid (MekfSampleResult::valid of its last sample): running, its 3σ bound below
// config.valid_bound, and no refused run of reset_after samples waiting for a single frame to restart from.
template <class T>
bool mekf_valid(const MekfState<T>& s, const MekfConfig<T>& config) noexcept;

// --- one whole sample, as the block runs it

template <class T>
struct MekfSampleInputs {
    T t = T(0);                   // s, sample time
    bool attitude_valid = false;  // the single-frame (Q-method) attitude of this sample
    Quaternion<T> q_single{};
    // The weights q_single was solved with (Wahba's a_1, a_2 for the sun and the field; any common scale): the
    // start covariance maps the field's offset through them into the start attitude (mekf.cpp).
    T sun_weight = T(0.5);
    T mag_weight = T(0.5);
    bool sun_valid = false;
    Vec3<T> sun_ref{};   // any length
    Vec3<T> sun_body{};  // unit
    bool mag_valid = false;
    Vec3<T> mag_ref{};            // T
    Vec3<T> mag_body{};           // T
    T polarity = T(1);            // set/reset sign of this field reading
    Vec3<T> position{};           // m, inertial: the on-board orbit (gravity gradient; zero: unknown)
    Vec3<T> air_velocity{};       // m/s, inertial: the on-board orbit's velocity against the air (drag; zero: unknown)
    T air_density = T(0);         // kg/m³: the on-board table's density at that orbit's altitude (drag; 0: unknown)
    bool mag_calibrated = false;  // mag_body comes through the in-flight calibration (mag_sigma_calibrated)
    std::uint8_t mag_axes = 7;    // the magnetometer axes to use (bit k = axis k; fault_detection.hpp)
    // T per axis: a part of the field known only within a range (an excluded face's string field, between its
    // reading and its predicted light: onboard_computer.cpp), correlated over a radian of the tumble (1/|ω̂|, at
    // most mag_ref_correlation) and weighed as the reference's error is, for the filter's memory. 0: none.
    T mag_unknown_sigma = T(0);
    // Face update (only with config.estimate_scale): relative responses and the faces to use.
    std::array<T, 6> face_r{};
    std::array<T, 6> face_albedo{};  // relative albedo on each face (cones' fit), taken out of face_r's model
    std::uint8_t face_use = 0;
    const panel_response::Response<T>* response = nullptr;
};

template <class T>
struct MekfSampleResult {
    bool valid = false;  // running and the 3σ bound below config.valid_bound
    bool reset = false;  // this sample reset the filter to the single-frame attitude
    bool lost = false;   // the reset came from the divergence watch (MekfConfig::watch_time)
    T bound = T(0);      // 3σ attitude bound (rad), 0 when not running
    MekfUpdate<T> sun{};
    MekfUpdate<T> mag{};
    int faces_accepted = 0;
};

// Initialise from the single-frame attitude (first valid sample: attitude; second within max_init_gap:
// rate by differencing), propagate to in.t, update with every valid measurement, and reset to the
// single-frame attitude after config.reset_after samples whose every update the innovation test refused.
template <class T>
MekfSampleResult<T> mekf_sample(MekfState<T>& s, const MekfSampleInputs<T>& in, const MekfConfig<T>& config) noexcept;

#define ATTITUDE_ESTIMATOR_MEKF_EXTERN(T)                                                                            \
    extern template void mekf_start(MekfState<T>&, const Quaternion<T>&, const Vec3<T>&, T,                          \
                                    const MekfConfig<T>&) noexcept;                                                  \
    extern template void mekf_propagate(MekfState<T>&, T, const MekfConfig<T>&) noexcept;                            \
    extern template MekfUpdate<T> mekf_update_sun(MekfState<T>&, const Vec3<T>&, const Vec3<T>&,                     \
                                                  const MekfConfig<T>&) noexcept;                                    \
    extern template MekfUpdate<T> mekf_update_field(MekfState<T>&, const Vec3<T>&, const Vec3<T>&, T,                \
                                                    const MekfConfig<T>&, std::uint8_t) noexcept;                    \
    extern template int mekf_update_faces(MekfState<T>&, const Vec3<T>&, const std::array<T, 6>&,                    \
                                          const std::array<T, 6>&, std::uint8_t, const panel_response::Response<T>&, \
                                          const MekfConfig<T>&) noexcept;                                            \
    extern template T mekf_attitude_bound(const MekfState<T>&) noexcept;                                             \
    extern template T mekf_attitude_bound(const MekfState<T>&, const MekfConfig<T>&) noexcept;                       \
    extern template Matrix3RowMajor<T> mekf_attitude_covariance(const MekfState<T>&, const MekfConfig<T>&) noexcept; \
    extern template bool mekf_valid(const MekfState<T>&, const MekfConfig<T>&) noexcept;                             \
    extern template MekfSampleResult<T> mekf_sample(MekfState<T>&, const MekfSampleInputs<T>&,                       \
                                                    const MekfConfig<T>&) noexcept;
ATTITUDE_ESTIMATOR_MEKF_EXTERN(float)
ATTITUDE_ESTIMATOR_MEKF_EXTERN(double)
#undef ATTITUDE_ESTIMATOR_MEKF_EXTERN

}  // namespace attitude_estimator
