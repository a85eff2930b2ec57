#include "attitude_estimator/estimator_block.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "attitude_estimator/spin_spectrum.hpp"
#include "fmu/errors.hpp"
#include "fmu/instant_clock.hpp"
#include "fmu/state_check.hpp"

namespace attitude_estimator {

namespace {

constexpr double kEarthMeanRadius = 6371e3;  // m: the albedo model's sphere (the core's 570 km default uses it)

// The rates' state must travel with the FMU state as bytes.
static_assert(std::is_trivially_copyable_v<MeanAngularRate<double>> &&
              std::is_trivially_copyable_v<SunMethodState<double>> && std::is_trivially_copyable_v<MekfState<double>> &&
              std::is_trivially_copyable_v<SetResetState<double>>);

// A face's current is used for the panel-scale update only well inside the response curve (below about
// 45 deg of incidence with the Kelly law), where a small attitude error changes it little and albedo is a
// small part of it.
constexpr double kScaleFaceMinResponse = 0.7;

panel_response::Response<double> response_from(const EstimatorData& d) {
    if (d.angular_response == AngularResponse::cosine) return panel_response::cosine<double>();
    std::array<panel_response::Knot<double>, 6> knots{};
    for (std::size_t i = 0; i < knots.size(); ++i) knots[i] = {d.kelly_angle[i], d.kelly_value[i]};
    return panel_response::table<double>(knots);
}

MeanAngularRateConfig<double> rate_config_from(const EstimatorData& d) {
    MeanAngularRateConfig<double> c;
    c.measure = RateMeasure::attitude_angle;
    c.window = static_cast<std::size_t>(d.rate_window);
    c.min_interval = d.rate_interval;
    // A few invalid estimates in between (a refused cones sample, a grazing sun) do not break an increment;
    // a gap longer than two increments (an eclipse) does: the rotation across it could alias past π.
    c.max_interval = std::max(2.0 * d.rate_interval, 5.0 * d.sample_period);
    return c;
}

SetResetConfig set_reset_config_from(const EstimatorData& d) {
    return SetResetConfig{.period_samples = d.mag_set_reset_samples, .offset_window = d.mag_offset_window};
}

AdcConfig<double> adc(std::int32_t bits, double min, double max) {
    return AdcConfig<double>{static_cast<unsigned>(bits), min, max};
}

}  // namespace

MekfConfig<double> filter_config_from(const EstimatorData& d) {
    MekfConfig<double> c;
    c.sun_sigma = d.filter_sun_sigma;
    c.mag_sigma = d.filter_mag_sigma;
    c.rate_noise = d.filter_rate_noise;
    c.attitude_noise = d.filter_attitude_noise;
    c.estimate_offset = d.filter_offset;
    c.estimate_scale = d.filter_scale;
    c.face_sigma = d.filter_face_sigma;
    c.inertia = d.inertia;
    c.reset_after = d.filter_reset_after;
    // The rate comes from two single-frame attitudes at most a few samples apart.
    c.max_init_gap = 3.5 * d.sample_period;
    return c;
}

EstimatorConfig<double> config_from(const EstimatorData& d) {
    EstimatorConfig<double> c;
    c.i_sc_norm = d.i_sc_norm;  // at 1 AU; at_sun_distance() scales them to the sample's distance
    c.mag_sensitivity = d.mag_sensitivity;
    c.sun_weight = d.weight_sun;
    c.mag_weight = d.weight_mag;
    const auto current = adc(d.adc_bits, d.i_adc_min, d.i_adc_max);
    const auto voltage = adc(d.adc_bits, d.v_adc_min, d.v_adc_max);
    c.sun_adc = {current, current, current};
    c.mag_adc = {voltage, voltage, voltage};
    c.mag_ref_adc = voltage;  // the zero-field reference goes through a channel of the same kind
    c.solver = d.solver;
    c.min_sun_norm = d.min_sun_norm;
    c.mag_rail_margin = d.mag_rail_margin;
    c.min_field = d.min_field;
    c.min_separation_sin = d.min_separation_sin;
    c.sun.method = d.sun_method;
    c.sun.i_face_norm = d.i_face_norm;
    c.sun.response = response_from(d);
    c.sun.dark_threshold = d.face_dark_threshold;
    c.sun.min_sun_norm = d.min_sun_norm;
    c.sun.cone_tolerance = d.cone_tolerance;
    c.sun.cube_max_step = d.cube_max_step;
    c.sun.cone_earth_sin_radius = kEarthMeanRadius / (kEarthMeanRadius + d.orbit_altitude);
    c.sun.cone_fit_tolerance = d.cone_fit_tolerance;
    c.sun.cone_albedo_max = d.cone_albedo_max;
    c.face_adc.fill(adc(d.adc_bits, 0.0, d.i_face_adc_max));
    return c;
}

EstimatorConfig<double> at_sun_distance(EstimatorConfig<double> c, double sun_distance) {
    // The panels' currents scale with the irradiance, (1 AU / distance)² of the 1 AU normalization
    // (±3.4 % over a year): the cones method's albedo fit needs the absolute scale.
    const double au_ratio = kAstronomicalUnit / sun_distance;
    const double scale = au_ratio * au_ratio;
    for (auto& v : c.i_sc_norm) v *= scale;
    for (auto& v : c.sun.i_face_norm) v *= scale;
    return c;
}

SampleInputs<double> inputs_from(const EstimatorData& d) {
    return SampleInputs<double>{
        .i_sh = d.i_sh,
        .i_face = d.i_face,
        .v_mag = d.v_mag,
        .v_mag_ref = d.v_mag_ref,
        .sun_ref = d.sun_ref,
        .mag_ref = d.mag_ref,
        // The reading now at the inputs was taken in the polarity commanded at the previous sample.
        .mag_polarity = d.set_reset.polarity,
        .mag_offset = applied_offset(d.set_reset, set_reset_config_from(d))};
}

void EstimatorBlock::declare(fmu::Table<EstimatorData>& t) {
    using D = EstimatorData;
    t.input("i_sh", &D::i_sh, "A",
            "Sample/hold differential currents I_sc+k - I_sc-k of the x, y, z panel pairs (ssr_plant i_sh)");
    t.input("i_face", &D::i_face, "A",
            "Per-face sample/hold currents of the faces +x, -x, +y, -y, +z, -z (ssr_plant i_face_sh); read by "
            "every sun_method except difference");
    t.input("v_mag", &D::v_mag, "V", "Magnetometer output voltages X, Y, Z (magnetometer v_out)");
    t.input("v_mag_ref", &D::v_mag_ref, "V", "Magnetometer zero-field reference voltage (magnetometer v_ref)");
    t.input("sun_ref", &D::sun_ref, "1",
            "Sun direction in the inertial frame, any nonzero length (environment sun_eci)");
    t.input("mag_ref", &D::mag_ref, "T",
            "Geomagnetic field in the inertial frame, any nonzero length (environment mag_eci)");

    t.input("sun_distance", &D::sun_distance, "m",
            "Distance satellite to sun from the on-board ephemeris (environment sun_distance); scales i_sc_norm "
            "and i_face_norm, which hold at 1 AU")
        .min(1e9);
    t.parameter("sample_period", &D::sample_period, "s",
                "Time between samples; sample k is taken at start time + k*sample_period (default 20 Hz)")
        .min(1e-6);
    t.parameter("i_sc_norm", &D::i_sc_norm, "A",
                "Differential current of each axis with one panel facing the sun squarely at 1 AU (000 eq. 5 "
                "denominators; default ssr_plant's short-circuit current at 1367 W/m2)")
        .min(1e-6);
    t.parameter("mag_sensitivity", &D::mag_sensitivity, "V/T",
                "Magnetometer sensitivity (HMC2003: 1 V/gauss = 1e4 V/T)")
        .min(1e-3);
    t.parameter("weight_sun", &D::weight_sun, "1", "Weight of the sun observation in Wahba's loss (000 eq. 8)")
        .min(0.0);
    t.parameter("weight_mag", &D::weight_mag, "1", "Weight of the field observation in Wahba's loss (000 eq. 8)")
        .min(0.0);
    t.parameter("adc_bits", &D::adc_bits, "", "Resolution of every A/D channel in bits (TMS320F2808: 12); 0 = ideal")
        .range(0.0, 24.0);
    t.parameter("i_adc_min", &D::i_adc_min, "A", "Lower end of the current channels' full-scale range");
    t.parameter("i_adc_max", &D::i_adc_max, "A", "Upper end of the current channels' full-scale range");
    t.parameter("v_adc_min", &D::v_adc_min, "V",
                "Lower end of the voltage channels' full-scale range; also the magnetometer's lower rail");
    t.parameter("v_adc_max", &D::v_adc_max, "V",
                "Upper end of the voltage channels' full-scale range; also the magnetometer's upper rail");
    t.choice("solver", &D::solver, {{"qmethod", SolverKind::qmethod}, {"fast", SolverKind::fast}},
             "Wahba solver: qmethod (default; largest eigenpair of K, 000 eq. 15) or fast (closed form for "
             "two observations)");
    t.parameter("min_sun_norm", &D::min_sun_norm, "1",
                "The sun vector is invalid (eclipse, albedo only) when |s| is below this")
        .min(0.0);
    t.parameter("mag_rail_margin", &D::mag_rail_margin, "V",
                "A magnetometer channel this close to a range end counts as saturated (field invalid)")
        .min(0.0);
    t.parameter("min_field", &D::min_field, "T", "The field vector is invalid when |B| is below this").min(0.0);
    t.parameter("min_separation_sin", &D::min_separation_sin, "1",
                "The attitude is invalid unless sun and field are more than asin(this) from (anti)parallel")
        .range(0.0, 1.0);

    t.choice("sun_method", &D::sun_method,
             {{"difference", SunMethod::difference},
              {"inverse_response", SunMethod::inverse_response},
              {"cones", SunMethod::cones},
              {"three_faces", SunMethod::three_faces}},
             "Sun vector from the panel currents: difference (000 eq. 5 on i_sh, the seed), inverse_response "
             "(per-face incidence from the inverted angular response), cones (002: cone pairs with albedo "
             "rejection and the panel cube), three_faces (004 eq. 2-3)");
    t.choice("angular_response", &D::angular_response,
             {{"cosine", AngularResponse::cosine}, {"kelly", AngularResponse::kelly}},
             "The panels' angular response the face-based methods invert: cosine (000 eq. 1) or kelly "
             "(the table kelly_angle/kelly_value); must match ssr_plant's angular_response");
    t.parameter("kelly_angle", &D::kelly_angle, "deg",
                "Kelly table: incidence angles, increasing, the first 0, the second where the cosine ends, all "
                "below 90 (default ssr_plant's, 000 fig. 4)")
        .range(0.0, 90.0);
    t.parameter("kelly_value", &D::kelly_value, "1",
                "Kelly table: relative response at kelly_angle, the first 1 (default ssr_plant's)")
        .range(0.0, 1.0);
    t.parameter(
         "i_face_norm", &D::i_face_norm, "A",
         "Each face's current facing the sun squarely in full sun at 1 AU (default ssr_plant's i_sc at 1367 W/m2)")
        .min(1e-6);
    t.parameter("face_dark_threshold", &D::face_dark_threshold, "1",
                "A face counts as lit above this fraction of its i_face_norm")
        .range(0.0, 1.0);
    t.parameter("i_face_adc_max", &D::i_face_adc_max, "A", "Face-current channels span 0 to this").min(1e-6);
    t.parameter("cone_tolerance", &D::cone_tolerance, "1",
                "cones: agreement tolerance on a face's relative response (larger: fewer faces rejected)")
        .range(1e-6, 1.0);
    t.parameter("cube_max_step", &D::cube_max_step, "rad",
                "cones: a transition the panel-cube graph forbids is accepted when the sun moved less than this "
                "since the last sample (0: the seed's graph alone; fast spin: about 1.5 x the turn per sample)")
        .range(0.0, 3.14159);
    t.parameter(
         "orbit_altitude", &D::orbit_altitude, "m",
         "cones: altitude of the orbit, for the Earth-albedo model's view of the Earth (default 570 km, seed 004)")
        .range(100e3, 100e6);
    t.parameter("cone_fit_tolerance", &D::cone_fit_tolerance, "1",
                "cones: an albedo-model fit is accepted below this RMS misfit of the relative face responses; 0 "
                "turns the model off (face rejection only)")
        .range(0.0, 1.0);
    t.parameter("cone_albedo_max", &D::cone_albedo_max, "1",
                "cones: largest albedo the model may fit on a face squarely toward the Earth (fraction of full sun)")
        .range(0.0, 1.0);
    t.parameter("spin_window", &D::spin_window, "",
                "Samples in the spin-rate FFT window (0: no spin-rate analysis); at most 2048")
        .range(0.0, static_cast<double>(kMaxSpinWindow));
    t.parameter("rate_interval", &D::rate_interval, "s",
                "Shortest time between the two attitudes of one mean-rate increment (004 eq. 4; 004 samples once "
                "a minute, 2 s or more keeps attitude noise from dominating)")
        .min(0.0);
    t.parameter("rate_window", &D::rate_window, "", "Mean-rate increments averaged (1 = 004 eq. 4 alone), 1 to 64")
        .range(1.0, static_cast<double>(kMaxRateWindow));

    t.choice("filter", &D::filter, {{"none", FilterKind::none}, {"mekf", FilterKind::mekf}},
             "Recursive attitude filter beside the single-frame estimate: none, or mekf (multiplicative "
             "extended Kalman filter with rate, magnetometer-offset and panel-scale states; docs/filter.md)");
    t.parameter("filter_sun_sigma", &D::filter_sun_sigma, "rad",
                "mekf: 1-sigma error of one sun vector per axis (noise and the sun method's model error)")
        .range(1e-6, 1.0);
    t.parameter("filter_mag_sigma", &D::filter_mag_sigma, "T",
                "mekf: 1-sigma error of one field vector per axis (noise, quantization, field-model error)")
        .range(1e-10, 1e-4);
    t.parameter("filter_rate_noise", &D::filter_rate_noise, "rad/s",
                "mekf: 1-sigma unpredictable change of the body rate over 1 s (a random walk: it grows as the "
                "square root of time; the rate random-walk density in rad/s per root second)")
        .range(0.0, 10.0);
    t.parameter("filter_attitude_noise", &D::filter_attitude_noise, "rad",
                "mekf: 1-sigma attitude drift over 1 s that the rate state does not explain (random walk)")
        .range(0.0, 1.0);
    t.parameter("filter_offset", &D::filter_offset, "",
                "mekf: estimate the magnetometer's offset (3 states; its sign follows the set/reset polarity)");
    t.parameter("filter_scale", &D::filter_scale, "",
                "mekf: estimate a common scale error of the panels' current normalization from the face "
                "currents and correct i_face_norm/i_sc_norm with it (face-based sun methods)");
    t.parameter("filter_face_sigma", &D::filter_face_sigma, "1",
                "mekf: 1-sigma error of one face's relative response in the panel-scale update (noise, albedo)")
        .range(1e-6, 1.0);
    t.parameter("inertia", &D::inertia, "kg.m2",
                "mekf: inertia matrix, body axes, row-major; all zero (default) = kinematic rate model, else "
                "Euler's torque-free equations propagate the rate");
    t.parameter("filter_reset_after", &D::filter_reset_after, "",
                "mekf: samples in a row whose every update fails the innovation test before the filter resets "
                "to the single-frame attitude")
        .range(1.0, 1e6);

    t.output("q_est", &D::q_est, "1", "Estimated attitude quaternion, scalar-last [x, y, z, w], w >= 0")
        .discrete()
        .depends_on({});
    t.output("A_est", &D::A_est, "1", "Estimated attitude matrix, row-major, w_body = A v_ref")
        .discrete()
        .depends_on({});
    t.output("sun_meas", &D::sun_meas, "1", "Measured sun direction, body axes, unit (zero when sun_valid is false)")
        .discrete()
        .depends_on({});
    t.output("mag_meas", &D::mag_meas, "1", "Measured field direction, body axes, unit (zero when mag_valid is false)")
        .discrete()
        .depends_on({});
    t.output("mag_field", &D::mag_field, "T", "Measured geomagnetic field, body axes").discrete().depends_on({});
    t.output("sun_norm", &D::sun_norm, "1", "|s| of 000 eq. 5 before normalization: 1 in full sun")
        .discrete()
        .depends_on({});
    t.output("loss", &D::loss, "1", "Wahba loss L(A) of the estimate (000 eq. 8); 0 when not valid")
        .discrete()
        .depends_on({});
    t.output("valid", &D::valid, "", "The estimate is valid (sun and field valid and separated)")
        .discrete()
        .depends_on({});
    t.output("sun_valid", &D::sun_valid, "", "The sun vector is valid (not in eclipse)").discrete().depends_on({});
    t.output("mag_valid", &D::mag_valid, "", "The field vector is valid (no channel saturated, field not tiny)")
        .discrete()
        .depends_on({});
    t.output("samples", &D::samples, "", "Number of samples taken, the one at the start time included")
        .discrete()
        .depends_on({});

    t.output("lit_faces", &D::lit_faces, "",
             "Bit k set: face k (+x, -x, +y, -y, +z, -z) above the dark threshold (face-based sun methods)")
        .discrete()
        .depends_on({});
    t.output("rejected_faces", &D::rejected_faces, "",
             "Bit k set: lit face k not used for the sun vector (albedo-polluted or the dimmer of a pair)")
        .discrete()
        .depends_on({});
    t.output("cube_state", &D::cube_state, "",
             "cones: panel-cube state 9(x+1) + 3(y+1) + (z+1), each axis -1/0/+1 for its lit face; 13 = dark")
        .discrete()
        .depends_on({});
    t.output("spin_theta_dot", &D::spin_theta_dot, "rad/s",
             "Spin rate theta-dot of the seed's sun motion, from the FFT of sun_meas (000 sec. 4)")
        .discrete()
        .depends_on({});
    t.output("spin_phi_dot", &D::spin_phi_dot, "rad/s", "Spin rate phi-dot, from the same FFT")
        .discrete()
        .depends_on({});
    t.output("spin_bin_width", &D::spin_bin_width, "rad/s", "Frequency resolution of the spin-rate FFT")
        .discrete()
        .depends_on({});
    t.output("spin_window_time", &D::spin_window_time, "s", "Length of the spin-rate FFT window")
        .discrete()
        .depends_on({});
    t.output("spin_valid", &D::spin_valid, "",
             "The spin rates are valid (window full of valid sun vectors, the seed's two-rate lines found)")
        .discrete()
        .depends_on({});
    t.output("rate_mean", &D::rate_mean, "rad/s",
             "Mean angular-rate magnitude from successive valid estimates (004 eq. 4, averaged over rate_window)")
        .discrete()
        .depends_on({});
    t.output("rate_window_time", &D::rate_window_time, "s", "Time spanned by the averaged mean-rate increments")
        .discrete()
        .depends_on({});
    t.output("rate_valid", &D::rate_valid, "",
             "rate_mean is valid: rate_window increments collected, and neither the filter's rate nor a turn "
             "between successive samples clearly above noise says one rate_interval may turn 90 deg or more "
             "(the increments could alias; omega_filt holds there)")
        .discrete()
        .depends_on({});

    t.output("q_filt", &D::q_filt, "1", "mekf: filter attitude quaternion, scalar-last [x, y, z, w], w >= 0")
        .discrete()
        .depends_on({});
    t.output("omega_filt", &D::omega_filt, "rad/s", "mekf: filter body rate").discrete().depends_on({});
    t.output("mag_offset_filt", &D::mag_offset_filt, "V",
             "mekf: estimated magnetometer offset per axis, as it reads after a set pulse")
        .discrete()
        .depends_on({});
    t.output("panel_scale_filt", &D::panel_scale_filt, "1",
             "mekf: estimated common panel scale error (face currents are (1 + this) x nominal)")
        .discrete()
        .depends_on({});
    t.output("attitude_bound", &D::attitude_bound, "rad",
             "mekf: 3-sigma bound on the filter's attitude error angle, 3 sqrt(trace of its attitude covariance)")
        .discrete()
        .depends_on({});
    t.output("filter_valid", &D::filter_valid, "",
             "mekf: the filter runs and its 3-sigma attitude bound is below 10 deg")
        .discrete()
        .depends_on({});
    t.output("filter_resets", &D::filter_resets, "",
             "mekf: times the innovation test found the filter diverged and reset it to the single-frame attitude")
        .discrete()
        .depends_on({});

    t.parameter("mag_set_reset_samples", &D::mag_set_reset_samples, "",
                "Pulse the magnetometer's set/reset strap (output mag_set_reset) every this many samples, "
                "alternating set and reset, and take the offset out of the field; 0 (default): no pulses, the "
                "offset stays in the field. Only with mag_set_reset wired to the magnetometer's "
                "set_reset_command (its set_reset_source = input): else every other reading is taken inverted")
        .range(0.0, 1e6);
    t.parameter("mag_offset_window", &D::mag_offset_window, "",
                "Set/reset pairs in the running mean of the magnetometer offset estimate")
        .range(1.0, 1e6);
    t.output("mag_set_reset", &D::mag_set_reset, "",
             "Set/reset pulse commanded last, to the magnetometer's set_reset_command: true set, false reset")
        .discrete()
        .depends_on({})
        .initial_depends_on({});  // set at the start sample, whatever the inputs (no pulse there)
    t.output("mag_offset", &D::mag_offset, "V",
             "Magnetometer offset taken out of the field: the mean of mag_offset_window estimates from set/reset "
             "readings (half the sum of a set and a reset reading); 0 until that many were taken")
        .discrete()
        .depends_on({})
        .initial_depends_on({});  // no set/reset pair at the start sample
    t.local("t_start", &D::t_start, "s", "Start time: sample k is due at t_start + k*sample_period").discrete();
}

fmu::ModelInfo EstimatorBlock::describe() {
    fmu::ModelInfo info;
    info.model_identifier = "attitude_estimator";
    info.model_name = "attitude_estimator";
    info.description = "On-board attitude computer: sun vector from panel currents, HMC2003 field, Q-method, sampled";
    info.documentation_html =
        "<p>The attitude computer of seed paper 000 sections 6-8 (fig. 11) as a sampled-data block. At each "
        "sample instant t<sub>k</sub> = t<sub>0</sub> + k&middot;<code>sample_period</code> (time events, "
        "t<sub>0</sub> the start time, k an integer count so the instants never drift; the sample at "
        "t<sub>0</sub> is taken in initialization) it digitizes the inputs with <code>adc_bits</code>-bit "
        "converters (currents over [<code>i_adc_min</code>, <code>i_adc_max</code>], voltages over "
        "[<code>v_adc_min</code>, <code>v_adc_max</code>]), forms the sun vector "
        "s<sub>k</sub> = i<sub>sh,k</sub>/i<sub>sc_norm,k</sub> (000 eq. 5) and the field "
        "B = p(v<sub>mag</sub> &minus; v<sub>mag_ref</sub> &minus; v<sub>os</sub>)/S (p = &plusmn;1 the "
        "magnetometer's set/reset polarity the block commanded through <code>mag_set_reset</code>, v<sub>os</sub> "
        "the offset it estimated from set/reset readings; with <code>mag_set_reset_samples</code> = 0, the "
        "default, p = 1 and v<sub>os</sub> = 0), and solves Wahba's problem (000 eq. 7-9) against "
        "the inertial references <code>sun_ref</code> and <code>mag_ref</code> with the Q-method "
        "(<code>solver = qmethod</code>, 000 eq. 15) or its closed form for two observations "
        "(<code>solver = fast</code>). Every output is discrete: held between samples.</p>"
        "<p>Conventions: quaternion scalar-last [x, y, z, w] with w &ge; 0; A row-major with "
        "w<sub>body</sub> = A v<sub>ref</sub>. Validity: the sun vector is invalid when |s| &lt; "
        "<code>min_sun_norm</code> (eclipse); the field is invalid when a channel is within "
        "<code>mag_rail_margin</code> of a range end (saturated) or |B| &lt; <code>min_field</code>; the "
        "estimate is invalid when either is, or when the two directions are within "
        "asin(<code>min_separation_sin</code>) of (anti)parallel. An invalid sample outputs the identity "
        "attitude and loss 0 (do not use it), and is still counted in <code>samples</code>.</p>"
        "<p>Defaults match the other blocks: <code>i_sc_norm</code> = 0.84754 A is ssr_plant's short-circuit "
        "current of one panel at normal incidence and 1367 W/m<sup>2</sup>, current range &plusmn;1.2 A; "
        "magnetometer 0-5 V, 2.5 V reference, 1e4 V/T. In Co-Simulation the inputs are held over each "
        "communication step, so a sample on a communication point sees the inputs of the step that ends "
        "there.</p>"
        "<p>With <code>filter = mekf</code> a multiplicative extended Kalman filter runs beside the single-frame "
        "estimate: attitude, body rate (kinematic, or Euler's equations when <code>inertia</code> is given), "
        "magnetometer offset and a common panel scale, started from the Q-method and reset to it when its "
        "innovation test says it diverged. Outputs <code>q_filt</code>, <code>omega_filt</code>, "
        "<code>mag_offset_filt</code>, <code>panel_scale_filt</code>, the 3-sigma bound "
        "<code>attitude_bound</code> and <code>filter_valid</code> (attitude_estimator/docs/filter.md).</p>";
    info.default_experiment = {.start_time = 0.0, .stop_time = 2.0, .tolerance = 1e-6, .step_size = 0.01};
    return info;
}

void EstimatorBlock::validate() const {
    const auto& d = data();
    if (!(d.i_adc_max > d.i_adc_min)) throw fmu::Error("i_adc_max must be above i_adc_min");
    if (!(d.v_adc_max - d.v_adc_min > 2.0 * d.mag_rail_margin))
        throw fmu::Error("v_adc_max - v_adc_min must exceed twice mag_rail_margin (else every field reads saturated)");
    if (!(d.weight_sun + d.weight_mag > 0.0)) throw fmu::Error("weight_sun + weight_mag must be positive");
    if (!(d.sample_period > 0.0)) throw fmu::Error("sample_period must be positive");
    if (d.angular_response == AngularResponse::kelly) {
        if (d.kelly_angle[0] != 0.0 || d.kelly_value[0] != 1.0)
            throw fmu::Error("kelly_angle[1], kelly_value[1] must be 0 deg, 1 (normal incidence)");
        for (std::size_t i = 1; i < d.kelly_angle.size(); ++i) {
            if (!(d.kelly_angle[i] > d.kelly_angle[i - 1]) || !(d.kelly_angle[i] < 90.0))
                throw fmu::Error("kelly_angle must increase and stay below 90 deg");
            if (i >= 2 && d.kelly_value[i] > d.kelly_value[i - 1])
                throw fmu::Error("kelly_value must not increase with the angle (the inverse needs a monotone curve)");
        }
    }
    if (d.spin_window != 0 && d.spin_window < 16) throw fmu::Error("spin_window must be 0 (off) or 16 to 2048");
    bool has_inertia = false;
    for (double v : d.inertia) has_inertia = has_inertia || v != 0.0;
    if (has_inertia) {
        const auto& j = d.inertia;
        const double m1 = j[0], m2 = j[0] * j[4] - j[1] * j[3];
        const double m3 = j[0] * (j[4] * j[8] - j[5] * j[7]) - j[1] * (j[3] * j[8] - j[5] * j[6]) +
                          j[2] * (j[3] * j[7] - j[4] * j[6]);
        if (j[1] != j[3] || j[2] != j[6] || j[5] != j[7] || !(m1 > 0.0 && m2 > 0.0 && m3 > 0.0))
            throw fmu::Error("inertia must be all zero (kinematic) or symmetric positive definite");
    }
}

void EstimatorBlock::take_sample(double t) {
    auto& d = data();
    const EstimatorConfig<double> nominal = at_sun_distance(config_, d.sun_distance);
    EstimatorConfig<double> config = nominal;
    if (d.filter == FilterKind::mekf && d.filter_scale && d.filter_state.stage == 2) {
        // The filter's panel-scale estimate corrects the normalization the sun method divides by.
        const double gain = 1.0 + d.filter_state.panel_scale;
        for (auto& v : config.sun.i_face_norm) v *= gain;
        for (auto& v : config.i_sc_norm) v *= gain;
    }
    const SampleResult<double> r = estimate_sample(inputs_from(d), config, d.sun_state);
    d.q_est = {r.q.x, r.q.y, r.q.z, r.q.w};
    d.A_est = r.a;
    d.sun_meas = r.sun_meas;
    d.mag_meas = r.mag_meas;
    d.mag_field = r.mag_field;
    d.sun_norm = r.sun_norm;
    d.loss = r.loss;
    d.valid = r.valid;
    d.sun_valid = r.sun_valid;
    d.mag_valid = r.mag_valid;
    d.lit_faces = r.lit_faces;
    d.rejected_faces = r.rejected_faces;
    d.cube_state = r.cube_state;
    if (d.samples < std::numeric_limits<std::int32_t>::max()) ++d.samples;
    const double reading_polarity = d.set_reset.polarity;  // this sample's reading was taken in it
    // The next reading is taken in the polarity commanded here.
    set_reset_after_sample(d.set_reset, r.mag_reading, r.mag_reading_usable, set_reset_config_from(d));
    d.mag_set_reset = d.set_reset.polarity > 0.0;
    d.mag_offset = applied_offset(d.set_reset, set_reset_config_from(d));
    update_rates(t);
    if (d.filter == FilterKind::mekf) update_filter(t, r, nominal, reading_polarity);
}

void EstimatorBlock::update_filter(double t, const SampleResult<double>& r, const EstimatorConfig<double>& nominal,
                                   double polarity) {
    auto& d = data();
    const MekfConfig<double>& config = filter_config_;
    MekfSampleInputs<double> in;
    in.t = t;
    in.attitude_valid = r.valid;
    in.q_single = r.q;
    in.sun_valid = r.sun_valid;
    in.sun_ref = d.sun_ref;
    in.sun_body = r.sun_meas;
    in.mag_valid = r.mag_valid;
    in.mag_ref = d.mag_ref;
    // The field comes with the set/reset offset estimate taken out, B + p (v_os − applied)/S: the filter's
    // offset state is what is left of the offset, with the sign of this reading's polarity.
    in.mag_body = r.mag_field;
    in.polarity = polarity;
    if (d.filter_scale && nominal.sun.method != SunMethod::difference) {
        // Relative responses against the nominal normalization: the filter's model is (1 + ε) R(cos β).
        for (std::size_t k = 0; k < 6; ++k) {
            const double i = convert(nominal.face_adc[k], d.i_face[k]).value;
            in.face_r[k] = i / nominal.sun.i_face_norm[k];
            // The cones fit's albedo is relative to the normalization the sun method used, (1 + ε̂) × nominal.
            in.face_albedo[k] = r.face_albedo[k];
            const bool usable =
                (r.lit_faces >> k & 1) && !(r.rejected_faces >> k & 1) && in.face_r[k] >= kScaleFaceMinResponse;
            if (usable) in.face_use |= static_cast<std::uint8_t>(1u << k);
        }
        in.response = &nominal.sun.response;
    }
    const MekfSampleResult<double> f = mekf_sample(d.filter_state, in, config);
    const MekfState<double>& s = d.filter_state;
    const bool running = s.stage == 2;
    d.q_filt = running ? std::array<double, 4>{s.q.x, s.q.y, s.q.z, s.q.w} : std::array<double, 4>{0, 0, 0, 1};
    d.omega_filt = running ? s.omega : Vec3d{};
    for (std::size_t k = 0; k < 3; ++k) d.mag_offset_filt[k] = s.mag_offset[k] * d.mag_sensitivity;
    d.panel_scale_filt = s.panel_scale;
    d.attitude_bound = running ? f.bound : 0.0;
    d.filter_valid = running && f.valid;
    d.filter_resets = s.resets;
}

void EstimatorBlock::update_rates(double t) {
    auto& d = data();
    // Mean |ω| (004 eq. 4) from successive valid attitudes; invalid ones are skipped, and a gap longer than
    // the rate config's max_interval starts a new chain.
    if (d.valid) d.rate_state.push(t, Quaternion<double>{d.q_est[0], d.q_est[1], d.q_est[2], d.q_est[3]});
    const MeanRate<double> mean = d.rate_state.result();
    d.rate_mean = mean.rate;
    d.rate_window_time = mean.window_seconds;
    // Aliasing: an increment rate_interval long reads the turn modulo 2π (folded beyond π), so rate_mean
    // is not trusted when one increment may turn more than π/2 (margin for a rate that changes within
    // the window). Two witnesses: the filter's rate when it runs, and the turn between successive
    // single-frame estimates (averaged, α = 0.2) when it is clearly above their noise (0.1 rad per sample;
    // below that a fast rate cannot be told from noise by this test: use omega_filt).
    constexpr double kHalfPi = 1.5707963267948966;
    constexpr double kStepNoise = 0.1;  // rad per sample
    if (d.valid) {
        if (d.rate_has_last && t - d.rate_last_t <= 1.5 * d.sample_period) {
            double dot = 0.0;
            for (std::size_t k = 0; k < 4; ++k) dot += d.rate_last_q[k] * d.q_est[k];
            const double turn = 2.0 * std::acos(std::min(1.0, std::abs(dot)));
            d.rate_step_turn += 0.2 * (turn - d.rate_step_turn);
        }
        d.rate_last_q = d.q_est;
        d.rate_last_t = t;
        d.rate_has_last = true;
    }
    const bool step_aliases =
        d.rate_step_turn >= kStepNoise && d.rate_step_turn / d.sample_period * d.rate_interval >= kHalfPi;
    const auto& f = d.filter_state;
    const double filter_rate = std::sqrt(f.omega[0] * f.omega[0] + f.omega[1] * f.omega[1] + f.omega[2] * f.omega[2]);
    const bool filter_aliases =
        d.filter == FilterKind::mekf && f.stage == 2 && filter_rate * d.rate_interval >= kHalfPi;
    d.rate_valid = mean.valid && !step_aliases && !filter_aliases;

    // Spin rates (000 §4): the history of valid sun vectors; an invalid one empties the window (the FFT
    // needs evenly spaced samples).
    const auto n = d.spin_window;
    if (n == 0) return;
    if (!d.sun_valid) {
        d.history_filled = 0;
    } else {
        d.sun_history[static_cast<std::size_t>(d.history_head)] = d.sun_meas;
        d.history_head = (d.history_head + 1) % kMaxSpinWindow;
        d.history_filled = std::min(d.history_filled + 1, n);
    }
    SpinSpectrum& spectrum = spin_.get(d.sample_period, n);
    SpinRates rates;  // not valid until the window is full
    if (d.history_filled >= n) {
        // The analyser gets the window afresh from the history, which (unlike the analyser) is FMU state.
        spectrum.reset();
        for (std::int32_t i = n; i > 0; --i)
            spectrum.push(
                d.sun_history[static_cast<std::size_t>((d.history_head - i + kMaxSpinWindow) % kMaxSpinWindow)]);
        rates = spectrum.analyze();
    }
    d.spin_theta_dot = rates.valid ? rates.theta_dot : 0.0;
    d.spin_phi_dot = rates.valid ? rates.phi_dot : 0.0;
    d.spin_bin_width = spectrum.bin_width();
    d.spin_window_time = spectrum.window_seconds();
    d.spin_valid = rates.valid;
}

SpinWorkspace::~SpinWorkspace() = default;

SpinSpectrum& SpinWorkspace::get(double sample_period, std::int32_t window) {
    if (!spectrum_ || spectrum_->sample_period() != sample_period ||
        spectrum_->window() != static_cast<std::size_t>(window))
        spectrum_ = std::make_unique<SpinSpectrum>(sample_period, static_cast<std::size_t>(window));
    return *spectrum_;
}

void EstimatorBlock::configure() {
    config_ = config_from(data());
    filter_config_ = filter_config_from(data());
}

void EstimatorBlock::initialize(double t) {
    auto& d = data();
    // From scratch every time (initialize runs on each read in initialization mode): the sample at the
    // start time sees the inputs as they are when initialization ends.
    d.t_start = t;
    d.samples = 0;
    d.sun_state = {};
    d.rate_state = MeanAngularRate<double>(rate_config_from(d));
    d.history_head = 0;
    d.history_filled = 0;
    d.filter_state = {};
    d.rate_has_last = false;
    d.rate_step_turn = 0.0;
    d.set_reset = {};  // set at power-up, no offset known
    // No pulse at the start sample: during initialization a host re-reads the magnetometer after every
    // output change, so a pulse here would be in the reading this very sample takes as a set one.
    d.set_reset.since_pulse = -1;
    take_sample(t);
    d.next_index = 1;
}

fmu::EventUpdate EstimatorBlock::event_update(double t, bool time_event_due) {
    auto& d = data();
    if (!time_event_due || !fmu::reached(t, next_time_event())) return {};
    // A host that stepped over sample instants (it should not) gets the next one after t, not a burst;
    // a time beyond the count's limit is refused before anything changes.
    const std::int64_t next = fmu::next_instant_index(t, d.t_start, d.sample_period, d.next_index + 1, "sample clock");
    take_sample(t);
    d.next_index = next;
    return {};
}

// The fields outside the table, for a state restored from bytes (issue 14 case 8).
void EstimatorBlock::check_state() const {
    const auto& d = data();
    fmu::require_range(d.next_index, 0, fmu::max_instant_index, "next_index");
    fmu::require_range(d.history_head, 0, kMaxSpinWindow - 1, "history_head");
    fmu::require_range(d.history_filled, 0, kMaxSpinWindow, "history_filled");
    fmu::require_finite(d.t_start, "t_start");
    for (const auto& s : d.sun_history) fmu::require_finite(std::span<const double>(s.data(), s.size()), "sun_history");
    fmu::require_range(d.sun_state.cube_state, 0, 26, "sun_state.cube_state");
    fmu::require_range(d.sun_state.refusals, 0, std::numeric_limits<int>::max(), "sun_state.refusals");
    fmu::require_bool(d.sun_state.has_last, "sun_state.has_last");
    fmu::require_finite(std::span<const double>(d.sun_state.last_unit.data(), d.sun_state.last_unit.size()),
                        "sun_state.last_unit");
    if (!d.rate_state.consistent()) throw fmu::Error("restored FMU state: rate_state is inconsistent");
    const MekfState<double>& f = d.filter_state;
    fmu::require_range(f.stage, 0, 2, "filter_state.stage");
    fmu::require_range(f.refused_in_row, 0, std::numeric_limits<std::int32_t>::max(), "filter_state.refused_in_row");
    fmu::require_range(f.resets, 0, std::numeric_limits<std::int32_t>::max(), "filter_state.resets");
    const double filter_scalars[] = {f.q.x,       f.q.y,           f.q.z,           f.q.w,           f.q_first.x,
                                     f.q_first.y, f.q_first.z,     f.q_first.w,     f.omega[0],      f.omega[1],
                                     f.omega[2],  f.mag_offset[0], f.mag_offset[1], f.mag_offset[2], f.panel_scale,
                                     f.t_first,   f.t_last};
    fmu::require_finite(filter_scalars, "filter_state");
    fmu::require_finite(std::span<const double>(f.p.data(), f.p.size()), "filter_state.p");
    fmu::require_finite(std::span<const double>(d.rate_last_q.data(), d.rate_last_q.size()), "rate_last_q");
    fmu::require_finite(d.rate_last_t, "rate_last_t");
    fmu::require_bool(d.rate_has_last, "rate_has_last");
    fmu::require_finite(d.rate_step_turn, "rate_step_turn");
}

double EstimatorBlock::next_time_event() const {
    const auto& d = data();
    // From the integer count, not a running sum: instant k is as exact as one multiply-add can make it.
    return d.t_start + static_cast<double>(d.next_index) * d.sample_period;
}

}  // namespace attitude_estimator

FMU_BLOCK(attitude_estimator::EstimatorBlock)
