// The fault detection's variables in the estimator's table (fault_detection.hpp, docs/faults.md).
#include "attitude_estimator/estimator_block.hpp"

namespace attitude_estimator {

namespace {

// The magnetometer's further tests and recovery (frozen axis, spikes, bias jump, strap recovery).
void declare_mag_fault_variables(fmu::Table<EstimatorData>& t) {
    using D = EstimatorData;
    t.parameter("detect_frozen_min_field", &D::detect_frozen_min_field, "T",
                "detect_faults: an axis too weak for the flip test is tested for not changing at all across a "
                "set/reset flip (stuck at its last value) where the calibrated predicted field along it is at "
                "least this and 4 sigma of the prediction's own uncertainty")
        .range(1e-8, 1e-3);
    t.parameter("detect_frozen_tolerance", &D::detect_frozen_tolerance, "T",
                "detect_faults: an axis whose half set/reset difference is below this fails the frozen test")
        .range(1e-10, 1e-5);
    t.parameter("detect_spike_sigma", &D::detect_spike_sigma, "T",
                "detect_faults: how far a healthy magnetometer axis strays from the filter's prediction besides "
                "the attitude's own uncertainty (noise, field model truncation, calibration residual)")
        .range(1e-9, 1e-3);
    t.parameter("detect_spike_gate", &D::detect_spike_gate, "1",
                "detect_faults: an axis reading further than this many sigma from the prediction is an outlier "
                "(one or two in a row: a spike, that sample's field is skipped)")
        .range(1.0, 1000.0);
    t.parameter("detect_spike_window", &D::detect_spike_window, "s",
                "detect_faults: spikes are counted over windows this long")
        .range(0.1, 86400.0);
    t.parameter("detect_spike_count", &D::detect_spike_count, "",
                "detect_faults: this many spikes on an axis within one window declare it spiking (bit 8; not "
                "excluded)")
        .range(1, 1000000);
    t.parameter("detect_bias_window", &D::detect_bias_window, "s",
                "detect_faults: the bias-jump test averages each axis' innovation (measured minus predicted "
                "field) over this time (exponential window)")
        .range(1.0, 86400.0);
    t.parameter("detect_bias_threshold", &D::detect_bias_threshold, "T",
                "detect_faults: an axis whose mean innovation exceeds this fails the bias-jump test; confirmed, "
                "the calibration's offset takes the jump and re-learns it (bit 16; not excluded)")
        .range(1e-9, 1e-3);
    t.parameter("detect_bias_noise_factor", &D::detect_bias_noise_factor, "1",
                "detect_faults: after a bias jump the filter's field noise is raised by this factor until the "
                "calibration has re-learnt its offset")
        .range(1.0, 1000.0);
    t.output("fault_mag_bias", &D::fault_mag_bias, "T",
             "detect_faults: the bias-jump test's mean innovation per magnetometer axis (measured minus "
             "predicted field, sensor axes)")
        .discrete()
        .depends_on({});
    t.output("fault_mag_strap_cleared_time", &D::fault_mag_strap_cleared_time, "s",
             "detect_faults: when a failed set/reset strap (bit 4) was last seen working again, its readings "
             "flipping with the commanded polarity for detect_confirm_time: set/reset resumes (-1: never)")
        .discrete()
        .depends_on({});
    t.output("fault_mag_spikes", &D::fault_mag_spikes, "",
             "detect_faults: one-sample outliers (spikes) skipped so far per magnetometer axis")
        .discrete()
        .depends_on({});
}

}  // namespace

void declare_fault_variables(fmu::Table<EstimatorData>& t) {
    using D = EstimatorData;
    t.parameter("detect_faults", &D::detect_faults, "",
                "Detect, isolate and exclude faulty faces and magnetometer axes (per-face innovation, face "
                "pair against i_sh, rails, set/reset flip, field norm); the predictive tests need filter = mekf");
    t.parameter("detect_confirm_time", &D::detect_confirm_time, "s",
                "detect_faults: a test must fail this long, without a pass between, before a fault is declared")
        .range(0.0, 3600.0);
    t.parameter("detect_face_min_response", &D::detect_face_min_response, "1",
                "detect_faults: a face is tested where its predicted relative response is at least this")
        .range(0.05, 1.0);
    t.parameter("detect_face_deficit", &D::detect_face_deficit, "1",
                "detect_faults: a face reading this far below its predicted relative response fails")
        .range(0.01, 1.0);
    // Panel faults (issue 28): the ratio, scale, dark and stuck tests.
    t.parameter("detect_face_ratio_min_response", &D::detect_face_ratio_min_response, "1",
                "detect_faults: once the in-flight calibration applies, a face is also tested where the irradiance "
                "times its predicted relative response is at least this")
        .range(0.01, 1.0);
    t.parameter("detect_face_ratio", &D::detect_face_ratio, "1",
                "detect_faults: ... and fails reading below this fraction of that (an open string reads 0)")
        .range(0.0, 1.0);
    t.parameter("detect_face_scale_min", &D::detect_face_scale_min, "1",
                "detect_faults: a confirmed deficit whose mean measured/expected ratio is at least this is a lower "
                "scale (shadow, degradation): the face is read divided by it (fault_face_scale), not excluded; a face "
                "whose scales together fall below it is excluded")
        .range(0.0, 1.0);
    t.parameter("detect_face_dark_max", &D::detect_face_dark_max, "1",
                "detect_faults: a face reading more than this fraction of full sun while the on-board orbit puts "
                "the spacecraft deep in the umbra fails (a Hall offset or a stuck channel)")
        .range(0.001, 1.0);
    t.parameter("detect_face_stuck_change", &D::detect_face_stuck_change, "1",
                "detect_faults: a sunlit face whose reading does not move while its predicted response spans this "
                "fails (a stuck Hall channel)")
        .range(0.01, 1.0);
    t.parameter("detect_face_stuck_tolerance", &D::detect_face_stuck_tolerance, "1",
                "detect_faults: a reading within this (relative to full sun) of where it started has not moved")
        .range(1e-5, 0.5);
    t.parameter("detect_face_excess", &D::detect_face_excess, "1",
                "detect_faults: a face reading this far above its predicted relative response fails (albedo "
                "adds up to about 0.4 on a face toward nadir)")
        .range(0.01, 10.0);
    t.parameter("detect_face_direct_min", &D::detect_face_direct_min, "1",
                "detect_faults: a face reading more than this has the sun itself on it (albedo adds up to about "
                "0.4), so its opposite face is dark: an excluded face is known dark without the filter's "
                "prediction (after a reset, the sun from the faces left)")
        .range(0.3, 1.0);
    t.parameter("detect_irradiance_min", &D::detect_irradiance_min, "1",
                "detect_faults: faces are tested while the other faces show at least this fraction of the sun "
                "predicted on them (not in eclipse or deep penumbra)")
        .range(0.01, 1.0);
    t.parameter("detect_bus_tolerance", &D::detect_bus_tolerance, "A",
                "detect_faults: largest |i_sh[k] - (i_face[2k-1] - i_face[2k])| of a healthy face pair")
        .range(1e-6, 10.0);
    t.parameter("detect_flip_min_field", &D::detect_flip_min_field, "T",
                "detect_faults: an axis' set/reset flip is tested where the predicted field along it is at least "
                "this")
        .range(1e-7, 1e-3);
    t.parameter("detect_flip_min_field_calibrated", &D::detect_flip_min_field_calibrated, "T",
                "detect_faults: the same (flip and strap tests) once a calibration's hard iron is in the predicted "
                "field: the ground calibration's from the first sample, else the in-flight one's once it applies")
        .range(1e-7, 1e-3);
    t.parameter("detect_flip_fraction", &D::detect_flip_fraction, "1",
                "detect_faults: an axis whose reading flips by less than this fraction of the predicted field "
                "fails")
        .range(0.01, 1.0);
    t.parameter("detect_norm_tolerance", &D::detect_norm_tolerance, "T",
                "detect_faults: largest | |B| - |B_ref| | of a healthy field")
        .range(1e-8, 1e-3);
    t.output("fault_face", &D::fault_face, "",
             "detect_faults: fault word per face (+x, -x, +y, -y, +z, -z), 0 healthy; bits 1 reads below the "
             "prediction, 2 above it, 4 disagrees with its axis' i_sh, 8 reads a steady fraction of its light "
             "(compensated by fault_face_scale, not excluded), 16 reads current in the umbra, 32 does not move "
             "while its light does; every bit but 8 excludes the face")
        .discrete()
        .depends_on({});
    t.output("fault_face_scale", &D::fault_face_scale, "1",
             "detect_faults: the scale a face with bit 8 (reads a steady fraction of its light) is divided by; 1 "
             "otherwise")
        .discrete()
        .depends_on({});
    t.output("fault_face_time", &D::fault_face_time, "s",
             "detect_faults: when each face's fault was declared (-1: never)")
        .discrete()
        .depends_on({});
    t.output("fault_mag_axis", &D::fault_mag_axis, "",
             "detect_faults: fault word per magnetometer axis, 0 healthy; bits 1 at a rail, 2 does not flip with "
             "the set/reset polarity (both exclude the axis), 4 the set/reset strap failed (read in its stuck "
             "polarity), 8 spiking (outliers skipped), 16 a bias jump (the calibration re-learns its offset)")
        .discrete()
        .depends_on({});
    t.output("fault_mag_axis_time", &D::fault_mag_axis_time, "s",
             "detect_faults: when each axis' fault was declared (-1: never)")
        .discrete()
        .depends_on({});
    t.output("fault_mag_norm", &D::fault_mag_norm, "",
             "detect_faults: 1 once the measured field's magnitude has disagreed with the reference's (names no "
             "axis, excludes nothing)")
        .discrete()
        .depends_on({});
    t.output("fault_mag_norm_time", &D::fault_mag_norm_time, "s",
             "detect_faults: when fault_mag_norm was declared (-1: never)")
        .discrete()
        .depends_on({});
    declare_mag_fault_variables(t);
}

}  // namespace attitude_estimator
