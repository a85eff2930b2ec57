// The Julian date of a Gregorian calendar day: one helper for every calendar conversion of the project
// (a TLE's epoch here, the environment's UTC and the on-board computer's clock). Header-only, no heap,
// no exceptions: the firmware compiles it too.
#pragma once

#include <cmath>

namespace orbit {

/// Julian date at 0 h of a Gregorian calendar date (Meeus, Astronomical Algorithms, ch. 7), an integer
/// plus one half. No range check: the caller checks the calendar.
inline double julian_date_at_midnight(int year, int month, int day) {
    if (month <= 2) {
        year -= 1;
        month += 12;
    }
    const int a = year / 100;
    const int b = 2 - a + a / 4;
    return std::floor(365.25 * (year + 4716)) + std::floor(30.6001 * (month + 1)) + day + b - 1524.5;
}

}  // namespace orbit
