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

/// A Gregorian calendar day and the UTC fraction of it.
struct CalendarDay {
    int year = 2000;
    int month = 1;
    int day = 1;
    double fraction = 0.0;  // of the day since 0 h, [0, 1)
};

/// The calendar day of a Julian date (Meeus, Astronomical Algorithms, ch. 7, the inverse of
/// julian_date_at_midnight; Gregorian dates only, JD >= 2299160.5).
inline CalendarDay calendar_day(double jd) {
    const double shifted = jd + 0.5;
    const double z = std::floor(shifted);
    const double f = shifted - z;
    const double alpha = std::floor((z - 1867216.25) / 36524.25);
    const double a = z + 1.0 + alpha - std::floor(alpha / 4.0);
    const double b = a + 1524.0;
    const double c = std::floor((b - 122.1) / 365.25);
    const double d = std::floor(365.25 * c);
    const double e = std::floor((b - d) / 30.6001);
    CalendarDay out;
    out.day = static_cast<int>(b - d - std::floor(30.6001 * e));
    out.month = static_cast<int>(e < 14.0 ? e - 1.0 : e - 13.0);
    out.year = static_cast<int>(out.month > 2 ? c - 4716.0 : c - 4715.0);
    out.fraction = f;
    return out;
}

}  // namespace orbit
