// What a value must be before it is written into a block: one rule for every writer (the FMU's
// fmi2Set* functions, the board emulator's settings and configuration frames), so that none of them
// lets through a value another would refuse. Each throws fmu::Error naming the variable and the limit.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fmu/variable.hpp"

namespace fmu {

// A Real: finite and within the variable's min and max.
void check_real(const Variable& v, double x);
// An Integer or Enumeration: within min and max; an Enumeration's value is one of its items.
void check_integer(const Variable& v, std::int32_t x);

// A value given as text (a command line's name=value), checked as above and returned as the f64 the
// wire carries: a Real or Integer is the whole text as a number, an Enumeration an item's name or
// number, a Boolean true, false, 1 or 0. String variables are not converted (refused).
double checked_value_from_text(const Variable& v, std::string_view text);

// Notes on legal settings a person most likely did not mean (issue 40), one line each, once per declared
// name: a parameter outside its plausible range ("omega0[1] = 5 rad/s is legal but unlikely: ..."), and a
// parameter set away from its default (`defaults`: the block's bytes as constructed) while the choice it
// applies under says it is ignored ("orbit_altitude = 4e+05 m has no effect: it applies when orbit_model is
// circular, and orbit_model is tle"). The runtime logs them as warnings when initialization ends.
std::vector<std::string> setting_notes(const std::vector<Variable>& variables, std::span<const std::byte> values,
                                       std::span<const std::byte> defaults);

}  // namespace fmu
