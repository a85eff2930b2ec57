// The magnetometer tests of the on-board fault detection (fault_detection.hpp): rail, set/reset flip per
// axis, the strap common to the three axes, and the field norm.
#include <algorithm>
#include <cmath>

#include "fault_detection_detail.hpp"

namespace attitude_estimator::fault_detail {

namespace {

// The frozen test's prediction must stand this many of its own σ clear of zero.
template <class T>
constexpr T kFrozenSigmas = T(4);

// The flip and strap tests' bar: the calibrated one once the spacecraft's own field is in the prediction.
template <class T>
T flip_min_field(const FaultObservation<T>& o, const FaultDetectionConfig<T>& c) {
    return o.field_calibrated || o.field_offset_known ? c.flip_min_field_calibrated : c.flip_min_field;
}

// The strap test: with every axis read (none at a rail; an axis excluded for not flipping is still read) and a prediction, the measured half
// difference vector h = p (r_k − r_{k−1})/2S is S B (the whole field) when the strap works, S B less one
// component when a single axis is stuck, about nothing when the strap failed. Applied where the field left
// without its largest component is at least flip_min_field, so that a stuck axis always passes.
template <class T>
Outcome strap_outcome(const FaultDetectionState<T>& s, const FaultObservation<T>& o, const FaultDetectionConfig<T>& c,
                      bool flip);

// After a declared strap failure: the readings paired by the commanded polarity flip again (the strap test
// passes) for the confirmation time without a failure in between: the strap works again.
template <class T>
void strap_recovery(FaultDetectionState<T>& s, const FaultObservation<T>& o, const FaultDetectionConfig<T>& c, T dt) {
    const bool flip = s.has_last && o.commanded_polarity * s.last_commanded_polarity < T(0) &&
                      o.t - s.last_t <= T(1.5) * o.sample_period;
    const Outcome strap = strap_outcome(s, o, c, flip);
    if (strap == Outcome::fail) s.strap_passing = T(0);
    if (strap != Outcome::pass) return;
    s.strap_passing += dt;
    if (s.strap_passing + T(0.5) * dt < c.confirm_time) return;
    s.strap_failed = false;
    s.strap_passing = T(0);
    s.strap_failing = T(0);
    s.strap_cleared_time = o.t;
}

template <class T>
void strap_test(FaultDetectionState<T>& s, const FaultObservation<T>& o, const FaultDetectionConfig<T>& c, T dt,
                bool flip) {
    if (s.strap_failed) {
        strap_recovery(s, o, c, dt);
        return;
    }
    const Outcome strap = strap_outcome(s, o, c, flip);
    if (strap == Outcome::pass) s.strap_offset = o.mag_offset;
    if (!confirmed(s.strap_failing, strap, dt, c.confirm_time)) return;
    s.strap_failed = true;
    s.strap_passing = T(0);
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
Outcome strap_outcome(const FaultDetectionState<T>& s, const FaultObservation<T>& o, const FaultDetectionConfig<T>& c,
                      bool flip) {
    Outcome strap = Outcome::not_applicable;
    if (flip && o.predicted && !o.at_rail[0] && !o.at_rail[1] && !o.at_rail[2]) {
        const Vec3<T>& b = o.field_body;
        const T b2 = b[0] * b[0] + b[1] * b[1] + b[2] * b[2];
        const T largest = std::max(b[0] * b[0], std::max(b[1] * b[1], b[2] * b[2]));
        const T least_two = b2 - largest;  // T²
        const T min_field = flip_min_field(o, c);
        if (least_two >= min_field * min_field) {
            T h2 = T(0);
            for (std::size_t k = 0; k < 3; ++k) {
                const T h = (o.mag_reading[k] - s.last_reading[k]) / (T(2) * o.sensitivity);
                h2 += h * h;
            }
            strap = h2 >= c.flip_fraction * c.flip_fraction * least_two ? Outcome::pass : Outcome::fail;
        }
    }
    return strap;
}

// The half difference p (r_k − r_{k−1})/2S below which axis k did not move (flip and frozen tests): the
// tolerance, or the converter's steps a stuck reading can still toggle (FaultDetectionConfig::frozen_steps).
template <class T>
T still_bar(const FaultObservation<T>& o, const FaultDetectionConfig<T>& c, std::size_t k) {
    return std::max(c.frozen_tolerance, c.frozen_steps * o.mag_reading_step[k] / (T(2) * o.sensitivity));
}

// At most this many outliers in a row are spikes; on an axis declared spiking, this many more (half a
// second at 20 Hz: frequent spikes come two or three in a row now and then, a change of the field stays).
constexpr std::int32_t kSpikeMaxRun = 2;
constexpr std::int32_t kSpikeMaxRunSpiking = 10;

// The spike test of one axis (fault_detection.hpp, FaultDetectionConfig::spike_*).
template <class T>
void spike_test(FaultDetectionState<T>& s, const FaultObservation<T>& o, const FaultDetectionConfig<T>& c,
                std::size_t k) {
    if (!(o.predicted && o.field_calibrated && o.field_measured && o.field_ref_norm > T(0)) || o.at_rail[k]) {
        s.outlier_run[k] = 0;
        return;
    }
    const T d = o.field_uncalibrated[k] - o.field_body[k];
    const T bound2 =
        c.spike_gate * c.spike_gate * (o.field_sigma[k] * o.field_sigma[k] + c.spike_sigma * c.spike_sigma);
    if (!(d * d > bound2)) {
        s.outlier_run[k] = 0;
        return;
    }
    ++s.outlier_run[k];
    const bool spiking = (s.axis_word[k] & kFaultAxisSpiking) != 0u;
    if (s.outlier_run[k] > (spiking ? kSpikeMaxRunSpiking : kSpikeMaxRun)) return;
    s.spike_now = static_cast<std::uint8_t>(s.spike_now | (1u << k));
    ++s.spikes[k];
    if (s.spike_window_start[k] < T(0) || o.t - s.spike_window_start[k] >= c.spike_window) {
        s.spike_window_start[k] = o.t;
        s.spike_window_count[k] = 0;
    }
    // Not declared while the axis' flip test or the strap test is failing: a stuck axis or a failed strap,
    // read in alternating polarities, strays on every other sample; its own test names it.
    const bool other_fault = s.axis_failing[k][1] > T(0) || s.strap_failing > T(0) || s.strap_failed;
    if (++s.spike_window_count[k] >= c.spike_count && !other_fault)
        declare(s.axis_word[k], s.axis_time[k], kFaultAxisSpiking, o.t);
}

// The bias-jump test of the three axes (fault_detection.hpp, FaultDetectionConfig::bias_*).
template <class T>
void bias_test(FaultDetectionState<T>& s, const FaultObservation<T>& o, const FaultDetectionConfig<T>& c, T dt,
               std::uint8_t excluded) {
    s.bias_jump_now = false;
    if (!(o.predicted && o.field_calibrated && o.field_measured && o.field_ref_norm > T(0))) return;
    const T alpha = std::min(T(1), dt / c.bias_window);
    const T alpha_recent = std::min(T(1), dt / c.bias_recent_window);
    bool jump = false;
    for (std::size_t k = 0; k < 3; ++k) {
        if ((excluded >> k & 1u) || o.at_rail[k] || (s.spike_now >> k & 1u)) continue;
        const T d = o.field_uncalibrated[k] - o.field_body[k];
        s.bias_mean[k] += alpha * (d - s.bias_mean[k]);
        s.bias_recent[k] += alpha_recent * (d - s.bias_recent[k]);
        const Outcome o_k = std::abs(s.bias_mean[k]) > c.bias_threshold ? Outcome::fail : Outcome::pass;
        if (confirmed(s.bias_failing[k], o_k, dt, c.confirm_time)) {
            declare(s.axis_word[k], s.axis_time[k], kFaultAxisBias, o.t);
            jump = true;
        }
    }
    if (!jump) return;
    // The jump: the recent means of every axis (a field has three components; those below the threshold
    // too). The slow mean lags a step; the recent one (bias_recent_window) has caught up with it by the
    // declaration, at least the confirmation time later.
    s.bias_jump_now = true;
    s.bias_jump = s.bias_recent;
    s.bias_recovering = true;
    s.bias_mean = Vec3<T>{};
    s.bias_recent = Vec3<T>{};
    s.bias_failing = {};
}

}  // namespace

template <class T>
void axis_tests(FaultDetectionState<T>& s, const FaultObservation<T>& o, const FaultDetectionConfig<T>& c, T dt) {
    const std::uint8_t excluded = excluded_axes(s);
    // Two readings in a row of opposite polarity: p (r_k − r_{k−1}) / 2 = S B_k (the offset cancels).
    const bool flip = s.has_last && o.polarity * s.last_polarity < T(0) && o.t - s.last_t <= T(1.5) * o.sample_period;
    strap_test(s, o, c, dt, flip);
    // While the strap test fails (or once the strap is declared) no axis is blamed for not flipping.
    const bool strap_suspect = s.strap_failed || s.strap_failing > T(0);
    s.spike_now = 0;
    for (std::size_t k = 0; k < 3; ++k) {
        if (excluded >> k & 1u) continue;
        spike_test(s, o, c, k);
        const Outcome rail = o.at_rail[k] ? Outcome::fail : Outcome::pass;
        if (confirmed(s.axis_failing[k][0], rail, dt, c.confirm_time))
            declare(s.axis_word[k], s.axis_time[k], kFaultAxisRail, o.t);
        Outcome flips = Outcome::not_applicable;
        const T expected = o.field_body[k];
        const T min_field = flip_min_field(o, c);
        if (flip && !strap_suspect && o.predicted && !o.at_rail[k] && std::abs(expected) >= min_field) {
            const T half = o.polarity * (o.mag_reading[k] - s.last_reading[k]) / (T(2) * o.sensitivity);
            const T along = expected > T(0) ? half : -half;
            // Below the fraction is a no-flip only if the difference did not move at all. What each fault
            // shows in the pair (set/reset half difference p (r_k − r_{k−1})/2S against the mean innovation):
            // - a stuck axis (latched output, rail): the same reading twice, half difference 0 whatever the
            //   field; its innovation alternates in sign with the polarity, so its mean is the prediction's.
            // - a bias jump (a field b at the sensor, magnetometer/README.md): it flips with the earth's
            //   field, so the half difference is B_k + b_k, the whole field at the sensor, and the innovation
            //   is b_k at both polarities: a steady mean, the bias test's. Where b_k opposes B_k the
            //   difference falls below the fraction for as long as the tumble keeps |b_k| > (1 − f) |B_k|
            //   (seconds to minutes), but it stays clear of zero (within frozen_tolerance only while B_k + b_k
            //   crosses zero, a sample or two). Such a sample is a flip: it passes, and the bias test judges.
            const bool moved = std::abs(half) >= still_bar(o, c, k);
            flips = along >= c.flip_fraction * std::abs(expected) || moved ? Outcome::pass : Outcome::fail;
        }
        if (flips == Outcome::not_applicable && flip && !strap_suspect && o.predicted && o.field_calibrated &&
            !o.at_rail[k]) {
            // Frozen: too weak a field for the flip test, yet clearly not zero: a healthy axis flips by
            // about 2 S B_k, one stuck at its last value not at all.
            const T bar = std::max(c.frozen_min_field, kFrozenSigmas<T> * o.field_sigma[k]);
            if (std::abs(expected) >= bar) {
                const T half = (o.mag_reading[k] - s.last_reading[k]) / (T(2) * o.sensitivity);
                flips = std::abs(half) < still_bar(o, c, k) ? Outcome::fail : Outcome::pass;
            }
        }
        if (confirmed(s.axis_failing[k][1], flips, dt, c.confirm_time))
            declare(s.axis_word[k], s.axis_time[k], kFaultAxisNoFlip, o.t);
    }
    bias_test(s, o, c, dt, excluded);
    s.last_reading = o.mag_reading;
    s.last_polarity = o.polarity;
    s.last_commanded_polarity = o.commanded_polarity;
    s.last_t = o.t;
    s.has_last = true;

    Outcome norm = Outcome::not_applicable;
    if (o.field_usable && o.field_ref_norm > T(0)) {
        const T n = std::sqrt(o.field[0] * o.field[0] + o.field[1] * o.field[1] + o.field[2] * o.field[2]);
        norm = std::abs(n - o.field_ref_norm) <= c.norm_tolerance ? Outcome::pass : Outcome::fail;
    }
    if (confirmed(s.norm_failing, norm, dt, c.confirm_time)) declare(s.norm_word, s.norm_time, 1u, o.t);
}

template void axis_tests(FaultDetectionState<float>&, const FaultObservation<float>&,
                         const FaultDetectionConfig<float>&, float);
template void axis_tests(FaultDetectionState<double>&, const FaultObservation<double>&,
                         const FaultDetectionConfig<double>&, double);

}  // namespace attitude_estimator::fault_detail
