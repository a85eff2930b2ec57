#include "attitude_estimator/estimator_data.hpp"

#include <algorithm>

#include "attitude_estimator/reference_error.hpp"
#include "orbit/element_age.hpp"

namespace attitude_estimator {

namespace {

constexpr double kEarthMeanRadius = 6371e3;  // m: the albedo model's sphere (the core's 570 km default uses it)

template <class T, std::size_t N>
std::array<T, N> to(const std::array<double, N>& a) {
    std::array<T, N> out{};
    for (std::size_t i = 0; i < N; ++i) out[i] = static_cast<T>(a[i]);
    return out;
}

template <std::size_t N, class T>
std::array<double, N> from(const std::array<T, N>& a) {
    std::array<double, N> out{};
    for (std::size_t i = 0; i < N; ++i) out[i] = static_cast<double>(a[i]);
    return out;
}

template <class T>
AdcConfig<T> adc(std::int32_t bits, double min, double max) {
    return AdcConfig<T>{static_cast<unsigned>(bits), static_cast<T>(min), static_cast<T>(max)};
}

template <class T>
panel_response::Response<T> response_from(const EstimatorData& d) {
    if (d.angular_response == AngularResponse::cosine) return panel_response::cosine<T>();
    std::array<panel_response::Knot<T>, 6> knots{};
    for (std::size_t i = 0; i < knots.size(); ++i)
        knots[i] = {static_cast<T>(d.kelly_angle[i]), static_cast<T>(d.kelly_value[i])};
    return panel_response::table<T>(knots);
}

}  // namespace

template <class T>
OnboardSettings<T> onboard_settings_from(const EstimatorData& d) {
    OnboardSettings<T> s;
    EstimatorConfig<T>& c = s.estimator;
    c.i_sc_norm = to<T>(d.i_sc_norm);  // at 1 AU; the sample scales them to its sun distance
    c.mag_sensitivity = static_cast<T>(d.mag_sensitivity);
    c.sun_weight = static_cast<T>(d.weight_sun);
    c.mag_weight = static_cast<T>(d.weight_mag);
    const auto current = adc<T>(d.adc_bits, d.i_adc_min, d.i_adc_max);
    const auto voltage = adc<T>(d.adc_bits, d.v_adc_min, d.v_adc_max);
    c.sun_adc = {current, current, current};
    c.mag_adc = {voltage, voltage, voltage};
    c.mag_ref_adc = voltage;  // the zero-field reference goes through a channel of the same kind
    c.solver = d.solver;
    c.min_sun_norm = static_cast<T>(d.min_sun_norm);
    c.mag_rail_margin = static_cast<T>(d.mag_rail_margin);
    c.min_field = static_cast<T>(d.min_field);
    c.min_separation_sin = static_cast<T>(d.min_separation_sin);
    c.sun.method = d.sun_method;
    c.sun.i_face_norm = to<T>(d.i_face_norm);
    c.sun.response = response_from<T>(d);
    c.sun.dark_threshold = static_cast<T>(d.face_dark_threshold);
    c.sun.min_sun_norm = static_cast<T>(d.min_sun_norm);
    c.sun.cone_tolerance = static_cast<T>(d.cone_tolerance);
    c.sun.cube_max_step = static_cast<T>(d.cube_max_step);
    s.reference_source = d.reference_source;
    // With its own references the cones' Earth is seen from the computer's own orbit: SGP4's mean semi-major
    // axis of its element set over its 6371 km sphere (no separate altitude to keep in step with the set).
    double orbit_radius = kEarthMeanRadius + d.orbit_altitude;
    double derived_ref = 0.0;   // T: the reference's error along the on-board orbit (reference_error.hpp)
    double derived_tilt = 0.0;  // rad: its position part read as one turn (ReferenceFieldError::turn)
    if (d.reference_source == ReferenceSource::onboard) {
        // The status was checked in the block's configure(); the firmware's board checks the epoch.
        const orbit::Tle tle = onboard_element_set(d);
        (void)make_reference_config(s.references, onboard_clock_epoch(d), tle.mean_elements<double>(), tle.epoch_jd_utc,
                                    d.field_degree, d.reference_period);
        orbit::Sgp4<double> sgp4;
        if (sgp4.initialize(tle.mean_elements<double>()) == orbit::Sgp4Status::ok)
            orbit_radius = sgp4.semi_major_axis_km() * 1e3;
        // The ground derives what is not given (both from one pass along the orbit).
        if (d.filter_mag_ref_correlation > 0.0 && !(d.filter_mag_ref_rms > 0.0 && d.filter_mag_ref_tilt > 0.0)) {
            const ReferenceFieldError e = reference_field_error(s.references.field, onboard_clock_epoch(d),
                                                                tle.mean_elements<double>(), tle.epoch_jd_utc);
            derived_ref = e.rms;
            derived_tilt = e.turn;
        }
    }
    c.sun.cone_earth_sin_radius = static_cast<T>(kEarthMeanRadius / orbit_radius);
    c.sun.cone_fit_tolerance = static_cast<T>(d.cone_fit_tolerance);
    c.sun.cone_albedo_max = static_cast<T>(d.cone_albedo_max);
    // The cones method's albedo model through the panels' response: a configure-time integral (1e6 response
    // evaluations), so only for the method that uses it.
    if (d.sun_method == SunMethod::cones)
        c.sun.cone_albedo_shape = cone_albedo_shape_table(c.sun.response, c.sun.cone_earth_sin_radius);
    c.face_adc.fill(adc<T>(d.adc_bits, 0.0, d.i_face_adc_max));

    s.set_reset = SetResetConfig{.period_samples = d.mag_set_reset_samples, .offset_window = d.mag_offset_window};
    s.sample_period = static_cast<T>(d.sample_period);
    s.rate_interval = static_cast<T>(d.rate_interval);
    s.rate.measure = RateMeasure::attitude_angle;
    s.rate.window = static_cast<std::size_t>(d.rate_window);
    s.rate.min_interval = static_cast<T>(d.rate_interval);
    // A few invalid estimates in between (a refused cones sample, a grazing sun) do not break an increment;
    // a gap longer than two increments (an eclipse) does: the rotation across it could alias past π.
    s.rate.max_interval = static_cast<T>(std::max(2.0 * d.rate_interval, 5.0 * d.sample_period));

    s.filter = d.filter;
    s.filter_scale = d.filter_scale;
    MekfConfig<T>& m = s.mekf;
    const auto method = static_cast<std::size_t>(d.sun_method);
    m.sun_sigma = static_cast<T>(d.filter_sun_sigma_method[method] > 0.0 ? d.filter_sun_sigma_method[method]
                                                                         : d.filter_sun_sigma);
    m.sun_correlation_time = static_cast<T>(d.filter_sun_correlation[method]);
    m.sun_turn_correlation = d.filter_sun_turn;
    m.mag_ref_sigma = static_cast<T>(d.filter_mag_ref_sigma);
    m.mag_ref_rms = static_cast<T>(d.filter_mag_ref_rms > 0.0 ? d.filter_mag_ref_rms : derived_ref);
    m.mag_ref_correlation = static_cast<T>(d.filter_mag_ref_correlation);
    m.mag_ref_tilt = static_cast<T>(d.filter_mag_ref_tilt > 0.0 ? d.filter_mag_ref_tilt : derived_tilt);
    m.mag_sigma_calibrated = static_cast<T>(d.filter_mag_sigma_calibrated);
    m.mag_sigma_calibrated_eclipse = static_cast<T>(d.filter_mag_sigma_eclipse);
    m.mag_hard_iron_sigma = static_cast<T>(d.filter_mag_hard_iron);
    m.mag_sigma = static_cast<T>(d.filter_mag_sigma);
    m.rate_noise = static_cast<T>(d.filter_rate_noise);
    m.start_rate_sigma = static_cast<T>(d.filter_start_rate);
    m.attitude_noise = static_cast<T>(d.filter_attitude_noise);
    m.estimate_offset = d.filter_offset;
    m.estimate_scale = d.filter_scale;
    m.face_sigma = static_cast<T>(d.filter_face_sigma);
    m.inertia = to<T>(d.inertia);
    m.dipole = to<T>(d.filter_dipole);
    m.gravity_gradient = d.filter_gravity_gradient;
    m.torque_noise = static_cast<T>(d.filter_torque_noise);
    if (d.filter_drag) {  // otherwise the geometry stays zero: no drag model
        m.drag.size = to<T>(d.body_size);
        m.drag.centre_of_mass = to<T>(d.centre_of_mass);
        m.drag.drag_coefficient = static_cast<T>(d.drag_coefficient);
    }
    m.drag_density_scale = static_cast<T>(d.filter_drag_density_scale);
    m.drag_density_sigma = static_cast<T>(d.filter_drag_density_sigma);
    m.drag_correlation_time = static_cast<T>(d.filter_drag_correlation);
    m.reset_after = d.filter_reset_after;
    m.watch_time = static_cast<T>(d.filter_watch_time);
    m.watch_gate = static_cast<T>(d.filter_watch_gate);
    m.watch_sun = d.filter_watch_sun;
    m.hold_field_axis = d.filter_hold_field_axis;
    s.mag_calibration = d.mag_calibration;
    s.mag_cal.sigma = static_cast<T>(d.mag_calibration_sigma);
    s.mag_cal.every = d.mag_calibration_every;
    s.mag_cal.min_equations = d.mag_calibration_min;
    s.mag_cal.prior_offset_sigma = static_cast<T>(d.mag_prior_offset_sigma);
    s.mag_cal.prior_field_sigma = static_cast<T>(d.mag_prior_field_sigma);
    s.mag_cal.prior_field_fluctuation = static_cast<T>(d.mag_prior_field_fluctuation);
    s.mag_cal.prior_field_correlation = static_cast<T>(d.mag_prior_field_correlation);
    s.mag_cal.prior_offset = to<T>(ground_calibration_offset(d));
    const auto strings = string_field_per_ampere(d);
    for (std::size_t f = 0; f < kStringFaces; ++f) s.string_field_per_amp[f] = to<T>(strings[f]);
    // The rate comes from two single-frame attitudes at most a few samples apart.
    m.max_init_gap = static_cast<T>(3.5 * d.sample_period);

    s.faults = fault_settings_from<T>(d);
    return s;
}

template <class T>
OnboardInputs<T> onboard_inputs_from(const EstimatorData& d) {
    return OnboardInputs<T>{.i_sh = to<T>(d.i_sh),
                            .i_face = to<T>(d.i_face),
                            .v_mag = to<T>(d.v_mag),
                            .v_mag_ref = static_cast<T>(d.v_mag_ref),
                            .sun_ref = to<T>(d.sun_ref),
                            .mag_ref = to<T>(d.mag_ref),
                            .sun_distance = static_cast<T>(d.sun_distance)};
}

Vec3<double> ground_calibration_offset(const EstimatorData& d) noexcept {
    Vec3<double> b =
        dipole_field_at_sensor(d.mag_prior_dipole, d.mag_prior_dipole_position, d.mag_prior_sensor_position);
    for (std::size_t i = 0; i < 3; ++i) b[i] += d.mag_prior_offset_error[i];
    return b;
}

orbit::Tle onboard_element_set(const EstimatorData& d) noexcept {
    const orbit::Tle given = orbit::tle_from_elements(d.parsed_elements[0] > 0.0 ? d.parsed_elements : d.tle_elements);
    return d.uplink_age == 0.0 ? given : orbit::older_set(given, d.uplink_age);
}

StringLoop string_loop(const EstimatorData& d, std::size_t face) noexcept {
    StringLoop l;
    for (std::size_t i = 0; i < 3; ++i) {
        l.center[i] = d.mag_string_loop_center[3 * face + i];
        l.side_a[i] = d.mag_string_loop_side_a[3 * face + i];
        l.side_b[i] = d.mag_string_loop_side_b[3 * face + i];
    }
    return l;
}

std::array<Vec3<double>, kStringFaces> string_field_per_ampere(const EstimatorData& d) noexcept {
    std::array<Vec3<double>, kStringFaces> k{};
    if (!d.mag_string_field) return k;
    const double gain = 1.0 + d.mag_string_field_error;
    for (std::size_t f = 0; f < kStringFaces; ++f) {
        const Vec3<double> b = string_loop_field_per_ampere(string_loop(d, f), d.mag_prior_sensor_position);
        for (std::size_t i = 0; i < 3; ++i) k[f][i] = gain * b[i];
    }
    return k;
}

CalendarInstant onboard_clock_epoch(const EstimatorData& d) noexcept {
    // The offset joins the seconds (make_onboard_clock counts them past the minute and below zero alike).
    return CalendarInstant{.year = d.clock_epoch_year,
                           .month = d.clock_epoch_month,
                           .day = d.clock_epoch_day,
                           .hour = d.clock_epoch_hour,
                           .minute = d.clock_epoch_minute,
                           .second = d.clock_epoch_second + d.clock_offset};
}

template <class T>
void store_outputs(EstimatorData& d, const OnboardOutputs<T>& out) {
    const SampleResult<T>& r = out.sample;
    d.q_est = {r.q.x, r.q.y, r.q.z, r.q.w};
    d.A_est = from<9>(r.a);
    d.sun_meas = from<3>(r.sun_meas);
    d.mag_meas = from<3>(r.mag_meas);
    d.mag_field = from<3>(r.mag_field);
    d.sun_norm = r.sun_norm;
    d.loss = r.loss;
    d.valid = r.valid;
    d.sun_valid = r.sun_valid;
    d.mag_valid = r.mag_valid;
    d.lit_faces = r.lit_faces;
    d.rejected_faces = r.rejected_faces;
    d.cube_state = r.cube_state;
    d.samples = out.samples;
    d.mag_set_reset = out.mag_set_reset;
    d.mag_offset = from<3>(out.mag_offset);
    d.rate_mean = out.rate_mean;
    d.rate_window_time = out.rate_window_time;
    d.rate_valid = out.rate_valid;
    d.ref_sun = from<3>(out.references.sun);
    d.ref_mag = from<3>(out.references.field);
    d.mag_cal_valid = out.mag_cal_valid;
    store_fault_outputs(d, out);
    if (d.filter == FilterKind::mekf) {
        d.q_filt = {out.q_filt.x, out.q_filt.y, out.q_filt.z, out.q_filt.w};
        d.omega_filt = from<3>(out.omega_filt);
        d.mag_offset_filt = from<3>(out.mag_offset_filt);
        d.panel_scale_filt = out.panel_scale_filt;
        d.attitude_bound = out.attitude_bound;
        const auto& l = out.attitude_cov_sqrt;  // row-major 3 × 3, lower
        d.attitude_cov_sqrt = {l[0], l[3], l[4], l[6], l[7], l[8]};
        d.filter_valid = out.filter_valid;
        d.filter_resets = out.filter_resets;
    }
}

template OnboardSettings<float> onboard_settings_from(const EstimatorData&);
template OnboardSettings<double> onboard_settings_from(const EstimatorData&);
template OnboardInputs<float> onboard_inputs_from(const EstimatorData&);
template OnboardInputs<double> onboard_inputs_from(const EstimatorData&);
template void store_outputs(EstimatorData&, const OnboardOutputs<float>&);
template void store_outputs(EstimatorData&, const OnboardOutputs<double>&);

}  // namespace attitude_estimator
