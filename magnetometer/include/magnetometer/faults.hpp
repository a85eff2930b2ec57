// Faults of the HMC2003 and its output circuit, injected as physical effects (issue 28). Plain C++.
//
//   stuck axis   one axis' output stays at the voltage it had at the onset (a latched amplifier or ADC
//                channel) or at a supply rail (an open bridge arm pulls its amplifier to a rail)
//   spikes       electrical interference on one axis' output: rectangular pulses of ±size volts lasting
//                `duration`, a Poisson process of `rate` per second thinned to at most one pulse per slot of
//                `duration` (probability 1 − exp(−rate·duration) per slot), the slot's draw and sign from a
//                counter-based generator keyed by `seed`: reproducible, no time events, any evaluation order
//   bias jump    a field appears at the sensor (a part nearby magnetised, a new current loop): it is a field,
//                so it passes the sensor matrix and flips with the set/reset pulses like the Earth's field,
//                and set/reset differencing does not remove it
//   strap failed the set/reset strap no longer re-magnetises the film (open strap, failed driver): the
//                polarity stays at what it was at the onset whatever the pulses (so the set/reset difference
//                is zero and half their sum holds the field, not just the offset)
//
// Each fault runs from its onset to its end (s, simulation time; end 0 = never clears); both are time events.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "magnetometer/hmc2003.hpp"

namespace magnetometer {

enum class StuckMode : std::int32_t { last = 0, rail_low = 1, rail_high = 2 };

struct FaultTimes {
    double onset = 0.0;  // s
    double end = 0.0;    // s, 0 = never clears
};

struct FaultParameters {
    std::int32_t stuck_axis = 0;  // 0 = none, 1 … 3 = X, Y, Z
    StuckMode stuck_mode = StuckMode::last;
    FaultTimes stuck;
    std::int32_t spike_axis = 0;   // 0 = none, 1 … 3
    double spike_rate = 0.0;       // 1/s, mean rate of the pulses
    double spike_size = 0.0;       // V, height of a pulse at the output
    double spike_duration = 1e-3;  // s, length of a pulse (and of a slot)
    std::int32_t spike_seed = 1;
    FaultTimes spikes;
    Vec3 bias_jump = {};  // T, body axes; all zero = none
    FaultTimes bias;
    bool strap_failed = false;
    FaultTimes strap;
};

enum MagnetometerFault : std::size_t { fault_stuck = 0, fault_spikes, fault_bias, fault_strap, fault_count };

inline constexpr std::int32_t fault_pending = 0;
inline constexpr std::int32_t fault_active = 1;
inline constexpr std::int32_t fault_cleared = 2;
using FaultPhases = std::array<std::int32_t, fault_count>;

// Throws std::invalid_argument naming the parameter (fault_...) that is out of range.
void check_faults(const FaultParameters& f);

// Whether the fault of this kind is configured at all.
bool fault_configured(const FaultParameters& f, MagnetometerFault kind);

// Moves the phases on to time t (onsets and ends reached within 1e-12 relative); returns a bit per kind
// that became active at t.
std::uint32_t advance_faults(const FaultParameters& f, FaultPhases& phases, double t);

// The next onset or end after the phases: +infinity if none.
double next_fault_event(const FaultParameters& f, const FaultPhases& phases);

// Probability that a slot of `duration` holds a pulse of a Poisson process of `rate`: 1 − exp(−rate·duration).
double spike_probability(double rate, double duration);

// The pulse on the faulty axis in slot `slot` (counted from the onset): +size, −size or 0. The draw is
// uniform(seed, slot, 0) < probability, the sign uniform(seed, slot, 1) < 1/2 (held_noise.hpp's generator).
double spike_in_slot(const FaultParameters& f, std::int64_t slot);

}  // namespace magnetometer
