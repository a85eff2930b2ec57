#include "attitude_estimator/set_reset.hpp"

namespace attitude_estimator {

template <class T>
bool set_reset_after_sample(SetResetState<T>& state, const Vec3<T>& reading, bool usable,
                            const SetResetConfig& config) noexcept {
    if (!usable) {
        state.last_polarity = T(0);  // a saturated reading pairs with nothing
        state.earlier_polarity = T(0);
    } else {
        const bool pair = state.last_polarity == -state.polarity;
        const bool three = pair && state.earlier_polarity == state.polarity;  // set, reset, set (or the reverse)
        // With a pulse every sample, wait for the third reading of a run: a lone first pair would weigh on the
        // mean for the whole window.
        if (three || (pair && config.period_samples != 1)) {
            // Running mean while the window fills, then an exponential mean with the window's weight.
            if (state.pairs < config.offset_window) ++state.pairs;
            const T weight = T(1) / static_cast<T>(state.pairs < 1 ? 1 : state.pairs);
            for (int k = 0; k < 3; ++k) {
                const T estimate =
                    three ? T(0.25) * (reading[k] + T(2) * state.last_reading[k] + state.earlier_reading[k])
                          : T(0.5) * (reading[k] + state.last_reading[k]);
                state.offset[k] += weight * (estimate - state.offset[k]);
            }
        }
        state.earlier_reading = state.last_reading;
        state.earlier_polarity = state.last_polarity;
        state.last_reading = reading;
        state.last_polarity = state.polarity;
    }
    if (config.period_samples <= 0) return false;
    if (++state.since_pulse < config.period_samples) return false;
    state.since_pulse = 0;
    state.polarity = -state.polarity;
    return true;
}

template bool set_reset_after_sample(SetResetState<float>&, const Vec3<float>&, bool, const SetResetConfig&) noexcept;
template bool set_reset_after_sample(SetResetState<double>&, const Vec3<double>&, bool, const SetResetConfig&) noexcept;

}  // namespace attitude_estimator
