// Held Gaussian noise without a generator state: the sample for hold interval k and axis a is a pure
// function of (seed, k, a). The block computes k from the time, so the noise needs no time events (the
// integrator is not restarted every noise_sample_period) and a saved FMU state (seed and start time)
// reproduces the sequence exactly, whatever order the host evaluates the instants in.
//
// Generator: a counter-based hash in the spirit of Salmon et al., "Parallel random numbers: as easy as
// 1, 2, 3" (SC '11): the splitmix64 finaliser (Steele, Lea & Flood, "Fast splittable pseudorandom number
// generators", OOPSLA 2014) applied to the counter 2·(3k + a) and its successor, each XORed with a key
// mixed from the seed, gives two 53-bit uniforms; the Box–Muller transform turns them into one standard
// normal deviate. No rejection loop, so every sample costs the same.
#pragma once

#include <cstdint>

namespace magnetometer {

// The largest |k| the block accepts: beyond 2^53 consecutive hold intervals are no longer distinct
// doubles, and (t − t0)/period past 9.2e18 cannot be converted to an integer at all.
inline constexpr double max_noise_index = 9007199254740992.0;  // 2^53

// Index of the hold interval that contains time t: the largest k with t ≥ t0 + k·period, allowing for
// the rounding of a host that reaches t0 + k·period as a sum of steps (the tolerance of fmu::reached).
// Throws fmu::Error when (t − t0)/period is not finite or exceeds max_noise_index in magnitude; the
// message names the parameters as `t0_name` and `period_name` (the noise's, or a fault's onset and slot).
std::int64_t noise_index(double t, double t0, double period, const char* t0_name = "t0",
                         const char* period_name = "noise_sample_period");

// Standard normal deviate for (seed, index, axis); axis is 0, 1 or 2.
double held_normal(std::uint64_t seed, std::int64_t index, int axis);

// Uniform deviate in (0, 1) for (seed, index, stream), stream 0, 1 or 2: the same generator under a key of
// its own, so that it is independent of held_normal's deviates of the same seed.
double held_uniform(std::uint64_t seed, std::int64_t index, int stream);

}  // namespace magnetometer
