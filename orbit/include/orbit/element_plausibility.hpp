#pragma once
// How far from its epoch an element set may be used: one rule for the truth (the environment's set at its
// epoch) and the on-board computer (its set at its clock). SGP4 is a fit over days; propagated for years
// it drifts by thousands of kilometres or decays, and a set decades away from the clock means a wrong
// date, not an old set. Host only (the message is a std::string).
#include <string>

#include "orbit/tle.hpp"

namespace orbit {

/// The longest time (days) between a set's epoch and the instant it is used at: a year. A catalogued LEO
/// set is replaced daily; a year-old one is already kilometres to hundreds of kilometres off, but still
/// an orbit (a study of an old uplink may want it). Beyond it the date is taken for a mistake.
inline constexpr double kMaxElementSetAgeDays = 366.0;

/// "" when the set may be used at `jd_utc`; otherwise a sentence naming the set's epoch, the instant (as
/// `what`, e.g. "the computer's clock at t = 0"), the difference and the bound, or SGP4's refusal there
/// (the satellite has decayed by then).
std::string element_set_problem_at(const Tle& tle, double jd_utc, const std::string& what);

/// "2026-03-20 00:00:00 UTC" (seconds rounded to the millisecond).
std::string format_utc(double jd_utc);

}  // namespace orbit
