// What the fault-detection core tests share (fault_detection_test.cpp, fault_detection_faces_test.cpp,
// fault_detection_mag_test.cpp): the bundled sample rate, the detection switched on with its defaults, and
// a lit scene's face observation: cosine panels reading r_k of full sun, the plant's Hall differences.
#pragma once

#include <array>
#include <cstddef>

#include "attitude_estimator/fault_detection.hpp"
#include "panel_response/kelly.hpp"

namespace attitude_estimator::test {

inline constexpr double kPeriod = 0.05;  // s: 20 Hz, the bundled sample rate

template <class T>
FaultDetectionConfig<T> enabled() {
    FaultDetectionConfig<T> c;
    c.enabled = true;
    return c;
}

// The faces' observation at t: the filter predicts the sun at `sun` (body axes), face k reads r[k] of full
// sun (i_norm amperes at full sun), and the per-axis Hall differential currents are the plant's
// i_sh[k] = i_face[2k] − i_face[2k+1].
template <class T>
FaultObservation<T> face_observation(const panel_response::Response<T>& response, const Vec3<T>& sun,
                                     const std::array<T, 6>& r, T i_norm, T t) {
    FaultObservation<T> o;
    o.t = t;
    o.sample_period = T(kPeriod);
    o.response = &response;
    o.predicted = true;
    o.prediction_valid = true;
    o.sun_body = sun;
    o.face_r = r;
    for (std::size_t k = 0; k < 6; ++k) o.i_face[k] = r[k] * i_norm;
    for (std::size_t k = 0; k < 3; ++k) o.i_sh[k] = o.i_face[2 * k] - o.i_face[2 * k + 1];
    o.bus_available = true;
    return o;
}

}  // namespace attitude_estimator::test
