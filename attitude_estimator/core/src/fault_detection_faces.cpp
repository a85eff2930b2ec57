// The face tests of the on-board fault detection (fault_detection.hpp): each face's current against the
// filter's prediction, and the per-axis Hall current against its face pair.
#include <algorithm>
#include <cmath>

#include "fault_detection_detail.hpp"

namespace attitude_estimator::fault_detail {

namespace {

// The face tests compare a reading with the response the filter's prediction gives, and the prediction is
// uncertain: the sun's direction in body axes has the attitude's error in it, σ per component
// (FaultObservation::sun_sigma, from the filter's covariance; 0 when exact). A test counts only what stands
// this many σ clear of it: the deficit test compares with the response at cos β − nσ (the least the face can
// be lit), the excess test with that at cos β + nσ, the stuck test with the change of the band's bounds.
// While the filter converges from an unknown attitude (σ of cos β ~0.5 in the first seconds) no face is
// tested; converged (~0.2°, σ ≈ 0.004) the band is ±0.015 wide. As many σ as the frozen test's.
template <class T>
constexpr T kFacePredictionSigmas = T(4);

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

// A confirmed deficit: a dead face (open string, switch stuck off, Hall channel at 0) is excluded; one that
// read a steady fraction of the light while failing (shadow, degradation) gets that fraction as its scale. The
// failing samples were read compensated by the scale declared before (a shadow that deepens), so the face
// now reads the product of the two: below face_scale_min that is a dead face too, however many steps it took
// (faults.toml runs 149 and 261: an appendage's shadow, whose fraction moves with the sun, scaled 0.30 and 9 s
// later 0.26 again, read 12 times its light whenever the appendage left the face in full sun).
template <class T>
void declare_deficit(FaultDetectionState<T>& s, std::size_t k, const FaultDetectionConfig<T>& c, T t) {
    const T n = s.deficit_ratio_count[k];
    const T ratio = n > T(0) ? s.deficit_ratio_sum[k] / n : T(0);
    if (s.face_scale[k] * ratio >= c.face_scale_min && ratio < T(1)) {
        s.face_scale[k] *= ratio;
        declare(s.face_word[k], s.face_time[k], kFaultFaceScale, t);
    } else {
        declare(s.face_word[k], s.face_time[k], kFaultFaceDeficit, t);
    }
    s.face_failing[k][0] = T(0);
    s.deficit_ratio_sum[k] = T(0);
    s.deficit_ratio_count[k] = T(0);
}

// The stuck test's outcome for face k reading r (compensated) where the predicted response lies within
// [lower, upper] (sunlit). What the light on the face has certainly done since the window opened: risen from
// below the least upper bound to above the greatest lower bound, or fallen the other way. A filter that
// corrects its attitude moves the prediction by about its σ, which the band takes out.
template <class T>
Outcome stuck_outcome(FaultDetectionState<T>& s, std::size_t k, T r, T lower, T upper,
                      const FaultDetectionConfig<T>& c) {
    if (!s.stuck_started[k] || std::abs(r - s.stuck_anchor[k]) > c.face_stuck_tolerance) {
        s.stuck_started[k] = true;
        s.stuck_anchor[k] = r;
        s.stuck_low[k] = upper;
        s.stuck_high[k] = lower;
        return Outcome::pass;
    }
    s.stuck_low[k] = std::min(s.stuck_low[k], upper);
    s.stuck_high[k] = std::max(s.stuck_high[k], lower);
    if (s.stuck_anchor[k] < c.face_dark_max) return Outcome::not_applicable;  // dark: the deficit test's
    return s.stuck_high[k] - s.stuck_low[k] >= c.face_stuck_change ? Outcome::fail : Outcome::not_applicable;
}

template <class T>
void face_tests(FaultDetectionState<T>& s, const FaultObservation<T>& o, const FaultDetectionConfig<T>& c, T dt) {
    // Each face's predicted response and its band (kFacePredictionSigmas): the response is monotone in cos β.
    std::array<T, 6> predicted{}, lower{}, upper{};
    if (o.predicted && o.response != nullptr) {
        for (std::size_t k = 0; k < 6; ++k) {
            const T cos_beta = face_cos(o.sun_body, k);
            const T margin = kFacePredictionSigmas<T> * o.sun_sigma[k / 2];
            predicted[k] = panel_response::response_from_cos(*o.response, cos_beta);
            lower[k] = panel_response::response_from_cos(*o.response, cos_beta - margin);
            upper[k] = panel_response::response_from_cos(*o.response, cos_beta + margin);
        }
    }
    // Each face's reading with its declared scale taken out (kFaultFaceScale).
    std::array<T, 6> r{};
    for (std::size_t k = 0; k < 6; ++k) r[k] = s.face_scale[k] > T(0) ? o.face_r[k] / s.face_scale[k] : o.face_r[k];
    const std::uint8_t excluded = excluded_faces(s);
    for (std::size_t k = 0; k < 6; ++k) {
        if (excluded >> k & 1u) continue;
        Outcome deficit = Outcome::not_applicable, excess = Outcome::not_applicable, stuck = Outcome::not_applicable;
        if (o.prediction_valid && o.response != nullptr) {
            // No other face well lit to tell the irradiance (one face toward the sun): full sun where the
            // on-board orbit says so (clear of the shadow by the penumbra's width and more).
            const T others = irradiance_without(r, predicted, excluded, k, c.others_min_predicted);
            const T f = others < T(0) && o.clear_of_shadow ? T(1) : others;
            if (f >= c.others_min_irradiance && !o.near_shadow) {
                // Two bars, either failing fails: far below a well-lit prediction (absolute margin), or a small
                // fraction of a prediction low in the sun once the calibrated attitude makes that trustworthy.
                // Both on the least the face can be lit (the band's lower bound); the scale's ratio below on the
                // prediction itself.
                const T expected = f * predicted[k];
                const T least = f * lower[k];
                const bool high = lower[k] >= c.face_min_response;
                const bool low = o.field_calibrated && least >= c.face_ratio_min_response;
                if (high || low) {
                    const bool fail = (high && r[k] < least - c.face_deficit) || (low && r[k] < c.face_ratio * least);
                    deficit = fail ? Outcome::fail : Outcome::pass;
                }
                // On the prediction alone: the irradiance (the other faces' best ratio) jumps when one of
                // them is faulty; in penumbra the reading moves and so passes.
                stuck = stuck_outcome(s, k, r[k], lower[k], upper[k], c);
                if (deficit == Outcome::pass) {
                    s.deficit_ratio_sum[k] = T(0);
                    s.deficit_ratio_count[k] = T(0);
                } else if (deficit == Outcome::fail && expected >= c.others_min_predicted) {
                    s.deficit_ratio_sum[k] += r[k] / expected;
                    s.deficit_ratio_count[k] += T(1);
                }
            }
            // More than the full sun and albedo can give (at full irradiance: another face's fault must not
            // lower the bar). On the reading as it is: a lower scale (a shadow) takes none of the albedo, so the
            // compensated reading carries albedo / scale.
            excess = o.face_r[k] > upper[k] + c.face_excess ? Outcome::fail : Outcome::pass;
        }
        if (confirmed(s.face_failing[k][0], deficit, dt, c.confirm_time)) declare_deficit(s, k, c, o.t);
        if (confirmed(s.face_failing[k][1], excess, dt, c.confirm_time))
            declare(s.face_word[k], s.face_time[k], kFaultFaceExcess, o.t);
        if (confirmed(s.stuck_failing[k], stuck, dt, c.confirm_time))
            declare(s.face_word[k], s.face_time[k], kFaultFaceStuck, o.t);
        // In the umbra nothing lights a face: current there is the Hall channel's own (offset, stuck).
        const Outcome dark = !o.umbra                 ? Outcome::not_applicable
                             : r[k] > c.face_dark_max ? Outcome::fail
                                                      : Outcome::pass;
        if (confirmed(s.dark_failing[k], dark, dt, c.confirm_time))
            declare(s.face_word[k], s.face_time[k], kFaultFaceDark, o.t);
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

namespace attitude_estimator {

template <class T>
T shadow_depth_km(const Vec3<T>& position_km, const Vec3<T>& sun_unit) noexcept {
    constexpr T kEarthRadiusKm = T(6378.137);
    const T along = position_km[0] * sun_unit[0] + position_km[1] * sun_unit[1] + position_km[2] * sun_unit[2];
    if (!(along < T(0))) return T(-1e9);  // on the sun's side (or no position)
    T off2 = T(0);
    for (std::size_t i = 0; i < 3; ++i) {
        const T d = position_km[i] - along * sun_unit[i];
        off2 += d * d;
    }
    return kEarthRadiusKm - std::sqrt(off2);
}

template float shadow_depth_km(const Vec3<float>&, const Vec3<float>&) noexcept;
template double shadow_depth_km(const Vec3<double>&, const Vec3<double>&) noexcept;

}  // namespace attitude_estimator
