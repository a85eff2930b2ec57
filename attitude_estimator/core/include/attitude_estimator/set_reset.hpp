// The on-board computer's side of the HMC2003 set/reset function: it pulses the sensor's set/reset strap
// (seed 000 fig. 10 drives it from MOSFETs) and takes the bridge offset out of the readings.
//
// A set pulse leaves the sensor reading v − v_ref = +S·B + v_os, a reset pulse −S·B + v_os: the pulse
// flips the field term, the offset v_os stays (Honeywell application note AN-213, "Set/Reset Function for
// Magnetic Sensors"). So half the sum of a set and a reset reading is v_os whatever the field, and each
// reading gives the field as B = p·(v − v_ref − v_os)/S with p = ±1 its polarity.
//
// Scheme: the computer alternates the polarity every `period_samples` samples, so consecutive readings
// around a pulse form set/reset pairs. A pair's half sum estimates v_os; in a turning satellite the field
// moves between the two readings, which adds p·S·(B_k − B_{k−1})/2 (the first difference: 47 mV for the
// seed's 6.3 rad/s spin at 20 Hz). When three readings in a row alternate (a pulse every sample) the
// estimate is (r_{k−2} + 2 r_{k−1} + r_k)/4 instead, which leaves only p·S·(B_k − 2 B_{k−1} + B_{k−2})/4,
// the second difference (7 mV there, nothing measurable in a slow tumble). Either residual changes sign
// from one estimate to the next, and a running mean over `offset_window` estimates cancels it (v_os
// itself only drifts with temperature, over minutes). With a pulse every sample only three-reading
// estimates enter the mean (a lone first pair would weigh on it for the whole window), and the estimate is
// applied once the window is full (applied_offset: zero before). The field of each sample then comes from
// that sample alone with the applied offset: no lag from the differencing. Plain C++, no heap, no
// exceptions.
#pragma once

#include <cstdint>

#include "attitude_estimator/types.hpp"

namespace attitude_estimator {

struct SetResetConfig {
    std::int32_t period_samples = 1;  // samples between pulses; 0: no pulses (the offset stays in the field)
    std::int32_t offset_window = 20;  // offset estimates (one per set/reset pair) in the running mean (≥ 1)
};

// Trivially copyable: it travels in an FMU state as bytes.
template <class T>
struct SetResetState {
    // The polarity the sensor is in: the last pulse commanded (+1 set, −1 reset). The next reading is taken
    // in it; pass it to estimate_sample as SampleInputs::mag_polarity. The sensor is set at power-up.
    T polarity = T(1);
    Vec3<T> offset{};              // V, the running mean of the offset estimates (see applied_offset)
    Vec3<T> last_reading{};        // V, the previous usable reading v − v_ref
    T last_polarity = T(0);        // its polarity; 0 when there is none (start, or after an unusable one)
    Vec3<T> earlier_reading{};     // V, the usable reading before that
    T earlier_polarity = T(0);     // its polarity; 0 when there is none
    std::int32_t pairs = 0;        // estimates in the running mean so far (stops growing at offset_window)
    std::int32_t since_pulse = 0;  // samples since the last pulse
};

// After each sample: `reading` is that sample's digitized v − v_ref per axis, taken at state.polarity;
// `usable` is false when a channel was saturated or not finite (the reading is then not paired). Updates
// the offset estimate from this reading and the previous one when their polarities differ, then commands
// the next pulse when period_samples have passed. Returns true when it commanded one (polarity flipped).
template <class T>
bool set_reset_after_sample(SetResetState<T>& state, const Vec3<T>& reading, bool usable,
                            const SetResetConfig& config) noexcept;

// The offset to take out of the next reading (SampleInputs::mag_offset): the running mean once it holds
// offset_window estimates, zero before (and with no pulses).
template <class T>
Vec3<T> applied_offset(const SetResetState<T>& state, const SetResetConfig& config) noexcept {
    return config.period_samples > 0 && state.pairs >= config.offset_window ? state.offset : Vec3<T>{};
}

extern template bool set_reset_after_sample(SetResetState<float>&, const Vec3<float>&, bool,
                                            const SetResetConfig&) noexcept;
extern template bool set_reset_after_sample(SetResetState<double>&, const Vec3<double>&, bool,
                                            const SetResetConfig&) noexcept;

}  // namespace attitude_estimator
