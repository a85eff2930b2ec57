#include "magnetometer/faults.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "magnetometer/held_noise.hpp"
#include "time_rule/time_rule.hpp"

namespace magnetometer {
namespace {

constexpr std::array<const char*, fault_count> prefix = {"fault_stuck", "fault_spike", "fault_bias", "fault_strap"};

void require(bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument("magnetometer parameters: " + what);
}

const FaultTimes& times(const FaultParameters& f, MagnetometerFault kind) {
    switch (kind) {
        case fault_stuck:
            return f.stuck;
        case fault_spikes:
            return f.spikes;
        case fault_bias:
            return f.bias;
        case fault_strap:
        default:
            return f.strap;
    }
}

// A time event is due by the rule the runtime and the master use (time_rule/time_rule.hpp).
using time_rule::reached;

}  // namespace

void check_faults(const FaultParameters& f) {
    for (std::size_t k = 0; k < fault_count; ++k) {
        const FaultTimes& w = times(f, static_cast<MagnetometerFault>(k));
        const std::string name = prefix[k];
        require(std::isfinite(w.onset), name + "_onset must be finite");
        require(std::isfinite(w.end) && (w.end == 0.0 || w.end > w.onset),
                name + "_end must be 0 (never clears) or after " + name + "_onset");
    }
    require(f.stuck_axis >= 0 && f.stuck_axis <= 3, "fault_stuck_axis must be 0 (none) or 1 ... 3 (X, Y, Z)");
    require(
        f.stuck_mode == StuckMode::last || f.stuck_mode == StuckMode::rail_low || f.stuck_mode == StuckMode::rail_high,
        "fault_stuck_mode must be 0 (last), 1 (rail_low) or 2 (rail_high)");
    require(f.spike_axis >= 0 && f.spike_axis <= 3, "fault_spike_axis must be 0 (none) or 1 ... 3 (X, Y, Z)");
    require(std::isfinite(f.spike_rate) && f.spike_rate >= 0.0, "fault_spike_rate must be finite and >= 0");
    require(std::isfinite(f.spike_size), "fault_spike_size must be finite");
    require(std::isfinite(f.spike_duration) && f.spike_duration > 0.0, "fault_spike_duration must be > 0");
    for (double b : f.bias_jump) require(std::isfinite(b), "fault_bias_jump must be finite");
}

bool fault_configured(const FaultParameters& f, MagnetometerFault kind) {
    switch (kind) {
        case fault_stuck:
            return f.stuck_axis != 0;
        case fault_spikes:
            return f.spike_axis != 0 && f.spike_rate > 0.0;
        case fault_bias:
            return f.bias_jump[0] != 0.0 || f.bias_jump[1] != 0.0 || f.bias_jump[2] != 0.0;
        case fault_strap:
        default:
            return f.strap_failed;
    }
}

std::uint32_t advance_faults(const FaultParameters& f, FaultPhases& phases, double t) {
    std::uint32_t started = 0;
    for (std::size_t k = 0; k < fault_count; ++k) {
        const auto kind = static_cast<MagnetometerFault>(k);
        if (!fault_configured(f, kind)) continue;
        const FaultTimes& w = times(f, kind);
        if (phases[k] == fault_pending && reached(t, w.onset)) {
            phases[k] = fault_active;
            started |= 1u << k;
        }
        if (phases[k] == fault_active && w.end != 0.0 && reached(t, w.end)) phases[k] = fault_cleared;
    }
    return started;
}

double next_fault_event(const FaultParameters& f, const FaultPhases& phases) {
    double next = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < fault_count; ++k) {
        const auto kind = static_cast<MagnetometerFault>(k);
        if (!fault_configured(f, kind)) continue;
        const FaultTimes& w = times(f, kind);
        if (phases[k] == fault_pending) next = std::min(next, w.onset);
        if (phases[k] == fault_active && w.end != 0.0) next = std::min(next, w.end);
    }
    return next;
}

double spike_probability(double rate, double duration) {
    return -std::expm1(-rate * duration);
}

double spike_in_slot(const FaultParameters& f, std::int64_t slot) {
    const auto seed = static_cast<std::uint64_t>(static_cast<std::uint32_t>(f.spike_seed));
    if (!(held_uniform(seed, slot, 0) < spike_probability(f.spike_rate, f.spike_duration))) return 0.0;
    return held_uniform(seed, slot, 1) < 0.5 ? -f.spike_size : f.spike_size;
}

}  // namespace magnetometer
