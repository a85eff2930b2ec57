// The firmware bench's case for harness/systems/leo_orbit.ssd's on-board computer, in a header of its own so
// that a host test (tests/e2e/e2e_firmware_bench_config_test.cpp) can hold it against the system as bundled:
// the bench states the instructions per sample of the bundled configuration, and a hand copy of a system's
// values drifts when the system is retuned.
#pragma once

#include "attitude_estimator/estimator_data.hpp"

namespace firmware {

// What the bench sets before every case's own values: the firmware computes in float and runs no spin
// spectrum (the seed's FFT, which leo_orbit does not run either).
inline void bench_case_start(attitude_estimator::EstimatorData& d) {
    d = attitude_estimator::EstimatorData{};
    d.precision = attitude_estimator::Precision::single_precision;
    d.spin_window = 0;
}

// leo_orbit's on-board computer as bundled (issue 39; the values of harness/systems/leo_orbit.ssd's `est` and
// of the system parameters connected to it): on-board references, set/reset every sample, the filter
// propagating the rate with the 3U's inertia, the uplinked dipole's, the gravity gradient's and the drag's
// torques (the box, its centre of mass and drag coefficient), the noise as tuned with the drag on, the sun's
// correlated errors per method, the in-flight calibration started from the uplinked ground calibration;
// `detect` the fault detection (on as bundled). `torques_only`: the former case (no drag, the noise before
// the drag's tuning, no ground calibration), kept to say what the drag and the calibration add.
inline void leo_orbit_3u(attitude_estimator::EstimatorData& d, bool detect, bool torques_only) {
    using namespace attitude_estimator;
    d.filter = FilterKind::mekf;
    d.reference_source = ReferenceSource::onboard;
    d.tle_elements = {2461118.5, 14.98524078, 0.0012, 64.9, 3.1277, 90.376, 275.3137, 1.5e-4};
    d.mag_set_reset_samples = 1;
    d.inertia = {0.0405, 0.0, 0.0, 0.0, 0.0398, 0.0, 0.0, 0.0, 0.0072};
    d.filter_dipole = {0.0, 0.0, 0.05};
    d.filter_gravity_gradient = true;
    d.detect_faults = detect;
    if (torques_only) {
        d.filter_torque_noise = 3e-8;
        return;
    }
    // The system gives the truth's element set and the uplink's age; the computer derives its own, a day older
    // (the former case above had that older set by hand and no age).
    d.tle_elements = {2461119.5, 14.98524078, 0.0012, 64.9, 0.0, 90.0, 270.0, 1.5e-4};
    d.uplink_age = 86400.0;
    d.angular_response = AngularResponse::kelly;
    d.inertia = {0.0405, 0.00015, -0.0002, 0.00015, 0.0398, 0.0001, -0.0002, 0.0001, 0.0072};
    d.field_degree = 8;
    d.filter_sun_sigma = 0.5;
    d.filter_mag_sigma = 100e-6;
    d.filter_mag_hard_iron = 10e-6;
    d.filter_mag_ref_sigma = 0.0;
    d.filter_mag_ref_correlation = 150.0;  // the reference's error derived for this orbit (reference_error.hpp)
    d.filter_attitude_noise = 1e-6;
    d.filter_rate_noise = 5e-7;
    d.filter_start_rate = 0.0873;
    d.mag_calibration = true;
    d.mag_prior_offset_sigma = 0.5e-6;
    d.mag_prior_field_sigma = 8e-6;
    d.mag_prior_field_fluctuation = 100e-9;
    d.mag_prior_field_correlation = 200.0;
    d.mag_prior_dipole = {0.0, 0.0, 0.05};
    // The strings' field taken out (the magnetometer's default layout, connected from the system's parameters).
    d.mag_string_field = true;
    d.mag_string_loop_center = {0.05, 0.0,   0.0, -0.05, 0.0, 0.0,  0.0, 0.05, 0.0,
                                0.0,  -0.05, 0.0, 0.0,   0.0, 0.17, 0.0, 0.0,  -0.17};
    d.mag_string_loop_side_a = {0.0, 0.0, 0.3, 0.0,  0.0, 0.3, 0.0,  0.0, 0.3,
                                0.0, 0.0, 0.3, 0.08, 0.0, 0.0, 0.08, 0.0, 0.0};
    d.mag_string_loop_side_b = {0.0,    -0.005, 0.0, 0.0, 0.005, 0.0, 0.005, 0.0,    0.0,
                                -0.005, 0.0,    0.0, 0.0, 0.005, 0.0, 0.0,   -0.005, 0.0};
    d.filter_mag_sigma_calibrated = 1.1e-6;
    d.filter_mag_sigma_eclipse = 0.75e-6;
    d.filter_sun_sigma_method = {0.094, 0.088, 0.069, 0.051};
    d.filter_sun_correlation = {200.0, 31.0, 12.0, 12.0};
    d.filter_sun_turn = true;
    d.filter_torque_noise = 1.5e-8;
    d.filter_drag = true;
    d.filter_watch_time = 300.0;
    d.filter_watch_sun = true;
    d.filter_watch_gate = 8.0;
    d.filter_hold_field_axis = true;
    d.body_size = {0.1, 0.1, 0.34};
    d.centre_of_mass = {0.004, -0.003, -0.012};
    d.drag_coefficient = 2.2;
    d.filter_drag_density_sigma = 0.0;
    d.filter_drag_correlation = 60.0;
}

}  // namespace firmware
