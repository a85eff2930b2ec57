#include "attitude_estimator/onboard_computer.hpp"

#include "attitude_estimator/attitude_matrix.hpp"
#include "attitude_estimator/vec3_math.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ground/atmosphere_table.hpp"

namespace attitude_estimator {

namespace {

// A face's current is used for the panel-scale update only well inside the response curve (below about
// 45 deg of incidence with the Kelly law), where a small attitude error changes it little and albedo is a
// small part of it.
template <class T>
constexpr T kScaleFaceMinResponse = T(0.7);

template <class T>
EstimatorConfig<T> at_sun_distance(EstimatorConfig<T> c, T sun_distance) {
    // The panels' currents scale with the irradiance, (1 AU / distance)² of the 1 AU normalization
    // (±3.4 % over a year): the cones method's albedo fit needs the absolute scale.
    const T au_ratio = T(kAstronomicalUnit) / sun_distance;
    const T scale = au_ratio * au_ratio;
    for (auto& v : c.i_sc_norm) v *= scale;
    for (auto& v : c.sun.i_face_norm) v *= scale;
    return c;
}

// Element (i, j) of the filter's attitude covariance P_θθ, read in place.
template <class T>
T attitude_p(const MekfState<T>& m, std::size_t i, std::size_t j) {
    return m.p[kMekfStates * (kMekfAttitude + i) + kMekfAttitude + j];
}

// The lower Cholesky factor of the attitude's covariance as the filter reports it (mekf_attitude_covariance: P_θθ
// and the reference's tilt; zeros where a pivot is not positive).
template <class T>
Matrix3RowMajor<T> attitude_covariance_sqrt(const Matrix3RowMajor<T>& p) {
    Matrix3RowMajor<T> l{};
    for (std::size_t j = 0; j < 3; ++j) {
        T d = p[3 * j + j];
        for (std::size_t k = 0; k < j; ++k) d -= l[3 * j + k] * l[3 * j + k];
        if (!(d > T(0))) return Matrix3RowMajor<T>{};
        l[3 * j + j] = std::sqrt(d);
        for (std::size_t i = j + 1; i < 3; ++i) {
            T s = p[3 * i + j];
            for (std::size_t k = 0; k < j; ++k) s -= l[3 * i + k] * l[3 * j + k];
            l[3 * i + j] = s / l[3 * j + j];
        }
    }
    return l;
}

// While the calibration re-learns its offset after a bias jump, the field's noise in the filter is raised
// by settings.faults.bias_noise_factor (what is left of the jump is a bias the white noise does not cover).
//
// The filter's offset state cannot take what is left of the jump as it stands once the calibration applies:
// it is then the sensor's offset left by the set/reset estimate, whose sign follows the polarity (flipped
// every sample in leo_orbit), while the jump is a field at the sensor, fixed in body axes (it flips with the
// earth's field, magnetometer/README.md). Re-opening its covariance would let it chase a constant with an
// alternating sign. So while the calibration re-learns, the filter takes the field as not calibrated
// (bias_recovering_uncalibrated) and its offset state holds a body-fixed field (MekfConfig::
// mag_hard_iron_sigma: the mode it has before the calibration first applies), restarted from zero with the
// size of the jump seen as its 1σ per axis: the residual of the calibration's offset is estimated with the
// attitude, the sun keeps the attitude, and the covariance carries what is not known of it. When the
// re-learnt offset applies the filter takes the calibrated field again (its offset state restarts then).
template <class T>
bool bias_recovering_uncalibrated(const OnboardState<T>& s, const OnboardSettings<T>& settings) {
    return settings.faults.enabled && s.faults.bias_recovering;
}

// Before the in-flight calibration applies, a ground calibration (MagCalibrationConfig::prior_offset) already
// takes the spacecraft's own field out of the reading from the first sample: what is left of it is the
// ground calibration's residual, fixed in body axes like the hard iron the offset state holds until the
// calibration applies, with the ground calibration's 1σ as that state's prior. The field is then weighed as
// a calibrated one (its noise the currents' field and the model's, not the hard iron's several µT), so that
// the field and the sun carry the attitude from the start (docs/filter.md, "The ground calibration").
template <class T>
bool ground_calibration_applies(const OnboardState<T>& s, const OnboardSettings<T>& settings) {
    return settings.mag_calibration && mag_calibration_prior_applies(s.mag_cal, settings.mag_cal);
}

// The prior of the body-fixed field the filter's offset state holds while it takes the field uncalibrated
// (MekfConfig::mag_hard_iron_sigma): the ground calibration's 1σ while it applies, the jump's size while the
// calibration re-learns its offset after one, the configured one otherwise.
template <class T>
T hard_iron_sigma(const OnboardState<T>& s, const OnboardSettings<T>& settings) {
    T sigma = settings.mekf.mag_hard_iron_sigma;
    if (ground_calibration_applies(s, settings)) sigma = settings.mag_cal.prior_offset_sigma;
    if (bias_recovering_uncalibrated(s, settings)) {
        const T jump = std::sqrt(squared_norm(s.faults.bias_jump));
        if (jump > T(0)) sigma = jump;
    }
    return sigma;
}

template <class T>
MekfConfig<T> field_recovery_config(const OnboardState<T>& s, const OnboardSettings<T>& settings) {
    MekfConfig<T> c = settings.mekf;
    c.mag_hard_iron_sigma = hard_iron_sigma(s, settings);
    if (ground_calibration_applies(s, settings)) {
        if (c.mag_sigma_calibrated > T(0)) c.mag_sigma = c.mag_sigma_calibrated;
        if (settings.mag_cal.prior_field_sigma > T(0)) c.mag_sigma = settings.mag_cal.prior_field_sigma;
        c.mag_turn_fluctuation = settings.mag_cal.prior_field_fluctuation;
        c.mag_turn_correlation = settings.mag_cal.prior_field_correlation;
    }
    if (bias_recovering_uncalibrated(s, settings)) {
        c.mag_sigma *= settings.faults.bias_noise_factor;
        c.mag_sigma_calibrated *= settings.faults.bias_noise_factor;
        c.mag_sigma_calibrated_eclipse *= settings.faults.bias_noise_factor;
        // The field still comes through the calibration's scale and non-orthogonality (kept by the reopening):
        // its noise is the calibrated one, the offset's residual being the state's (leo_orbit: 9.5 µT, not the
        // uncalibrated 100 µT that would leave the attitude to the sun alone).
        if (c.mag_sigma_calibrated > T(0)) c.mag_sigma = c.mag_sigma_calibrated;
    }
    return c;
}

// Whether the filter's offset state holds a field fixed in body axes (mekf.cpp, holds_hard_iron): it took its
// last field uncalibrated in flight, with a hard-iron prior configured.
template <class T>
bool holds_body_fixed_field(const OnboardState<T>& s, const OnboardSettings<T>& settings) {
    return settings.filter == FilterKind::mekf && s.filter.stage == 2 && settings.mekf.estimate_offset &&
           s.filter.mag_calibrated == 0 && hard_iron_sigma(s, settings) > T(0);
}

template <class T>
void update_filter(OnboardState<T>& s, const OnboardInputs<T>& in, const OnboardSettings<T>& settings, T t,
                   const SampleResult<T>& r, const EstimatorConfig<T>& nominal, T polarity, bool mag_valid,
                   std::uint8_t mag_axes, T mag_unknown_sigma, OnboardOutputs<T>& out) {
    MekfSampleInputs<T> f;
    f.mag_unknown_sigma = mag_unknown_sigma;
    f.t = t;
    f.attitude_valid = r.valid;
    f.q_single = r.q;
    f.sun_weight = nominal.sun_weight;
    f.mag_weight = nominal.mag_weight;
    f.sun_valid = r.sun_valid;
    f.sun_ref = in.sun_ref;
    f.sun_body = r.sun_meas;
    f.mag_valid = mag_valid;
    f.mag_axes = mag_axes;
    f.mag_ref = in.mag_ref;
    // The field comes with the set/reset offset estimate taken out, B + p (v_os − applied)/S: the filter's
    // offset state is what is left of the offset, with the sign of this reading's polarity.
    f.mag_body = r.mag_field;
    f.polarity = polarity;
    // The on-board orbit's position (km, TEME; zero when the references are inputs) for the gravity gradient:
    // TEME and J2000 differ by the precession since 2000 (0.3°), nothing to a torque.
    for (std::size_t k = 0; k < 3; ++k) f.position[k] = T(1000) * out.references.position[k];
    // The drag's surroundings from the same orbit: its wind, and the density the table (a constant the computer
    // carries: mean solar activity) gives at its altitude; the filter scales it by its belief of the activity.
    if (out.references.valid && squared_norm(out.references.air_velocity) > T(0)) {
        f.air_velocity = out.references.air_velocity;
        f.air_density = ground::atmosphere::density(out.references.altitude);
    }
    f.mag_calibrated = settings.mag_calibration && s.mag_cal.valid && !bias_recovering_uncalibrated(s, settings);
    if (settings.filter_scale && nominal.sun.method != SunMethod::difference) {
        // Relative responses against the nominal normalization: the filter's model is (1 + ε) R(cos β).
        for (std::size_t k = 0; k < 6; ++k) {
            const T i = convert(nominal.face_adc[k], in.i_face[k]).value;
            f.face_r[k] = i / nominal.sun.i_face_norm[k];
            // The cones fit's albedo is relative to the normalization the sun method used, (1 + ε̂) × nominal.
            f.face_albedo[k] = r.face_albedo[k];
            const bool usable =
                (r.lit_faces >> k & 1) && !(r.rejected_faces >> k & 1) && f.face_r[k] >= kScaleFaceMinResponse<T>;
            if (usable) f.face_use |= static_cast<std::uint8_t>(1u << k);
        }
        f.response = &nominal.sun.response;
    }
    const MekfSampleResult<T> result = mekf_sample(s.filter, f, field_recovery_config(s, settings));
    const MekfState<T>& m = s.filter;
    const bool running = m.stage == 2;
    out.q_filt = running ? m.q : Quaternion<T>{};
    out.omega_filt = running ? m.omega : Vec3<T>{};
    for (std::size_t k = 0; k < 3; ++k) out.mag_offset_filt[k] = m.mag_offset[k] * settings.estimator.mag_sensitivity;
    out.panel_scale_filt = m.panel_scale;
    out.attitude_bound = running ? result.bound : T(0);
    if (running) out.attitude_cov_sqrt = attitude_covariance_sqrt(mekf_attitude_covariance(m, settings.mekf));
    out.filter_valid = running && result.valid;
    out.filter_resets = m.resets;
}

// A bias jump pulls the filter's attitude from its onset until the bias test declares it (the innovation is
// read as an attitude error: 1.3 deg in leo_orbit for 11 µT), and the filter, converged, believes the pulled
// attitude (its covariance a few hundredths of a degree): the sun brings it back only over many minutes. The
// bias test declares at most bias_window/2 after the onset in leo_orbit's campaign (5–22 s, 20 runs), so
// a copy of the filter kept 30 to 60 s old is from before the jump. At the first declaration of a jump it
// replaces the filter, propagated to now by the filter's own model (at most 1 s a step), its covariance
// grown by the process noise over that time: no measurement since the copy, none of the jump's.
template <class T>
constexpr T kFilterHoldInterval = T(30);  // s: the held copy is 30 to 60 s old

template <class T>
void hold_filter(OnboardState<T>& s, T t) {
    if (s.filter.stage != 2 || (s.filter_pending.stage == 2 && t - s.filter_checkpoint_t < kFilterHoldInterval<T>))
        return;
    s.filter_held = s.filter_pending;
    s.filter_pending = s.filter;
    s.filter_checkpoint_t = t;
}

template <class T>
bool rewind_filter(OnboardState<T>& s, const OnboardSettings<T>& settings, T t) {
    const MekfState<T>& held = s.filter_held;
    if (held.stage != 2 || !(held.t_last < t) || t - held.t_last > T(3) * kFilterHoldInterval<T>) return false;
    const std::int32_t resets = s.filter.resets;
    s.filter = held;
    s.filter.resets = resets;
    s.filter.refused_in_row = 0;
    while (s.filter.t_last < t) mekf_propagate(s.filter, std::min(T(1), t - s.filter.t_last), settings.mekf);
    // Both copies are from before the jump or are now outdated by the rewind: they start over.
    s.filter_pending.stage = 0;
    s.filter_held.stage = 0;
    return true;
}

// The calibration's equations between a bias jump's onset and its declaration (5–22 s in leo_orbit's
// campaign) were taken with the jump in the reading and the old offset in the model: a few equations whose
// residuals are a thousand times their σ (2 Hᵀ J against 2 σ |H|). Reopening the offset marginalizes c and
// μ but keeps what those equations say about the scale and non-orthogonality E, which they pull by per cents
// (a 44 µT jump left z's scale 1.9 % off after the re-learnt solution applied: 0.4–0.9 µT of field error
// following the field, NEES/dof 10–18 in the eclipse). So the calibration is held as the filter is, a copy 30
// to 60 s old, and the reopening starts from it: the jump's equations go with the minute before it.
template <class T>
void hold_calibration(OnboardState<T>& s, T t) {
    if (s.mag_cal_copies > 0 && t - s.mag_cal_checkpoint_t < kFilterHoldInterval<T>) return;
    s.mag_cal_held = s.mag_cal_pending;
    s.mag_cal_pending = s.mag_cal;
    s.mag_cal_checkpoint_t = t;
    if (s.mag_cal_copies < 2) ++s.mag_cal_copies;
}

// The bias jump's reopening (mag_calibration_reopen_offset) from the held calibration when it is from before
// the jump and applies; the copies start over.
template <class T>
void reopen_calibration(OnboardState<T>& s, T t, const Vec3<T>& jump) {
    const bool held_usable =
        s.mag_cal_copies >= 2 && s.mag_cal_held.valid && t - s.mag_cal_checkpoint_t <= T(2) * kFilterHoldInterval<T>;
    if (held_usable) s.mag_cal = s.mag_cal_held;
    mag_calibration_reopen_offset(s.mag_cal, multiply(s.mag_cal.gain, jump));
    s.mag_cal_copies = 0;
}

template <class T>
void update_rates(OnboardState<T>& s, const OnboardSettings<T>& settings, T t, const SampleResult<T>& r,
                  OnboardOutputs<T>& out) {
    // Mean |ω| (004 eq. 4) from successive valid attitudes; invalid ones are skipped, and a gap longer than
    // the rate config's max_interval starts a new chain.
    if (r.valid) s.rate.push(t, r.q);
    const MeanRate<T> mean = s.rate.result();
    out.rate_mean = mean.rate;
    out.rate_window_time = mean.window_seconds;
    // Aliasing: an increment rate_interval long reads the turn modulo 2π (folded beyond π), so rate_mean
    // is not trusted when one increment may turn more than π/2 (margin for a rate that changes within
    // the window). Two witnesses: the filter's rate when it runs, and the turn between successive
    // single-frame estimates (averaged, α = 0.2) when it is clearly above their noise (0.1 rad per sample;
    // below that a fast rate cannot be told from noise by this test: use omega_filt).
    constexpr T kHalfPi = T(1.5707963267948966);
    constexpr T kStepNoise = T(0.1);  // rad per sample
    if (r.valid) {
        if (s.has_last && t - s.last_t <= T(1.5) * settings.sample_period) {
            const T dot = s.last_q.x * r.q.x + s.last_q.y * r.q.y + s.last_q.z * r.q.z + s.last_q.w * r.q.w;
            const T turn = T(2) * std::acos(std::min(T(1), std::abs(dot)));
            s.step_turn += T(0.2) * (turn - s.step_turn);
        }
        s.last_q = r.q;
        s.last_t = t;
        s.has_last = true;
    }
    const bool step_aliases =
        s.step_turn >= kStepNoise && s.step_turn / settings.sample_period * settings.rate_interval >= kHalfPi;
    const auto& f = s.filter;
    const T filter_rate = std::sqrt(f.omega[0] * f.omega[0] + f.omega[1] * f.omega[1] + f.omega[2] * f.omega[2]);
    const bool filter_aliases =
        settings.filter == FilterKind::mekf && f.stage == 2 && filter_rate * settings.rate_interval >= kHalfPi;
    out.rate_valid = mean.valid && !step_aliases && !filter_aliases;
}

// A body vector's uncertainty from the attitude's: δv = v × δθ, var_k = m_k P_θθ m_kᵀ with m_k the k-th row of
// [v×] (the propagation since the filter's last sample adds a negligible amount at 20 Hz); 1σ per component.
template <class T>
Vec3<T> attitude_sigma(const MekfState<T>& m, const Vec3<T>& v) {
    const Matrix3RowMajor<T> vx{T(0), -v[2], v[1], v[2], T(0), -v[0], -v[1], v[0], T(0)};
    Vec3<T> sigma{};
    for (std::size_t k = 0; k < 3; ++k) {
        T var = T(0);
        for (std::size_t i = 0; i < 3; ++i)
            for (std::size_t j = 0; j < 3; ++j) var += vx[3 * k + i] * vx[3 * k + j] * attitude_p(m, i, j);
        sigma[k] = std::sqrt(var > T(0) ? var : T(0));
    }
    return sigma;
}

// The filter's prediction for time t: its attitude propagated by its rate since its last sample
// (v_body(t) = exp(−[ω h×]) v_body(t_last)), applied to the sun and field references.
template <class T>
void predict(const MekfState<T>& m, const OnboardInputs<T>& in, T t, FaultObservation<T>& o) {
    const Matrix3RowMajor<T> a = attitude_matrix(m.q);
    Vec3<T> sun = multiply(a, in.sun_ref);
    Vec3<T> field = multiply(a, in.mag_ref);
    const Vec3<T> turn = scaled(m.omega, -(t - m.t_last));
    const T angle = std::sqrt(squared_norm(turn));
    if (angle > T(0)) {
        const Vec3<T> axis = scaled(turn, T(1) / angle);
        const T c = std::cos(angle), sn = std::sin(angle);
        const auto rotate = [&](const Vec3<T>& v) {
            const Vec3<T> kxv = cross(axis, v);
            const T kv = dot(axis, v);
            Vec3<T> w{};
            for (std::size_t i = 0; i < 3; ++i) w[i] = v[i] * c + kxv[i] * sn + axis[i] * kv * (T(1) - c);
            return w;
        };
        sun = rotate(sun);
        field = rotate(field);
    }
    const T sun_norm = std::sqrt(squared_norm(sun));
    o.sun_body = sun_norm > T(0) ? scaled(sun, T(1) / sun_norm) : Vec3<T>{};
    o.field_body = field;
    o.field_sigma = attitude_sigma(m, field);
    o.sun_sigma = attitude_sigma(m, o.sun_body);
    o.predicted = sun_norm > T(0);
}

// The filter's prediction of the field the sensor reads (before the calibration's correction) and of the
// sun, in o.field_body / o.sun_body (o.predicted false when the filter is not running).
template <class T>
void predict_at_sensor(const OnboardState<T>& s, const OnboardInputs<T>& in, const OnboardSettings<T>& settings, T t,
                       FaultObservation<T>& o) {
    if (settings.filter == FilterKind::mekf && s.filter.stage == 2) {
        predict(s.filter, in, t, o);
        // (field_recovery_config, the filter's configuration per sample, leaves valid_bound and reset_after.)
        o.prediction_valid = o.predicted && mekf_valid(s.filter, settings.mekf);
    }
    if (o.predicted && settings.mag_calibration && (s.mag_cal.valid || ground_calibration_applies(s, settings))) {
        // What the sensor sees is the calibration's model inverted: H = (I + D)⁻¹ (B + b), to first order in
        // the small D: (B + b) − D (B + b) (D is a few per cent at most: an error of its square).
        // While the filter's offset state holds a body-fixed field (the ground calibration's residual, or what
        // the calibration's offset still lacks after a bias jump), that field is part of the prediction: the
        // bias test then judges only what the filter does not explain. Without it, what the calibration's shift
        // left of a jump was declared again and again, each time shifting the offset on top of the filter's
        // own estimate of it and dropping the calibration's new equations (faults.toml's run 318: 12
        // declarations, no new solution in 4000 s, 19.5° in the eclipse; docs/faults.md).
        const Vec3<T> held = holds_body_fixed_field(s, settings) ? s.filter.mag_offset : Vec3<T>{};
        Vec3<T> v{};
        for (std::size_t k = 0; k < 3; ++k) v[k] = o.field_body[k] + s.mag_cal.offset[k] + held[k];
        const Vec3<T> gv = multiply(s.mag_cal.gain, v);
        for (std::size_t k = 0; k < 3; ++k) o.field_body[k] = T(2) * v[k] - gv[k];
        // The ground calibration's offset alone: the spacecraft's field is in the prediction (the flip and strap
        // tests' calibrated bar), its scale is not (the tests that need the in-flight calibration wait).
        o.field_calibrated = s.mag_cal.valid;
        o.field_offset_known = true;
    }
}

// The tests' view of this sample: the raw readings (before any exclusion), the filter's prediction.
template <class T>
FaultObservation<T> observe(const OnboardState<T>& s, const OnboardInputs<T>& in, const OnboardSettings<T>& settings,
                            const EstimatorConfig<T>& nominal, T t, T polarity, const SampleResult<T>& r,
                            std::uint8_t axes_out) {
    FaultObservation<T> o;
    o.t = t;
    o.sample_period = settings.sample_period;
    o.response = &nominal.sun.response;
    o.bus_available = true;
    for (std::size_t k = 0; k < 6; ++k) {
        o.i_face[k] = convert(nominal.face_adc[k], in.i_face[k]).value;
        o.face_r[k] = o.i_face[k] / nominal.sun.i_face_norm[k];
    }
    const T v_ref = convert(nominal.mag_ref_adc, in.v_mag_ref).value;
    for (std::size_t k = 0; k < 3; ++k) {
        o.i_sh[k] = convert(nominal.sun_adc[k], in.i_sh[k]).value;
        const AdcConfig<T>& adc = nominal.mag_adc[k];
        const T v = convert(adc, in.v_mag[k]).value;
        o.mag_reading[k] = v - v_ref;
        o.at_rail[k] = !(v > adc.min + nominal.mag_rail_margin && v < adc.max - nominal.mag_rail_margin);
        o.mag_reading_step[k] = adc_step(adc) + adc_step(nominal.mag_ref_adc);
    }
    o.polarity = polarity;
    o.commanded_polarity = s.set_reset.polarity;
    o.sensitivity = nominal.mag_sensitivity;
    o.field_usable = axes_out == 0 && r.mag_valid;
    o.field = r.mag_field;
    o.field_measured = r.mag_reading_usable;
    o.field_uncalibrated = r.mag_field_uncalibrated;
    o.field_ref_norm = std::sqrt(squared_norm(in.mag_ref));
    predict_at_sensor(s, in, settings, t, o);
    return o;
}

// Panel faults: a face declared reading a steady fraction of its light (kFaultFaceScale: a shadow over part of
// it, degraded cells) is read divided by that fraction, and so is its share of the per-axis Hall difference
// (i_sh[k] = i_face[2k] − i_face[2k+1]), so that every sun method keeps the face.
template <class T>
OnboardInputs<T> with_face_scales(const OnboardInputs<T>& in, const FaultDetectionState<T>& f) {
    OnboardInputs<T> c = in;
    for (std::size_t k = 0; k < 6; ++k) {
        // Only a face that is kept: an excluded one reads 0 (its light in i_sh drops the sun while it may be lit).
        if (f.face_word[k] != kFaultFaceScale || !(f.face_scale[k] > T(0))) continue;
        const T extra = in.i_face[k] * (T(1) / f.face_scale[k] - T(1));
        c.i_face[k] += extra;
        c.i_sh[k / 2] += k % 2 == 0 ? extra : -extra;
    }
    return c;
}

// Panel faults: the spacecraft counts as deep in the umbra 100 km inside the Earth's shadow cylinder, and near
// the shadow from 100 km outside it (the umbra cone narrows by ~30 km at LEO, the penumbra is as wide outside
// the cylinder; the rest for the atmosphere's dimming and the on-board orbit's error).
template <class T>
constexpr T kShadowMarginKm = T(100);

// The field of the panels' string currents at the sensor from the measured face currents (OnboardSettings::
// string_field_per_amp): Σ K_f i_f over the digitized currents as they are read, not rescaled for a declared
// partial shadow (the string carries what the cells give). A face excluded by the fault detection counts with
// `excluded_current` (excluded_face_currents) in place of its reading.
template <class T>
Vec3<T> string_field(const OnboardInputs<T>& in, const OnboardSettings<T>& settings, const EstimatorConfig<T>& nominal,
                     std::uint8_t faces_out, const std::array<T, 6>& excluded_current) {
    Vec3<T> b{};
    for (std::size_t k = 0; k < 6; ++k) {
        const T i = (faces_out >> k & 1u) ? excluded_current[k] : convert(nominal.face_adc[k], in.i_face[k]).value;
        if (!std::isfinite(i)) continue;
        for (std::size_t j = 0; j < 3; ++j) b[j] += settings.string_field_per_amp[k][j] * i;
    }
    return b;
}

// The current an excluded face's string carries, for its field at the sensor: the lesser of its reading and the
// direct sun the filter predicts on it (none in the umbra). Neither alone can be trusted: the reading is wrong for
// a Hall channel stuck or offset and for a switch stuck off (it reads 0 while the string feeds the bus), the
// prediction for an open string (it carries nothing) and a shadow (less). The lesser is right for an open string,
// a shadow and a channel reading above the light; below it (a switch stuck off, a channel stuck low) it leaves
// part out. Counted as 0, as before 2026-12-06 (third session), an appendage's shadow on +x left its string's
// field (a few 100 nT, following the sun on the face) in the field weighed at 1.5 µT: faults.toml's appendage
// runs 1.97 times the control's sunlit p95 (median; 13 of 20 above 1.5). Without a prediction (before the
// start, after a reset): 0. What the string carries is known only between the two: `unknown` is their difference
// (A), whose field the filter weighs as an error (string_field_unknown_sigma; docs/faults.md, "An excluded face's
// unknown string field").
template <class T>
struct ExcludedFaceCurrents {
    std::array<T, 6> current{};
    std::array<T, 6> unknown{};
};

template <class T>
ExcludedFaceCurrents<T> excluded_face_currents(const OnboardState<T>& s, const OnboardInputs<T>& in,
                                               const OnboardSettings<T>& settings, const EstimatorConfig<T>& nominal,
                                               T t, std::uint8_t faces_out, bool umbra) {
    ExcludedFaceCurrents<T> e;
    if (faces_out == 0) return e;
    FaultObservation<T> o;
    predict_at_sensor(s, in, settings, t, o);
    if (!o.predicted) return e;
    for (std::size_t k = 0; k < 6; ++k) {
        if (!(faces_out >> k & 1u)) continue;
        const T cos_beta = face_cos(o.sun_body, k);
        const T light =
            umbra ? T(0)
                  : nominal.sun.i_face_norm[k] * panel_response::response_from_cos(nominal.sun.response, cos_beta);
        const T read = convert(nominal.face_adc[k], in.i_face[k]).value;
        e.current[k] = std::isfinite(read) ? std::min(read, light) : T(0);
        e.unknown[k] = std::isfinite(read) ? std::abs(read - light) : light;
    }
    return e;
}

// The field of the excluded faces' strings left unknown (ExcludedFaceCurrents::unknown), as 1σ per axis for the
// filter: the strings' field Σ K_k u_k with the error anywhere between none and all of it, its mean square |v|²/3
// put on each axis.
template <class T>
T string_field_unknown_sigma(const OnboardSettings<T>& settings, const std::array<T, 6>& unknown) {
    if (unknown == std::array<T, 6>{}) return T(0);  // no face excluded: the usual sample pays nothing
    Vec3<T> v{};
    for (std::size_t k = 0; k < 6; ++k)
        for (std::size_t j = 0; j < 3; ++j) v[j] += settings.string_field_per_amp[k][j] * unknown[k];
    return std::sqrt(squared_norm(v) / T(3));
}

// An excluded axis is read at the filter's prediction of it when there is one, else at its null (so that its
// rail does not take the other two with it; its component is not used by the filter). The prediction, not
// the null, because the calibration's correction (I + D) H mixes the axes: with the null, the cross terms
// D_jk H_k (a few tenths of a per cent of tens of µT) would reach the other axes as an error as large as
// their noise, following the tumble; the prediction's error there is D_jk times |B| times the attitude error.
template <class T>
void stand_in_for_excluded_axes(const OnboardState<T>& s, const OnboardInputs<T>& in,
                                const OnboardSettings<T>& settings, T t, std::uint8_t axes_out, SampleInputs<T>& used) {
    FaultObservation<T> o;
    predict_at_sensor(s, in, settings, t, o);
    const T sensitivity = settings.estimator.mag_sensitivity;
    for (std::size_t k = 0; k < 3; ++k) {
        if (!(axes_out >> k & 1u)) continue;
        // The reading model: v − v_ref = p S H + v_os (field_vector.hpp), with the offset the sample applies; H
        // holds the strings' field the sample takes out again (the prediction is of the field without it).
        const T h = o.field_body[k] + used.mag_known_field[k];
        used.v_mag[k] =
            o.predicted ? in.v_mag_ref + used.mag_polarity * sensitivity * h + used.mag_offset[k] : in.v_mag_ref;
    }
}

// No attitude from this sample's single frame (a vector it needs is excluded).
template <class T>
void drop_single_frame(SampleResult<T>& r) {
    r.valid = false;
    r.q = Quaternion<T>{};
    r.a = Matrix3RowMajor<T>{1, 0, 0, 0, 1, 0, 0, 0, 1};
    r.loss = T(0);
}

// A spike on an axis (fault_detection.hpp): this sample's field is used nowhere, neither by the single frame
// nor the filter (nor, in onboard_sample, by the calibration and the set/reset offset mean).
template <class T>
void skip_spiking_field(SampleResult<T>& r, bool& filter_mag_valid) {
    r.mag_valid = false;
    r.mag_meas = Vec3<T>{};
    if (r.valid) drop_single_frame(r);
    filter_mag_valid = false;
}

// The sample's inputs with the reference vectors the settings choose: the inputs' own, or the on-board
// models' at time t (an element set SGP4 cannot propagate leaves the field zero: no field observation).
template <class T>
OnboardInputs<T> with_references(OnboardState<T>& s, const OnboardInputs<T>& given, const OnboardSettings<T>& settings,
                                 T t, References<T>& used) {
    if (settings.reference_source == ReferenceSource::inputs) {
        used = References<T>{.sun = given.sun_ref,
                             .sun_distance = given.sun_distance,
                             .field = given.mag_ref,
                             .position = {},
                             .valid = true};
        return given;
    }
    used = onboard_references(s.references, settings.references, t);
    OnboardInputs<T> in = given;
    in.sun_ref = used.sun;
    in.sun_distance = used.sun_distance;
    in.mag_ref = used.valid ? used.field : Vec3<T>{};
    return in;
}

}  // namespace

template <class T>
void onboard_start(OnboardState<T>& state, const OnboardSettings<T>& settings) noexcept {
    state = OnboardState<T>{};
    if (settings.mag_calibration) mag_calibration_start(state.mag_cal, settings.mag_cal);
    state.rate = MeanAngularRate<T>(settings.rate);
    state.set_reset.since_pulse = -1;  // no pulse at the first sample
}

template <class T>
OnboardOutputs<T> onboard_sample(OnboardState<T>& s, const OnboardInputs<T>& given, const OnboardSettings<T>& settings,
                                 T t) noexcept {
    OnboardOutputs<T> out;
    const OnboardInputs<T> in = with_references(s, given, settings, t, out.references);
    const EstimatorConfig<T> nominal = at_sun_distance(settings.estimator, in.sun_distance);
    EstimatorConfig<T> config = nominal;
    if (settings.filter == FilterKind::mekf && settings.filter_scale && s.filter.stage == 2) {
        // The filter's panel-scale estimate corrects the normalization the sun method divides by.
        const T gain = T(1) + s.filter.panel_scale;
        for (auto& v : config.sun.i_face_norm) v *= gain;
        for (auto& v : config.i_sc_norm) v *= gain;
    }
    // The reading now at the inputs was taken in the polarity commanded at the previous sample; once the
    // strap is declared failed, in the polarity the film stayed in, with the offset from before the failure.
    const bool detecting = settings.faults.enabled;
    const OnboardInputs<T> scaled_in = detecting ? with_face_scales(in, s.faults) : in;
    const bool strap_failed = detecting && s.faults.strap_failed;
    const T reading_polarity = strap_failed ? s.faults.strap_polarity : s.set_reset.polarity;
    const Vec3<T> offset = strap_failed ? s.faults.strap_offset : applied_offset(s.set_reset, settings.set_reset);
    const std::uint8_t faces_out = detecting ? excluded_faces(s.faults) : std::uint8_t{0};
    // Panel faults: the umbra 100 km inside the Earth's shadow cylinder by the on-board orbit (kShadowMarginKm).
    const T shadow_depth = shadow_depth_km(out.references.position, in.sun_ref);
    const bool umbra = shadow_depth > kShadowMarginKm<T>;
    const ExcludedFaceCurrents<T> excluded = excluded_face_currents(s, in, settings, nominal, t, faces_out, umbra);
    const SampleInputs<T> sample_in{
        .i_sh = scaled_in.i_sh,
        .i_face = scaled_in.i_face,
        .v_mag = in.v_mag,
        .v_mag_ref = in.v_mag_ref,
        .sun_ref = in.sun_ref,
        .mag_ref = in.mag_ref,
        .mag_polarity = reading_polarity,
        .mag_offset = offset,
        .mag_gain = s.mag_cal.gain,
        .mag_cal_offset = s.mag_cal.offset,
        .mag_known_field = string_field(in, settings, nominal, faces_out, excluded.current)};
    // Excluded faces read nothing; an excluded axis reads its null, so that its rail does not take the
    // other two with it (its component is not used below).
    const std::uint8_t axes_out = detecting ? excluded_axes(s.faults) : std::uint8_t{0};
    SampleInputs<T> used_in = sample_in;
    for (std::size_t k = 0; k < 6; ++k)
        if (faces_out >> k & 1u) used_in.i_face[k] = T(0);
    // The per-axis current of an axis with an excluded face, formed from its two faces as used (the excluded one
    // at 0): the panels form i_sh from the face channels (ssr_plant: i_sh[k] = i_face[2k] − i_face[2k+1]), so a
    // faulty channel (a Hall channel stuck or offset) is in it too. Where the excluded face is dark, as the sun is
    // used only then (below), that is the axis' current. Kept as read, a Hall channel stuck at 0.64 A left the
    // difference method's sun 42-49 deg off whenever the face was dark (faults.toml's run 105).
    for (std::size_t axis = 0; axis < 3; ++axis)
        if (faces_out >> (2 * axis) & 3u) used_in.i_sh[axis] = used_in.i_face[2 * axis] - used_in.i_face[2 * axis + 1];
    if (axes_out != 0) stand_in_for_excluded_axes(s, in, settings, t, axes_out, used_in);
    out.sample = estimate_sample(used_in, config, s.sun);
    bool filter_mag_valid = out.sample.mag_valid;
    if (detecting) {
        FaultObservation<T> o = observe(s, in, settings, nominal, t, reading_polarity, out.sample, axes_out);
        o.mag_offset = offset;
        o.umbra = umbra;
        o.near_shadow = shadow_depth > -kShadowMarginKm<T>;
        // A position only from the computer's own orbit (zero when the references are inputs).
        o.clear_of_shadow = out.references.valid && squared_norm(out.references.position) > T(0) && !o.near_shadow;
        const bool was_recovering = s.faults.bias_recovering;
        fault_detect(s.faults, o, settings.faults);
        if (s.faults.bias_jump_now && !was_recovering && settings.filter == FilterKind::mekf &&
            rewind_filter(s, settings, t)) {
            // The jump was seen against the pulled attitude's prediction, which had taken up part of it (the
            // part across the field): against the rewound one, the jump is what was seen plus that part.
            FaultObservation<T> rewound;
            predict_at_sensor(s, in, settings, t, rewound);
            if (o.predicted && rewound.predicted)
                for (std::size_t k = 0; k < 3; ++k) s.faults.bias_jump[k] += o.field_body[k] - rewound.field_body[k];
        }
        // An excluded face that may be lit (predicted within 3° of its horizon or facing the sun) leaves the sun
        // vector without its light: no sun this sample. Dark, it changes nothing. Without a prediction (before the
        // start, after a reset) it is dark where its opposite face, kept, has the sun itself on it: otherwise a
        // reset after an exclusion would leave no sun to restart from, ever.
        bool face_may_be_lit = false;
        for (std::size_t k = 0; k < 6; ++k) {
            if (!(faces_out >> k & 1u)) continue;
            const std::size_t opposite = k ^ 1u;
            // The opposite face's current as digitized, its declared scale taken out (with_face_scales).
            const T opposite_current = convert(nominal.face_adc[opposite], sample_in.i_face[opposite]).value;
            const bool opposite_direct =
                !(faces_out >> opposite & 1u) &&
                opposite_current > settings.faults.face_direct_min * nominal.sun.i_face_norm[opposite];
            const T toward = face_cos(o.sun_body, k);
            if (o.predicted ? toward > T(-0.05) : !opposite_direct) face_may_be_lit = true;
        }
        if (face_may_be_lit && out.sample.sun_valid) {
            out.sample.sun_valid = false;
            out.sample.sun_meas = Vec3<T>{};
            drop_single_frame(out.sample);
        }
        // With an axis excluded the field is incomplete: no single-frame attitude; the filter takes the
        // axes left.
        if (axes_out != 0 && out.sample.mag_valid) {
            out.sample.mag_valid = false;
            out.sample.mag_meas = Vec3<T>{};
            drop_single_frame(out.sample);
        }
        if (axes_out == 7) filter_mag_valid = false;
        if (s.faults.spike_now != 0) skip_spiking_field(out.sample, filter_mag_valid);
    }
    const FaultDetectionState<T>& fd = s.faults;
    out.fault_face = fd.face_word;
    out.fault_face_time = fd.face_time;
    out.fault_mag_axis = fd.axis_word;
    out.fault_mag_axis_time = fd.axis_time;
    out.fault_mag_norm = fd.norm_word;
    out.fault_mag_norm_time = fd.norm_time;
    out.fault_face_scale = fd.face_scale;
    out.fault_mag_spikes = fd.spikes;
    out.fault_mag_bias = fd.bias_mean;
    out.fault_mag_strap_cleared_time = fd.strap_cleared_time;
    const bool spike = detecting && fd.spike_now != 0;
    if (detecting && fd.bias_jump_now && settings.mag_calibration && s.mag_cal.valid) {
        // A bias jump (fault_detection.hpp): the calibration's offset takes it at once, by (I + D) times the
        // jump seen before the correction, and re-learns it from the equations to come (those since the held
        // copy dropped: reopen_calibration).
        reopen_calibration(s, t, fd.bias_jump);
    }
    const Vec3<T> cal_offset_before = s.mag_cal.offset;
    if (settings.mag_calibration && out.sample.mag_reading_usable && axes_out == 0 && !spike) {
        // Against the reference field's magnitude only: no attitude needed (the next sample applies it).
        const T ref =
            std::sqrt(in.mag_ref[0] * in.mag_ref[0] + in.mag_ref[1] * in.mag_ref[1] + in.mag_ref[2] * in.mag_ref[2]);
        mag_calibration_offer(s.mag_cal, out.sample.mag_field_uncalibrated, ref, settings.mag_cal);
    }
    // The re-learnt offset is applied (a solve changed it): the recovery from a bias jump is over.
    if (detecting && s.faults.bias_recovering && !fd.bias_jump_now && s.mag_cal.offset != cal_offset_before)
        s.faults.bias_recovering = false;
    out.mag_cal_valid = s.mag_cal.valid;
    out.mag_cal_gain = s.mag_cal.gain;
    out.mag_cal_offset = s.mag_cal.offset;
    if (s.samples < std::numeric_limits<std::int32_t>::max()) ++s.samples;
    out.samples = s.samples;
    // The next reading is taken in the polarity commanded here.
    // (A failed strap's readings would pull the offset mean to S p B + v_os: they are not paired.)
    const bool strap_failed_now = detecting && s.faults.strap_failed;
    set_reset_after_sample(s.set_reset, out.sample.mag_reading,
                           out.sample.mag_reading_usable && !strap_failed_now && !spike, settings.set_reset);
    out.mag_set_reset = s.set_reset.polarity > T(0);
    out.mag_offset = strap_failed_now ? s.faults.strap_offset : applied_offset(s.set_reset, settings.set_reset);
    update_rates(s, settings, t, out.sample, out);
    if (settings.filter == FilterKind::mekf)
        update_filter(s, scaled_in, settings, t, out.sample, nominal, reading_polarity, filter_mag_valid,
                      static_cast<std::uint8_t>(~axes_out & 7u), string_field_unknown_sigma(settings, excluded.unknown),
                      out);
    if (settings.filter == FilterKind::mekf && detecting) hold_filter(s, t);
    if (detecting && settings.mag_calibration) hold_calibration(s, t);
    return out;
}

template void onboard_start(OnboardState<float>&, const OnboardSettings<float>&) noexcept;
template void onboard_start(OnboardState<double>&, const OnboardSettings<double>&) noexcept;
template OnboardOutputs<float> onboard_sample(OnboardState<float>&, const OnboardInputs<float>&,
                                              const OnboardSettings<float>&, float) noexcept;
template OnboardOutputs<double> onboard_sample(OnboardState<double>&, const OnboardInputs<double>&,
                                               const OnboardSettings<double>&, double) noexcept;

}  // namespace attitude_estimator
