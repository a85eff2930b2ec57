// When the master counts an instant as reached: within 1e-12 of it, relative (absolute below 1 s),
// allowing for the rounding of a time computed as a sum of steps. The blocks decide their own time
// events by the same rule (fmu::reached, fmus/include/fmu/model.hpp); a master and a block that disagree
// step past an event or take it twice, so cosim_tests checks the two against each other.
#pragma once

#include <algorithm>
#include <cmath>

namespace cosim {

inline constexpr double time_relative_tolerance = 1e-12;

// The smallest difference of two times near t that the rule tells apart.
inline double time_resolution(double t) {
    return time_relative_tolerance * std::max(1.0, std::abs(t));
}

inline bool reached(double t, double event_time) {
    return t >= event_time - time_resolution(event_time);
}

}  // namespace cosim
