// What the two halves of the on-board fault detection share (fault_detection_faces.cpp,
// fault_detection_mag.cpp): a test's outcome, its confirmation over time and a declaration. Internal to
// the core; float or double, no heap, no exceptions.
#pragma once

#include <cstdint>

#include "attitude_estimator/fault_detection.hpp"

namespace attitude_estimator::fault_detail {

// One test's evidence: failing accumulates the sample period, a pass clears it, a sample where the test
// cannot run leaves it (a face turned away from the sun neither confirms nor clears an open string).
enum class Outcome { pass, fail, not_applicable };

template <class T>
inline bool confirmed(T& failing, Outcome outcome, T dt, T confirm_time) {
    if (outcome == Outcome::pass) failing = T(0);
    if (outcome == Outcome::fail) failing += dt;
    // Half a sample of slack: the n-th failing sample confirms when n·dt reaches the time, whatever the
    // rounding of the sum.
    return outcome == Outcome::fail && failing + T(0.5) * dt >= confirm_time;
}

template <class T>
inline void declare(std::uint32_t& word, T& time, std::uint32_t bit, T t) {
    if (word == 0) time = t;
    word |= bit;
}

// The face tests (deficit, excess, bus) of one sample.
template <class T>
void face_tests(FaultDetectionState<T>& s, const FaultObservation<T>& o, const FaultDetectionConfig<T>& c, T dt);
// The magnetometer tests (strap, rail, flip, field norm) of one sample.
template <class T>
void axis_tests(FaultDetectionState<T>& s, const FaultObservation<T>& o, const FaultDetectionConfig<T>& c, T dt);

extern template void face_tests(FaultDetectionState<float>&, const FaultObservation<float>&,
                                const FaultDetectionConfig<float>&, float);
extern template void face_tests(FaultDetectionState<double>&, const FaultObservation<double>&,
                                const FaultDetectionConfig<double>&, double);
extern template void axis_tests(FaultDetectionState<float>&, const FaultObservation<float>&,
                                const FaultDetectionConfig<float>&, float);
extern template void axis_tests(FaultDetectionState<double>&, const FaultObservation<double>&,
                                const FaultDetectionConfig<double>&, double);

}  // namespace attitude_estimator::fault_detail
