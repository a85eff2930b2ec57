// The face tests of the on-board fault detection (fault_detection.hpp): each face's current against the
// filter's prediction, and the per-axis Hall current against its face pair.
#include <algorithm>
#include <cmath>

#include "fault_detection_detail.hpp"

namespace attitude_estimator::fault_detail {

namespace {

// The irradiance the sun gives this sample, as a fraction of full sun, from the faces other than k (and
// not excluded) that the prediction puts well in the sun: the largest of their measured-to-predicted
// ratios, at most 1, or −1 when no such face can say. The largest, so that a second faulty (dark) face
// does not make the sun look dimmer than it is; albedo can only raise it, which makes the deficit test
// stricter, never laxer.
template <class T>
T irradiance_without(const std::array<T, 6>& measured, const std::array<T, 6>& predicted, std::uint8_t excluded,
                     std::size_t k, T min_predicted) {
    T f = T(-1);
    for (std::size_t j = 0; j < 6; ++j) {
        if (j == k || (excluded >> j & 1u) || predicted[j] < min_predicted) continue;
        f = std::max(f, measured[j] / predicted[j]);
    }
    return std::min(T(1), f);
}

}  // namespace

template <class T>
void face_tests(FaultDetectionState<T>& s, const FaultObservation<T>& o, const FaultDetectionConfig<T>& c, T dt) {
    std::array<T, 6> predicted{};
    if (o.predicted && o.response != nullptr) {
        for (std::size_t k = 0; k < 6; ++k) {
            const T cos_beta = (k % 2 == 0 ? T(1) : T(-1)) * o.sun_body[k / 2];
            predicted[k] = panel_response::response_from_cos(*o.response, cos_beta);
        }
    }
    const std::uint8_t excluded = excluded_faces(s);
    for (std::size_t k = 0; k < 6; ++k) {
        if (excluded >> k & 1u) continue;
        Outcome deficit = Outcome::not_applicable, excess = Outcome::not_applicable;
        if (o.predicted && o.response != nullptr) {
            const T f = irradiance_without(o.face_r, predicted, excluded, k, c.others_min_predicted);
            if (f >= c.others_min_irradiance && predicted[k] >= c.face_min_response)
                deficit = o.face_r[k] < f * predicted[k] - c.face_deficit ? Outcome::fail : Outcome::pass;
            // More than the full sun and albedo can give (at full irradiance: another face's fault must not
            // lower the bar).
            excess = o.face_r[k] > predicted[k] + c.face_excess ? Outcome::fail : Outcome::pass;
        }
        if (confirmed(s.face_failing[k][0], deficit, dt, c.confirm_time))
            declare(s.face_word[k], s.face_time[k], kFaultFaceDeficit, o.t);
        if (confirmed(s.face_failing[k][1], excess, dt, c.confirm_time))
            declare(s.face_word[k], s.face_time[k], kFaultFaceExcess, o.t);
    }
    if (!o.bus_available) return;
    for (std::size_t axis = 0; axis < 3; ++axis) {
        const std::size_t plus = 2 * axis, minus = plus + 1;
        if ((excluded >> plus & 1u) && (excluded >> minus & 1u)) continue;
        const T gap = std::abs(o.i_sh[axis] - (o.i_face[plus] - o.i_face[minus]));
        // Not a number fails as well: a channel that reads nothing sensible disagrees.
        const Outcome bus = gap <= c.bus_tolerance ? Outcome::pass : Outcome::fail;
        // Both faces of the pair share the evidence: the test cannot tell which channel is wrong.
        const bool plus_due = confirmed(s.face_failing[plus][2], bus, dt, c.confirm_time);
        const bool minus_due = confirmed(s.face_failing[minus][2], bus, dt, c.confirm_time);
        if (plus_due) declare(s.face_word[plus], s.face_time[plus], kFaultFaceBus, o.t);
        if (minus_due) declare(s.face_word[minus], s.face_time[minus], kFaultFaceBus, o.t);
    }
}

template void face_tests(FaultDetectionState<float>&, const FaultObservation<float>&,
                         const FaultDetectionConfig<float>&, float);
template void face_tests(FaultDetectionState<double>&, const FaultObservation<double>&,
                         const FaultDetectionConfig<double>&, double);

}  // namespace attitude_estimator::fault_detail
