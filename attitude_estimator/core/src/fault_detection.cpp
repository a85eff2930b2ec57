#include "attitude_estimator/fault_detection.hpp"

#include "fault_detection_detail.hpp"

namespace attitude_estimator {

template <class T>
void fault_detect(FaultDetectionState<T>& s, const FaultObservation<T>& o, const FaultDetectionConfig<T>& c) noexcept {
    if (!c.enabled) return;
    // Evidence accrues by the sample period (a sample after a gap counts as one sample).
    const T dt = o.sample_period;
    fault_detail::face_tests(s, o, c, dt);
    fault_detail::axis_tests(s, o, c, dt);
}

template <class T>
std::uint8_t excluded_faces(const FaultDetectionState<T>& s) noexcept {
    std::uint8_t mask = 0;
    for (std::size_t k = 0; k < 6; ++k)
        // A face with a lower scale alone is compensated, not excluded.
        if ((s.face_word[k] & ~kFaultFaceScale) != 0u) mask = static_cast<std::uint8_t>(mask | (1u << k));
    return mask;
}

template <class T>
std::uint8_t excluded_axes(const FaultDetectionState<T>& s) noexcept {
    std::uint8_t mask = 0;
    for (std::size_t k = 0; k < 3; ++k)
        if (s.axis_word[k] & (kFaultAxisRail | kFaultAxisNoFlip)) mask = static_cast<std::uint8_t>(mask | (1u << k));
    return mask;
}

template void fault_detect(FaultDetectionState<float>&, const FaultObservation<float>&,
                           const FaultDetectionConfig<float>&) noexcept;
template void fault_detect(FaultDetectionState<double>&, const FaultObservation<double>&,
                           const FaultDetectionConfig<double>&) noexcept;
template std::uint8_t excluded_faces(const FaultDetectionState<float>&) noexcept;
template std::uint8_t excluded_faces(const FaultDetectionState<double>&) noexcept;
template std::uint8_t excluded_axes(const FaultDetectionState<float>&) noexcept;
template std::uint8_t excluded_axes(const FaultDetectionState<double>&) noexcept;

}  // namespace attitude_estimator
