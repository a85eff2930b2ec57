#include "attitude_estimator/fault_detection.hpp"

#include <algorithm>
#include <cmath>

namespace attitude_estimator {

namespace {

// One test's evidence: failing accumulates the sample period, a pass clears it, a sample where the test
// cannot run leaves it (a face turned away from the sun neither confirms nor clears an open string).
enum class Outcome { pass, fail, not_applicable };

template <class T>
bool confirmed(T& failing, Outcome outcome, T dt, T confirm_time) {
    if (outcome == Outcome::pass) failing = T(0);
    if (outcome == Outcome::fail) failing += dt;
    // Half a sample of slack: the n-th failing sample confirms when n·dt reaches the time, whatever the
    // rounding of the sum.
    return outcome == Outcome::fail && failing + T(0.5) * dt >= confirm_time;
}

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

template <class T>
void declare(std::uint32_t& word, T& time, std::uint32_t bit, T t) {
    if (word == 0) time = t;
    word |= bit;
}

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

// The strap test: with every axis read (none at a rail; an axis excluded for not flipping is still read) and a prediction, the measured half
// difference vector h = p (r_k − r_{k−1})/2S is S B (the whole field) when the strap works, S B less one
// component when a single axis is stuck, about nothing when the strap failed. Applied where the field left
// without its largest component is at least flip_min_field, so that a stuck axis always passes.
template <class T>
void strap_test(FaultDetectionState<T>& s, const FaultObservation<T>& o, const FaultDetectionConfig<T>& c, T dt,
                bool flip) {
    if (s.strap_failed) return;
    Outcome strap = Outcome::not_applicable;
    if (flip && o.predicted && !o.at_rail[0] && !o.at_rail[1] && !o.at_rail[2]) {
        const Vec3<T>& b = o.field_body;
        const T b2 = b[0] * b[0] + b[1] * b[1] + b[2] * b[2];
        const T largest = std::max(b[0] * b[0], std::max(b[1] * b[1], b[2] * b[2]));
        const T least_two = b2 - largest;  // T²
        const T min_field = o.field_calibrated ? c.flip_min_field_calibrated : c.flip_min_field;
        if (least_two >= min_field * min_field) {
            T h2 = T(0);
            for (std::size_t k = 0; k < 3; ++k) {
                const T h = (o.mag_reading[k] - s.last_reading[k]) / (T(2) * o.sensitivity);
                h2 += h * h;
            }
            strap = h2 >= c.flip_fraction * c.flip_fraction * least_two ? Outcome::pass : Outcome::fail;
        }
    }
    if (strap == Outcome::pass) s.strap_offset = o.mag_offset;
    if (!confirmed(s.strap_failing, strap, dt, c.confirm_time)) return;
    s.strap_failed = true;
    // The reading is S p B + v_os with p the polarity the film stayed in: its sign against the prediction.
    T along = T(0);
    for (std::size_t k = 0; k < 3; ++k) along += (o.mag_reading[k] - s.strap_offset[k]) * o.field_body[k];
    s.strap_polarity = along >= T(0) ? T(1) : T(-1);
    // The strap explains any axis declared for not flipping: read again, marked as the strap.
    for (std::size_t k = 0; k < 3; ++k) {
        s.axis_word[k] &= ~kFaultAxisNoFlip;
        s.axis_failing[k][1] = T(0);
        declare(s.axis_word[k], s.axis_time[k], kFaultAxisStrap, o.t);
    }
}

template <class T>
void axis_tests(FaultDetectionState<T>& s, const FaultObservation<T>& o, const FaultDetectionConfig<T>& c, T dt) {
    const std::uint8_t excluded = excluded_axes(s);
    // Two readings in a row of opposite polarity: p (r_k − r_{k−1}) / 2 = S B_k (the offset cancels).
    const bool flip = s.has_last && o.polarity * s.last_polarity < T(0) && o.t - s.last_t <= T(1.5) * o.sample_period;
    strap_test(s, o, c, dt, flip);
    // While the strap test fails (or once the strap is declared) no axis is blamed for not flipping.
    const bool strap_suspect = s.strap_failed || s.strap_failing > T(0);
    for (std::size_t k = 0; k < 3; ++k) {
        if (excluded >> k & 1u) continue;
        const Outcome rail = o.at_rail[k] ? Outcome::fail : Outcome::pass;
        if (confirmed(s.axis_failing[k][0], rail, dt, c.confirm_time))
            declare(s.axis_word[k], s.axis_time[k], kFaultAxisRail, o.t);
        Outcome flips = Outcome::not_applicable;
        const T expected = o.field_body[k];
        const T min_field = o.field_calibrated ? c.flip_min_field_calibrated : c.flip_min_field;
        if (flip && !strap_suspect && o.predicted && !o.at_rail[k] && std::abs(expected) >= min_field) {
            const T half = o.polarity * (o.mag_reading[k] - s.last_reading[k]) / (T(2) * o.sensitivity);
            const T along = expected > T(0) ? half : -half;
            flips = along >= c.flip_fraction * std::abs(expected) ? Outcome::pass : Outcome::fail;
        }
        if (confirmed(s.axis_failing[k][1], flips, dt, c.confirm_time))
            declare(s.axis_word[k], s.axis_time[k], kFaultAxisNoFlip, o.t);
    }
    s.last_reading = o.mag_reading;
    s.last_polarity = o.polarity;
    s.last_t = o.t;
    s.has_last = true;

    Outcome norm = Outcome::not_applicable;
    if (o.field_usable && o.field_ref_norm > T(0)) {
        const T n = std::sqrt(o.field[0] * o.field[0] + o.field[1] * o.field[1] + o.field[2] * o.field[2]);
        norm = std::abs(n - o.field_ref_norm) <= c.norm_tolerance ? Outcome::pass : Outcome::fail;
    }
    if (confirmed(s.norm_failing, norm, dt, c.confirm_time)) declare(s.norm_word, s.norm_time, 1u, o.t);
}

}  // namespace

template <class T>
void fault_detect(FaultDetectionState<T>& s, const FaultObservation<T>& o, const FaultDetectionConfig<T>& c) noexcept {
    if (!c.enabled) return;
    // Evidence accrues by the sample period (a sample after a gap counts as one sample).
    const T dt = o.sample_period;
    face_tests(s, o, c, dt);
    axis_tests(s, o, c, dt);
}

template <class T>
std::uint8_t excluded_faces(const FaultDetectionState<T>& s) noexcept {
    std::uint8_t mask = 0;
    for (std::size_t k = 0; k < 6; ++k)
        if (s.face_word[k] != 0) mask = static_cast<std::uint8_t>(mask | (1u << k));
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
