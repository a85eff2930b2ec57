// Sample and event instants counted by an integer: instant k is origin + k·period. Blocks keep the
// count (not a running sum) so that instants never drift; this header is where the count is advanced
// past a time a host jumped to, with a bound, so that no time a host passes makes a block loop.
#pragma once

#include <cstdint>
#include <string_view>

namespace fmu {

// The most periods a block counts from its origin. Beyond it consecutive instants are closer than the
// 1e-12 relative tolerance of reached() (and past 9.2e18 an int64 count would overflow), so a later
// time is refused with fmu::Error instead of looping. At 20 Hz this is 5e9 s, 158 years.
inline constexpr std::int64_t max_instant_index = 100'000'000'000;

// The index of the first instant origin + k·period that t has not reached (fmu::reached), with
// k >= `at_least`. At most a handful of steps whatever t is. Throws fmu::Error naming `what` and the
// limit when t is not finite, the period is not positive, or the index would exceed max_instant_index.
std::int64_t next_instant_index(double t, double origin, double period, std::int64_t at_least, std::string_view what);

}  // namespace fmu
