// When an instant counts as reached: t within 1e-12 of it, relative (absolute below 1 s), allowing for
// the rounding of a time computed as a sum of steps. The one rule for the master (harness/engine), the
// runtime (fmu::reached) and the blocks' cores (fault windows): a master and a block that disagree step
// past an event or take it twice. Plain C++, no FMI types, so that a core may include it.
#pragma once

namespace time_rule {

inline constexpr double relative_tolerance = 1e-12;

// The smallest difference of two times near t that the rule tells apart.
constexpr double resolution(double t) {
    const double magnitude = t < 0 ? -t : t;
    return relative_tolerance * (magnitude > 1.0 ? magnitude : 1.0);
}

constexpr bool reached(double t, double event_time) {
    return t >= event_time - resolution(event_time);
}

}  // namespace time_rule
