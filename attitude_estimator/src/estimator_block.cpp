#include "attitude_estimator/estimator_block.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "attitude_estimator/spin_spectrum.hpp"
#include "fmu/errors.hpp"
#include "fmu/instant_clock.hpp"
#include "fmu/state_check.hpp"
#include "orbit/element_plausibility.hpp"
#include "orbit/tle.hpp"

namespace attitude_estimator {

namespace {

// The computer's state must travel with the FMU state as bytes.
static_assert(std::is_trivially_copyable_v<OnboardState<double>> && std::is_trivially_copyable_v<OnboardState<float>>);

}  // namespace

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
        .range(0.0, 90.0)
        .applies_when("angular_response", {"kelly"});
    t.parameter("kelly_value", &D::kelly_value, "1",
                "Kelly table: relative response at kelly_angle, the first 1, the second the cosine of its angle "
                "(default ssr_plant's)")
        .range(0.0, 1.0)
        .applies_when("angular_response", {"kelly"});
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
        .range(1e-6, 1.0)
        .applies_when("sun_method", {"cones"});
    t.parameter("cube_max_step", &D::cube_max_step, "rad",
                "cones: a transition the panel-cube graph forbids is accepted when the sun moved less than this "
                "since the last sample (0: the seed's graph alone; fast spin: about 1.5 x the turn per sample)")
        .range(0.0, 3.14159)
        .applies_when("sun_method", {"cones"});
    t.parameter(
         "orbit_altitude", &D::orbit_altitude, "m",
         "cones with reference_source = inputs: altitude of the orbit over a 6371 km Earth, for the Earth-albedo "
         "model's view of the Earth (default 570 km, seed 004); onboard: not used, the computer's own element set "
         "gives it (SGP4's mean semi-major axis)")
        .range(100e3, 100e6)
        .applies_when("sun_method", {"cones"});
    t.parameter("cone_fit_tolerance", &D::cone_fit_tolerance, "1",
                "cones: an albedo-model fit is accepted below this RMS misfit of the relative face responses; 0 "
                "turns the model off (face rejection only)")
        .range(0.0, 1.0)
        .applies_when("sun_method", {"cones"});
    t.parameter("cone_albedo_max", &D::cone_albedo_max, "1",
                "cones: largest albedo the model may fit on a face squarely toward the Earth (fraction of full sun)")
        .range(0.0, 1.0)
        .applies_when("sun_method", {"cones"});
    t.parameter("spin_window", &D::spin_window, "",
                "Samples in the spin-rate FFT window (0: no spin-rate analysis); at most 2048")
        .range(0.0, static_cast<double>(kMaxSpinWindow));
    t.parameter("rate_interval", &D::rate_interval, "s",
                "Shortest time between the two attitudes of one mean-rate increment (004 eq. 4; 004 samples once "
                "a minute, 2 s or more keeps attitude noise from dominating)")
        .min(0.0);
    t.parameter("rate_window", &D::rate_window, "", "Mean-rate increments averaged (1 = 004 eq. 4 alone), 1 to 64")
        .range(1.0, static_cast<double>(kMaxRateWindow));

    t.choice("precision", &D::precision,
             {{"double", Precision::double_precision}, {"float", Precision::single_precision}},
             "Arithmetic of the on-board computer: double, or float as the firmware on a Cortex-M4F computes "
             "(attitude_estimator/firmware: the same source; the spin-rate FFT stays in double)");
    t.choice("filter", &D::filter, {{"none", FilterKind::none}, {"mekf", FilterKind::mekf}},
             "Recursive attitude filter beside the single-frame estimate: none, or mekf (multiplicative "
             "extended Kalman filter with rate, magnetometer-offset and panel-scale states; docs/filter.md)");
    t.parameter("filter_sun_sigma", &D::filter_sun_sigma, "rad",
                "mekf: 1-sigma error of one sun vector per axis (noise and the sun method's model error)")
        .range(1e-6, 1.0)
        .applies_when("filter", {"mekf"});
    t.parameter("filter_mag_sigma", &D::filter_mag_sigma, "T",
                "mekf: 1-sigma error of one field vector per axis (noise, quantization, field-model error)")
        .range(1e-10, 1e-4)
        .applies_when("filter", {"mekf"});
    t.parameter("filter_sun_sigma_method", &D::filter_sun_sigma_method, "rad",
                "mekf: 1-sigma error of one sun vector per axis for each sun_method (difference, "
                "inverse_response, cones, three_faces); 0 = filter_sun_sigma")
        .range(0.0, 100.0)
        .applies_when("filter", {"mekf"});
    t.parameter("filter_sun_correlation", &D::filter_sun_correlation, "s",
                "mekf: correlation time of the sun vector's error for each sun_method (same order): an update "
                "counts as white noise of sigma^2 max(1, 2 tau / dt); 0 = white")
        .range(0.0, 1e5)
        .applies_when("filter", {"mekf"});
    t.parameter("filter_sun_turn", &D::filter_sun_turn, "",
                "mekf: the sun vector's error correlated over one radian of the tumble, tau = 1/|rate| (the "
                "filter's rate), at most filter_sun_correlation (false: tau = filter_sun_correlation)")
        .applies_when("filter", {"mekf"});
    t.parameter("filter_mag_ref_sigma", &D::filter_mag_ref_sigma, "T",
                "mekf: 1-sigma error per axis of the reference field model (adds to filter_mag_sigma in quadrature)")
        .range(0.0, 1e-4)
        .applies_when("filter", {"mekf"});
    t.parameter("filter_mag_ref_rms", &D::filter_mag_ref_rms, "T",
                "mekf: rms per axis of the reference field's error along the orbit, correlated over "
                "filter_mag_ref_correlation; 0 = with the on-board references, what the on-board model's field_degree "
                "leaves of IGRF-14 at the on-board orbit's semi-major axis (the degrees above it, by their spectrum; "
                "docs/filter.md)")
        .range(0.0, 1e-4)
        .applies_when("filter", {"mekf"});
    t.parameter("filter_mag_ref_correlation", &D::filter_mag_ref_correlation, "s",
                "mekf: correlation time of the reference field's error along the orbit; each field update weighs "
                "it as rms^2 (2 tau / dt) T / (T + tau), T the filter's memory (its attitude variance over the rate "
                "the process noise adds to it), in quadrature with filter_mag_ref_sigma; 0 = not modelled")
        .range(0.0, 1e5)
        .applies_when("filter", {"mekf"});
    t.calculated_parameter("filter_mag_ref_rms_used", &D::filter_mag_ref_rms_used, "T",
                           "mekf: the reference field's error rms per axis the filter weighs: filter_mag_ref_rms, or "
                           "what the ground derives for the on-board orbit when it is 0 (0 without "
                           "filter_mag_ref_correlation)");
    t.parameter("filter_mag_ref_tilt", &D::filter_mag_ref_tilt, "rad",
                "mekf: the turn of the reference field about the orbit's normal that the on-board set's along-track "
                "lag makes (about twice the lag's angle), a bias of the attitude no measurement of the field removes, "
                "considered along the on-board orbit's normal in the covariance the filter reports and judges its "
                "validity by, not in its weights; 0 = with the on-board references and filter_mag_ref_correlation, "
                "what the ground derives for the on-board orbit (the lag's least-squares turn over one period; "
                "docs/filter.md, the section on the reference's tilt)")
        .range(0.0, 0.1)
        .applies_when("filter", {"mekf"});
    t.calculated_parameter("filter_mag_ref_tilt_used", &D::filter_mag_ref_tilt_used, "rad",
                           "mekf: the reference's tilt the filter adds to its covariance: filter_mag_ref_tilt, or what "
                           "the ground derives when it is 0");
    t.parameter("filter_mag_sigma_calibrated", &D::filter_mag_sigma_calibrated, "T",
                "mekf: filter_mag_sigma once the in-flight magnetometer calibration applies (0 = filter_mag_sigma)")
        .range(0.0, 1e-4)
        .applies_when("filter", {"mekf"});
    t.parameter("filter_mag_sigma_eclipse", &D::filter_mag_sigma_eclipse, "T",
                "mekf: filter_mag_sigma_calibrated in a sample without a sun vector (eclipse: no panel currents' "
                "field at the magnetometer; 0 = filter_mag_sigma_calibrated)")
        .range(0.0, 1e-4)
        .applies_when("filter", {"mekf"});
    t.parameter("filter_mag_hard_iron", &D::filter_mag_hard_iron, "T",
                "mekf: 1-sigma per axis of the spacecraft's own field at the magnetometer (the uplinked prior of its "
                "hard iron) until the in-flight calibration applies; the offset state then estimates it fixed in "
                "body axes (0 = not modelled)")
        .range(0.0, 1e-4)
        .applies_when("filter", {"mekf"});
    t.parameter("filter_start_rate", &D::filter_start_rate, "rad/s",
                "mekf: 1-sigma per axis of the body rate the spacecraft can have at the start (its design's largest "
                "tumble): the rate differenced from the first two single-frame attitudes is fused with zero +- "
                "this (0 = not: the difference alone, 1.4 rad/s 1-sigma at 20 Hz)")
        .range(0.0, 10.0)
        .applies_when("filter", {"mekf"});
    t.parameter("filter_rate_noise", &D::filter_rate_noise, "rad/s",
                "mekf: 1-sigma unpredictable change of the body rate over 1 s (a random walk: it grows as the "
                "square root of time; the rate random-walk density in rad/s per root second)")
        .range(0.0, 10.0)
        .applies_when("filter", {"mekf"});
    t.parameter("filter_attitude_noise", &D::filter_attitude_noise, "rad",
                "mekf: 1-sigma attitude drift over 1 s that the rate state does not explain (random walk)")
        .range(0.0, 1.0)
        .applies_when("filter", {"mekf"});
    t.parameter("filter_offset", &D::filter_offset, "",
                "mekf: estimate the magnetometer's offset (3 states; its sign follows the set/reset polarity)")
        .applies_when("filter", {"mekf"});
    t.parameter("filter_scale", &D::filter_scale, "",
                "mekf: estimate a common scale error of the panels' current normalization from the face "
                "currents and correct i_face_norm/i_sc_norm with it (face-based sun methods)")
        .applies_when("filter", {"mekf"});
    t.parameter("filter_face_sigma", &D::filter_face_sigma, "1",
                "mekf: 1-sigma error of one face's relative response in the panel-scale update (noise, albedo)")
        .range(1e-6, 1.0)
        .applies_when("filter", {"mekf"});
    t.parameter("inertia", &D::inertia, "kg.m2",
                "mekf: inertia matrix, body axes, row-major; all zero (default) = kinematic rate model, else "
                "Euler's equations propagate the rate, with the torques of filter_dipole and "
                "filter_gravity_gradient")
        .applies_when("filter", {"mekf"});
    t.parameter("filter_dipole", &D::filter_dipole, "A.m2",
                "mekf with inertia: the spacecraft's residual magnetic dipole, body axes (its magnetic budget, "
                "uplinked): the filter propagates the rate with its torque m x B (B the reference field in the "
                "body); 0 (default): not modelled")
        .applies_when("filter", {"mekf"});
    t.parameter("filter_torque_noise", &D::filter_torque_noise, "N.m",
                "mekf with inertia: the torques the filter does not model (drag, solar pressure, the models' "
                "errors) as white noise, 1-sigma (N m s) of the angular momentum they add over 1 s (N m per "
                "sqrt(Hz)); rate noise through the inertia, "
                "added to filter_rate_noise")
        .range(0.0, 1.0)
        .applies_when("filter", {"mekf"});
    t.parameter("filter_drag", &D::filter_drag, "",
                "mekf with inertia: the filter propagates the rate with the drag torque of the box (body_size, "
                "centre_of_mass, drag_coefficient) in the wind of the on-board orbit (reference_source onboard "
                "only), at its table's density times filter_drag_density_scale")
        .applies_when("filter", {"mekf"});
    t.parameter("body_size", &D::body_size, "m",
                "mekf drag: the spacecraft's box as the computer knows it (its design, uplinked), edges along body "
                "x, y, z; 0 (default): not modelled")
        .range(0.0, 10.0)
        .applies_when("filter", {"mekf"});
    t.parameter("centre_of_mass", &D::centre_of_mass, "m",
                "mekf drag: the centre of mass from the box's geometric centre, body axes, as the computer knows it")
        .range(-5.0, 5.0)
        .applies_when("filter", {"mekf"});
    t.parameter("drag_coefficient", &D::drag_coefficient, "1",
                "mekf drag: the drag coefficient of a face (free-molecular flat plate about 2.2) as the computer "
                "knows it; 0 (default): not modelled")
        .range(0.0, 10.0)
        .applies_when("filter", {"mekf"});
    t.parameter("filter_drag_density_scale", &D::filter_drag_density_scale, "1",
                "mekf drag: the computer's density against its table (CIRA-72 at mean solar activity, Vallado "
                "2013 table 8-4): its belief of the solar activity, the named on-board error of the density (the "
                "truth flies the table itself)")
        .range(1e-3, 1e3)
        .applies_when("filter", {"mekf"});
    t.parameter("filter_drag_density_sigma", &D::filter_drag_density_sigma, "1",
                "mekf drag: relative 1-sigma uncertainty of the density (a factor of several over the solar "
                "cycle at 400 km); the modelled drag torque times it enters the rate noise as white torque noise "
                "over filter_drag_correlation")
        .range(0.0, 100.0)
        .applies_when("filter", {"mekf"});
    t.parameter("filter_drag_correlation", &D::filter_drag_correlation, "s",
                "mekf drag: the time over which the drag torque's error stays put in body axes (white noise of "
                "the same information: (sigma |tau|)^2 2 tau_c per second); 0: no drag noise")
        .range(0.0, 1e5)
        .applies_when("filter", {"mekf"});
    t.parameter("filter_gravity_gradient", &D::filter_gravity_gradient, "",
                "mekf with inertia: the filter propagates the rate with the gravity-gradient torque (from the "
                "on-board orbit: reference_source onboard only)")
        .applies_when("filter", {"mekf"});
    t.parameter("mag_calibration", &D::mag_calibration, "",
                "Calibrate the magnetometer in flight (scale, non-orthogonality, offset against the reference "
                "field's magnitude; Alonso and Shuster 2002) and correct the field with it once solved");
    t.parameter("mag_calibration_sigma", &D::mag_calibration_sigma, "T",
                "mag_calibration: 1-sigma error of one field reading per axis (weights the equations)")
        .range(1e-10, 1e-4)
        .applies_when("mag_calibration", {"true"});
    t.parameter("mag_calibration_every", &D::mag_calibration_every, "",
                "mag_calibration: samples between two calibration equations")
        .range(1.0, 1e6)
        .applies_when("mag_calibration", {"true"});
    t.parameter("mag_calibration_min", &D::mag_calibration_min, "",
                "mag_calibration: equations before the first solution is applied")
        .range(10.0, 1e8)
        .applies_when("mag_calibration", {"true"});
    t.parameter("mag_prior_offset_sigma", &D::mag_prior_offset_sigma, "T",
                "mag_calibration: 1-sigma per axis of the ground calibration of the spacecraft's own field at the "
                "magnetometer (uplinked): applied from the first sample, weighed with this until the in-flight "
                "calibration refines it (0 = no ground calibration: the field is weighed as uncalibrated)")
        .range(0.0, 1e-4)
        .applies_when("mag_calibration", {"true"});
    t.parameter("mag_prior_field_sigma", &D::mag_prior_field_sigma, "T",
                "mag_prior_offset_sigma > 0: the field's 1-sigma per axis in the filter while the ground "
                "calibration applies (white-equivalent: its scale and non-orthogonality are not calibrated yet; "
                "0 = filter_mag_sigma_calibrated)")
        .range(0.0, 1e-4)
        .applies_when("mag_calibration", {"true"});
    t.parameter("mag_prior_field_fluctuation", &D::mag_prior_field_fluctuation, "T",
                "mag_prior_offset_sigma > 0: instead of mag_prior_field_sigma (above 0), the field's error as it "
                "turns through the uncalibrated sensor, 1-sigma per axis correlated over one radian of the tumble "
                "(1/|rate|, at most mag_prior_field_correlation), weighed as white noise sigma sqrt(2 tau / step)")
        .range(0.0, 1e-5)
        .applies_when("mag_calibration", {"true"});
    t.parameter("mag_prior_field_correlation", &D::mag_prior_field_correlation, "s",
                "mag_prior_field_fluctuation > 0: the longest correlation of that error (a slow tumble: the orbit's "
                "own turn of the field)")
        .range(1.0, 3600.0)
        .applies_when("mag_calibration", {"true"});
    t.parameter("mag_prior_dipole", &D::mag_prior_dipole, "A.m2",
                "mag_prior_offset_sigma > 0: the spacecraft's residual dipole, body axes (the scenario's magnetic "
                "budget: connect the system's dipole_moment), whose field at the sensor the ground calibration "
                "measured")
        .range(-10.0, 10.0)
        .applies_when("mag_calibration", {"true"});
    t.parameter("mag_prior_dipole_position", &D::mag_prior_dipole_position, "m",
                "mag_prior_offset_sigma > 0: where the residual dipole sits, body axes (the magnetometer's "
                "dipole_position)")
        .range(-10.0, 10.0)
        .applies_when("mag_calibration", {"true"});
    t.parameter("mag_prior_sensor_position", &D::mag_prior_sensor_position, "m",
                "mag_prior_offset_sigma > 0 or mag_string_field: where the magnetometer sits, body axes (the "
                "magnetometer's sensor_position)")
        .range(-10.0, 10.0);
    t.parameter("mag_prior_offset_error", &D::mag_prior_offset_error, "T",
                "mag_prior_offset_sigma > 0: the ground calibration's error, body axes: it gives the dipole's field "
                "at the sensor plus this (default 0.4, -0.3, 0.5 uT: about 1 sigma of a clean-room measurement)")
        .range(-1e-4, 1e-4)
        .applies_when("mag_calibration", {"true"});
    t.parameter("mag_string_field", &D::mag_string_field, "",
                "Take the field of the panels' string currents out of the magnetometer's reading before the "
                "calibration, the fault tests and the filter: each face's measured current (i_face) times its "
                "string loop's field per ampere at mag_prior_sensor_position (mag_string_loop_*, uplinked), "
                "times 1 + mag_string_field_error (docs/filter.md)");
    t.parameter("mag_string_loop_center", &D::mag_string_loop_center, "m",
                "mag_string_field: each face's string loop (faces +x, -x, +y, -y, +z, -z, 3 numbers each), body "
                "axes: its centre (the magnetometer's string_loop_center)")
        .range(-10.0, 10.0)
        .applies_when("mag_string_field", {"true"});
    t.parameter("mag_string_loop_side_a", &D::mag_string_loop_side_a, "m",
                "mag_string_field: each loop's first side, along which the current runs first (the "
                "magnetometer's string_loop_side_a)")
        .range(-10.0, 10.0)
        .applies_when("mag_string_field", {"true"});
    t.parameter("mag_string_loop_side_b", &D::mag_string_loop_side_b, "m",
                "mag_string_field: each loop's second side: a positive current's moment is I (side_a x side_b); "
                "zero sides: no loop (the magnetometer's string_loop_side_b)")
        .range(-10.0, 10.0)
        .applies_when("mag_string_field", {"true"});
    t.parameter("mag_string_field_error", &D::mag_string_field_error, "1",
                "mag_string_field: the relative error of the strings' field per ampere the computer is given (the "
                "loops' geometry as built against as drawn): it uses the loops' field times 1 + this (default "
                "0.05)")
        .range(-0.5, 0.5)
        .applies_when("mag_string_field", {"true"});
    t.parameter("filter_reset_after", &D::filter_reset_after, "",
                "mekf: samples in a row whose every update fails the innovation test before the filter resets "
                "to the single-frame attitude (without one, in eclipse, it coasts, not valid, until one comes)")
        .range(1.0, 1e6)
        .applies_when("filter", {"mekf"});
    t.parameter("filter_watch_time", &D::filter_watch_time, "s",
                "mekf: averaging time of the divergence watch (the field's innovation in inertial axes against "
                "its expected size; docs/filter.md); 0: off")
        .range(0.0, 1e6)
        .applies_when("filter", {"mekf"});
    t.parameter("filter_watch_gate", &D::filter_watch_gate, "1",
                "mekf: the watch's squared average over its expected size above which the filter is lost and "
                "resets to the single-frame attitude (counted in filter_resets)")
        .range(1.0, 1e6)
        .applies_when("filter", {"mekf"});
    t.parameter("filter_watch_sun", &D::filter_watch_sun, "",
                "mekf: the divergence watch also on the sun: its squared innovation over what its own sigma and the "
                "covariance allow, averaged over filter_watch_time from each start until the filter has been valid "
                "that long; above filter_watch_gate the filter restarts (it sees a turn about the field, which the "
                "field's watch cannot; docs/filter.md). false: the field's watch alone")
        .applies_when("filter", {"mekf"});
    t.parameter("filter_hold_field_axis", &D::filter_hold_field_axis, "",
                "mekf: from each start, hold the attitude's variance about the field's direction at no less than "
                "what the sun alone has told of it until 3 sigma of that is within the validity bound (the field's "
                "own turn cannot tell that axis from a rate error; docs/filter.md). false: off")
        .applies_when("filter", {"mekf"});

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

    t.output("mag_cal_valid", &D::mag_cal_valid, "", "mag_calibration: a calibration is solved and applied")
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
    t.output("attitude_cov_sqrt", &D::attitude_cov_sqrt, "rad",
             "mekf: lower Cholesky factor L of the filter's attitude error covariance P = L L' (body axes), its "
             "lower triangle by rows: L11, L21, L22, L31, L32, L33; |inv(L) dtheta|^2 / 3 is the normalized error "
             "per degree of freedom of an error dtheta")
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
    // The reference vectors (onboard_references.hpp, docs/onboard_references.md).
    t.choice("reference_source", &D::reference_source,
             {{"inputs", ReferenceSource::inputs}, {"onboard", ReferenceSource::onboard}},
             "Where the reference vectors come from: inputs (sun_ref, mag_ref, sun_distance: a GPS receiver with "
             "its own models, or the truth-fed study), or onboard (the computer's own SGP4 orbit from tle_line1/2, "
             "almanac sun and IGRF-14 to field_degree, at its clock from the clock_epoch parameters)");
    t.parameter("tle_line1", &D::tle_line1, "",
                "onboard: line 1 of the computer's own two-line element set (it may be older than the truth's)");
    t.parameter("tle_line2", &D::tle_line2, "", "onboard: line 2 of the computer's own two-line element set");
    t.parameter("tle_elements", &D::tle_elements, "1",
                "onboard, when tle_line1 and tle_line2 are empty: the element set as numbers in its own units: "
                "epoch (Julian date, UTC), mean motion (rev/day), eccentricity, inclination, node, argument of "
                "perigee, mean anomaly (deg), B* (1/Earth radii); the firmware gets its set this way");
    t.parameter("field_degree", &D::field_degree, "",
                "onboard: degree of the on-board IGRF-14 field model, 1 (tilted dipole) to 13 (the whole model)")
        .range(1.0, static_cast<double>(kFieldMaxDegree));
    t.parameter("clock_epoch_year", &D::clock_epoch_year, "",
                "onboard: the computer's clock, UTC at t = 0: year (IGRF-14 covers 2025.0 to 2030.0)")
        .range(2025.0, 2030.0);
    t.parameter("clock_epoch_month", &D::clock_epoch_month, "", "onboard: the computer's clock at t = 0: month")
        .range(1.0, 12.0);
    t.parameter("clock_epoch_day", &D::clock_epoch_day, "", "onboard: the computer's clock at t = 0: day of the month")
        .range(1.0, 31.0);
    t.parameter("clock_epoch_hour", &D::clock_epoch_hour, "", "onboard: the computer's clock at t = 0: hour")
        .range(0.0, 23.0);
    t.parameter("clock_epoch_minute", &D::clock_epoch_minute, "", "onboard: the computer's clock at t = 0: minute")
        .range(0.0, 59.0);
    t.parameter("clock_epoch_second", &D::clock_epoch_second, "s",
                "onboard: the computer's clock at t = 0: second of the minute")
        .range(0.0, 60.999);
    t.parameter("clock_offset", &D::clock_offset, "s",
                "onboard: the computer's clock error: at t = 0 it reads clock_epoch_* plus this (connect clock_epoch_* "
                "to the scenario's epoch)")
        .range(-86400.0, 86400.0);
    t.parameter("uplink_age", &D::uplink_age, "s",
                "onboard: the computer's element set is the given one (tle_line1/2 or tle_elements: connect the "
                "scenario's set) made this much older along SGP4's secular rates (orbit/element_age.hpp); 0: the "
                "given set as it is")
        .range(0.0, orbit::kMaxElementSetAgeDays * 86400.0);
    t.parameter("reference_period", &D::reference_period, "s",
                "onboard: time between two evaluations of the on-board orbit, sun and field models (each sample "
                "interpolates between the two around it)")
        .range(0.01, 600.0);
    // (The on-board orbit's position and sun distance are not outputs: the block has 90, a bridge frame carries
    // up to 128.)
    t.output("ref_sun", &D::ref_sun, "1",
             "The sun reference (J2000) the last sample used: sun_ref, or the on-board one")
        .discrete()
        .depends_on({});
    t.output("ref_mag", &D::ref_mag, "T",
             "The field reference (J2000) the last sample used: mag_ref, or the on-board model's")
        .discrete()
        .depends_on({});
    declare_fault_variables(t);
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

namespace {
// How far kelly_value[2] may lie from the cosine of kelly_angle[2]: half a unit of the third decimal, to
// which the Kelly table is tabulated (000 fig. 4: 0.866 at 30 deg).
constexpr double kelly_join_tolerance = 5e-4;

// The clock's epoch day must exist (30 February would be 2 March to the Julian-day formula).
void check_calendar_day(std::int32_t year, std::int32_t month, std::int32_t day) {
    const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
    constexpr int days[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    const int last = days[month - 1] + (month == 2 && leap ? 1 : 0);
    if (day > last)
        throw fmu::Error("clock_epoch_day " + std::to_string(day) + " does not exist in month " +
                         std::to_string(month) + " of " + std::to_string(year));
}
}  // namespace

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
        // panel_response::table holds the cosine up to the second knot and takes its exact value there: a
        // tabulated value other than that cosine (to the table's three decimals) would be silently replaced.
        const double join = std::cos(d.kelly_angle[1] * std::numbers::pi / 180.0);
        if (!(std::abs(d.kelly_value[1] - join) <= kelly_join_tolerance))
            throw fmu::Error("kelly_value[2] must be cos(kelly_angle[2]) = " + std::to_string(join) + " within " +
                             std::to_string(kelly_join_tolerance) +
                             " (kelly_join_tolerance: the cosine holds up to the second knot)");
    }
    if (d.reference_source == ReferenceSource::onboard) {
        check_calendar_day(d.clock_epoch_year, d.clock_epoch_month, d.clock_epoch_day);
        if (d.tle_line1.view().empty() && d.tle_line2.view().empty() && !(d.tle_elements[0] > 0.0))
            throw fmu::Error(
                "reference_source = onboard needs the computer's element set: tle_line1 and tle_line2, "
                "or its numbers in tle_elements (tle_elements[1], the epoch, is 0)");
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
    if (d.precision == Precision::single_precision) {
        store_outputs(
            d, onboard_sample(d.onboard_float, onboard_inputs_from<float>(d), settings_float_, static_cast<float>(t)));
    } else {
        store_outputs(d, onboard_sample(d.onboard, onboard_inputs_from<double>(d), settings_, t));
    }
    update_spin();
}

void EstimatorBlock::update_spin() {
    auto& d = data();
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
    SpinSpectrum& spectrum = spin_.spectrum();
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

void SpinWorkspace::configure(double sample_period, std::int32_t window) {
    if (window == 0)
        spectrum_.reset();
    else if (!spectrum_ || spectrum_->sample_period() != sample_period ||
             spectrum_->window() != static_cast<std::size_t>(window))
        spectrum_ = std::make_unique<SpinSpectrum>(sample_period, static_cast<std::size_t>(window));
}

// 1 mm, as the magnetometer's min_source_distance: closer, a point dipole describes nothing real.
constexpr double min_prior_dipole_distance = 1e-3;  // m
// The same for a string loop's wires and the sensor (mag_string_field).
constexpr double min_string_wire_distance = 1e-3;  // m

void EstimatorBlock::configure() {
    auto& d = data();
    d.parsed_elements = {};
    if (d.reference_source == ReferenceSource::onboard) {
        const bool text = !d.tle_line1.view().empty() || !d.tle_line2.view().empty();
        if (text) {
            // The element set's text is parsed by the orbit library (it checks columns, checksums and ranges).
            try {
                d.parsed_elements = orbit::elements_of(orbit::parse_tle(d.tle_line1.view(), d.tle_line2.view()));
            } catch (const orbit::TleError& e) {
                throw fmu::Error(std::string("reference_source = onboard: tle_line1/tle_line2: ") + e.what());
            }
        }
        if (!text) {
            // The numbers get the checks the parser makes on the text.
            try {
                (void)orbit::checked_tle_from_elements(d.tle_elements);
            } catch (const orbit::TleElementsError& e) {
                throw fmu::Error(std::string("reference_source = onboard: tle_elements") + e.what());
            }
        }
        const orbit::Tle tle = onboard_element_set(d);
        OnboardReferenceConfig<double> check;
        const orbit::Sgp4Status status =
            make_reference_config(check, onboard_clock_epoch(d), tle.mean_elements<double>(), tle.epoch_jd_utc,
                                  d.field_degree, d.reference_period);
        if (status != orbit::Sgp4Status::ok)
            throw fmu::Error(std::string("reference_source = onboard: the element set") +
                             (d.uplink_age > 0.0 ? " made uplink_age older" : "") + ": " + orbit::describe(status));
        // The truth's rule (orbit/element_plausibility.hpp): the set within a year of the clock, SGP4 still
        // propagating there.
        const std::string problem =
            orbit::element_set_problem_at(tle, check.clock.epoch_julian_date, "the computer's clock at t = 0");
        if (!problem.empty())
            throw fmu::Error("reference_source = onboard: " + problem +
                             (d.uplink_age > 0.0 ? " (the given set made uplink_age older)" : ""));
    }
    if (d.mag_calibration && d.mag_prior_offset_sigma > 0.0) {
        // The point dipole's field holds away from the dipole (the magnetometer's own min_source_distance).
        double gap2 = 0.0;
        for (std::size_t i = 0; i < 3; ++i) {
            const double g = d.mag_prior_sensor_position[i] - d.mag_prior_dipole_position[i];
            gap2 += g * g;
        }
        if (!(std::sqrt(gap2) >= min_prior_dipole_distance))
            throw fmu::Error("mag_prior_sensor_position is " + std::to_string(std::sqrt(gap2) * 1e3) +
                             " mm from mag_prior_dipole_position: at least " +
                             std::to_string(min_prior_dipole_distance * 1e3) +
                             " mm (min_prior_dipole_distance) for a point dipole's field");
    }
    if (d.mag_string_field) {
        // The thin-wire field holds away from the wires (the magnetometer's own min_source_distance).
        static constexpr const char* faces[kStringFaces] = {"+x", "-x", "+y", "-y", "+z", "-z"};
        for (std::size_t f = 0; f < kStringFaces; ++f) {
            const double gap = string_loop_wire_distance(string_loop(d, f), d.mag_prior_sensor_position);
            if (!(gap >= min_string_wire_distance))
                throw fmu::Error(std::string("mag_string_field: the string loop of face ") + faces[f] + " passes " +
                                 std::to_string(gap * 1e3) + " mm from mag_prior_sensor_position: at least " +
                                 std::to_string(min_string_wire_distance * 1e3) +
                                 " mm (min_string_wire_distance) for a thin wire's field");
        }
    }
    settings_ = onboard_settings_from<double>(data());
    settings_float_ = onboard_settings_from<float>(data());
    d.filter_mag_ref_rms_used = settings_.mekf.mag_ref_correlation > 0.0 ? settings_.mekf.mag_ref_rms : 0.0;
    d.filter_mag_ref_tilt_used = settings_.mekf.mag_ref_tilt;
    spin_.configure(d.sample_period, d.spin_window);
}

void EstimatorBlock::initialize(double t) {
    auto& d = data();
    // From scratch every time (initialize runs on each read in initialization mode): the sample at the
    // start time sees the inputs as they are when initialization ends.
    d.t_start = t;
    d.history_head = 0;
    d.history_filled = 0;
    onboard_start(d.onboard, settings_);
    onboard_start(d.onboard_float, settings_float_);
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

namespace {

template <class T>
void check_onboard_state(const OnboardState<T>& s, const std::string& name) {
    fmu::require_range(s.sun.cube_state, 0, 26, name + ".sun.cube_state");
    fmu::require_range(s.sun.refusals, 0, std::numeric_limits<int>::max(), name + ".sun.refusals");
    fmu::require_bool(s.sun.has_last, name + ".sun.has_last");
    for (const T x : s.sun.last_unit) fmu::require_finite(static_cast<double>(x), name + ".sun.last_unit");
    if (!s.rate.consistent()) throw fmu::Error("restored FMU state: " + name + ".rate is inconsistent");
    const MekfState<T>& f = s.filter;
    fmu::require_range(f.stage, 0, 2, name + ".filter.stage");
    fmu::require_range(f.refused_in_row, 0, std::numeric_limits<std::int32_t>::max(), name + ".filter.refused_in_row");
    fmu::require_range(f.resets, 0, std::numeric_limits<std::int32_t>::max(), name + ".filter.resets");
    const T filter_scalars[] = {f.q.x,       f.q.y,           f.q.z,           f.q.w,           f.q_first.x,
                                f.q_first.y, f.q_first.z,     f.q_first.w,     f.omega[0],      f.omega[1],
                                f.omega[2],  f.mag_offset[0], f.mag_offset[1], f.mag_offset[2], f.panel_scale,
                                f.t_first,   f.t_last,        f.memory};
    for (const T x : filter_scalars) fmu::require_finite(static_cast<double>(x), name + ".filter");
    for (const T x : f.p) fmu::require_finite(static_cast<double>(x), name + ".filter.p");
    if (f.memory < T(0)) throw fmu::Error("restored FMU state: " + name + ".filter.memory is negative");
    const MekfWatch<T>& w = f.watch;
    const MekfSunWatch<T>& sw = f.sun_watch;
    const T watch[] = {w.sum[0], w.sum[1], w.sum[2], w.weight, w.noise,     w.spread,
                       w.ratio,  w.t,      sw.ratio, sw.t,     sw.valid_for};
    for (const T x : watch) fmu::require_finite(static_cast<double>(x), name + ".filter.watch");
    for (const T x : f.sun_information) fmu::require_finite(static_cast<double>(x), name + ".filter.sun_information");
    fmu::require_range(f.field_axis_seen, 0, 1, name + ".filter.field_axis_seen");
    const T last[] = {s.last_q.x, s.last_q.y, s.last_q.z, s.last_q.w, s.last_t, s.step_turn};
    for (const T x : last) fmu::require_finite(static_cast<double>(x), name + ".last_q/last_t/step_turn");
    fmu::require_bool(s.has_last, name + ".has_last");
    fmu::require_range(s.samples, 0, std::numeric_limits<std::int32_t>::max(), name + ".samples");
    const SetResetState<T>& r = s.set_reset;
    const T set_reset[] = {r.polarity,           r.offset[0],          r.offset[1],          r.offset[2],
                           r.last_reading[0],    r.last_reading[1],    r.last_reading[2],    r.last_polarity,
                           r.earlier_reading[0], r.earlier_reading[1], r.earlier_reading[2], r.earlier_polarity};
    for (const T x : set_reset) fmu::require_finite(static_cast<double>(x), name + ".set_reset");
    fmu::require_bool(s.references.started, name + ".references.started");
    for (const ReferenceKnot<T>* k : {&s.references.before, &s.references.after}) {
        fmu::require_bool(k->valid, name + ".references.valid");
        const T knot[] = {k->t,        k->sun[0],   k->sun[1],      k->sun[2],      k->sun_distance, k->field[0],
                          k->field[1], k->field[2], k->position[0], k->position[1], k->position[2]};
        for (const T x : knot) fmu::require_finite(static_cast<double>(x), name + ".references");
    }
}

}  // namespace

// The fields outside the table, for a state restored from bytes (issue 14 case 8).
void EstimatorBlock::check_state() const {
    const auto& d = data();
    fmu::require_range(d.next_index, 0, fmu::max_instant_index, "next_index");
    fmu::require_range(d.history_head, 0, kMaxSpinWindow - 1, "history_head");
    fmu::require_range(d.history_filled, 0, kMaxSpinWindow, "history_filled");
    fmu::require_finite(d.t_start, "t_start");
    for (const auto& s : d.sun_history) fmu::require_finite(std::span<const double>(s.data(), s.size()), "sun_history");
    check_onboard_state(d.onboard, "onboard");
    check_onboard_state(d.onboard_float, "onboard_float");
}

double EstimatorBlock::next_time_event() const {
    const auto& d = data();
    // From the integer count, not a running sum: instant k is as exact as one multiply-add can make it.
    return d.t_start + static_cast<double>(d.next_index) * d.sample_period;
}

}  // namespace attitude_estimator

FMU_BLOCK(attitude_estimator::EstimatorBlock)
