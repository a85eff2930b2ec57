// The fault detection's parameters and outputs (estimator_data.hpp) and their conversions to and from the
// core (fault_detection.hpp). FMI-free: the block and the firmware build it.
#include "attitude_estimator/estimator_data.hpp"

namespace attitude_estimator {

namespace {

// The magnetometer's further tests (frozen axis, spikes, bias jump).
template <class T>
void mag_fault_settings_from(const EstimatorData& d, FaultDetectionConfig<T>& c) {
    c.frozen_min_field = static_cast<T>(d.detect_frozen_min_field);
    c.frozen_tolerance = static_cast<T>(d.detect_frozen_tolerance);
    c.spike_sigma = static_cast<T>(d.detect_spike_sigma);
    c.spike_gate = static_cast<T>(d.detect_spike_gate);
    c.spike_window = static_cast<T>(d.detect_spike_window);
    c.spike_count = d.detect_spike_count;
    c.bias_window = static_cast<T>(d.detect_bias_window);
    c.bias_threshold = static_cast<T>(d.detect_bias_threshold);
    c.bias_noise_factor = static_cast<T>(d.detect_bias_noise_factor);
}

template <class T>
void store_mag_fault_outputs(EstimatorData& d, const OnboardOutputs<T>& out) {
    d.fault_mag_spikes = out.fault_mag_spikes;
    for (std::size_t k = 0; k < 3; ++k) d.fault_mag_bias[k] = static_cast<double>(out.fault_mag_bias[k]);
    d.fault_mag_strap_cleared_time = static_cast<double>(out.fault_mag_strap_cleared_time);
}

}  // namespace

template <class T>
FaultDetectionConfig<T> fault_settings_from(const EstimatorData& d) {
    FaultDetectionConfig<T> c{.enabled = d.detect_faults,
                              .confirm_time = static_cast<T>(d.detect_confirm_time),
                              .face_min_response = static_cast<T>(d.detect_face_min_response),
                              .face_deficit = static_cast<T>(d.detect_face_deficit),
                              .face_ratio_min_response = static_cast<T>(d.detect_face_ratio_min_response),
                              .face_ratio = static_cast<T>(d.detect_face_ratio),
                              .face_scale_min = static_cast<T>(d.detect_face_scale_min),
                              .face_dark_max = static_cast<T>(d.detect_face_dark_max),
                              .face_stuck_change = static_cast<T>(d.detect_face_stuck_change),
                              .face_stuck_tolerance = static_cast<T>(d.detect_face_stuck_tolerance),
                              .face_excess = static_cast<T>(d.detect_face_excess),
                              .face_direct_min = static_cast<T>(d.detect_face_direct_min),
                              .others_min_irradiance = static_cast<T>(d.detect_irradiance_min),
                              .others_min_predicted = T(0.3),
                              .bus_tolerance = static_cast<T>(d.detect_bus_tolerance),
                              .flip_min_field = static_cast<T>(d.detect_flip_min_field),
                              .flip_min_field_calibrated = static_cast<T>(d.detect_flip_min_field_calibrated),
                              .flip_fraction = static_cast<T>(d.detect_flip_fraction),
                              .norm_tolerance = static_cast<T>(d.detect_norm_tolerance)};
    mag_fault_settings_from(d, c);
    return c;
}

template <class T>
void store_fault_outputs(EstimatorData& d, const OnboardOutputs<T>& out) {
    for (std::size_t k = 0; k < 6; ++k) {
        d.fault_face[k] = static_cast<std::int32_t>(out.fault_face[k]);
        d.fault_face_time[k] = static_cast<double>(out.fault_face_time[k]);
    }
    for (std::size_t k = 0; k < 3; ++k) {
        d.fault_mag_axis[k] = static_cast<std::int32_t>(out.fault_mag_axis[k]);
        d.fault_mag_axis_time[k] = static_cast<double>(out.fault_mag_axis_time[k]);
    }
    d.fault_mag_norm = static_cast<std::int32_t>(out.fault_mag_norm);
    d.fault_mag_norm_time = static_cast<double>(out.fault_mag_norm_time);
    for (std::size_t k = 0; k < 6; ++k) d.fault_face_scale[k] = static_cast<double>(out.fault_face_scale[k]);
    store_mag_fault_outputs(d, out);
}

template FaultDetectionConfig<float> fault_settings_from(const EstimatorData&);
template FaultDetectionConfig<double> fault_settings_from(const EstimatorData&);
template void store_fault_outputs(EstimatorData&, const OnboardOutputs<float>&);
template void store_fault_outputs(EstimatorData&, const OnboardOutputs<double>&);

}  // namespace attitude_estimator
