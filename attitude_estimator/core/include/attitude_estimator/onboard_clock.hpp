// The on-board computer's own clock: a sample's time t (s from the run's start, the block's time) plus
// the UTC epoch of t = 0 that the computer was given (an uplinked parameter), turned into the time
// arguments its reference models need. Templated on float/double, no heap, no exceptions; the epoch is
// split into whole days and seconds of the day so that float keeps the seconds to a few ms over days.
#pragma once

#include <cstdint>

namespace attitude_estimator {

// A UTC calendar instant (Gregorian). The caller checks the calendar (the block does, in validate()).
struct CalendarInstant {
    std::int32_t year = 2026;
    std::int32_t month = 3;
    std::int32_t day = 20;
    std::int32_t hour = 0;
    std::int32_t minute = 0;
    double second = 0.0;
};

template <class T>
struct OnboardClock {
    T midnight_days = T(0);  // days from J2000.0 (JD 2451545.0) to 0 h UTC of the epoch's day (a half-integer)
    T epoch_seconds = T(0);  // s: UTC seconds of that day at t = 0
    T gmst_midnight = T(0);  // rad: Greenwich mean sidereal time at 0 h UTC of the epoch's day (UT1 = UTC)
    T epoch_year = T(2026);  // decimal year at t = 0 (the field model's time argument)
    double epoch_julian_date = 2451545.0;  // JD (UTC) at t = 0, for set-up computations (double)
};

// The clock's constants for an epoch, computed in double and rounded once to T.
template <class T>
OnboardClock<T> make_onboard_clock(const CalendarInstant& epoch) noexcept;

// Seconds of the epoch's day at time t (beyond 86400 after the first day).
template <class T>
T seconds_of_epoch_day(const OnboardClock<T>& c, T t) noexcept {
    return c.epoch_seconds + t;
}
// Days from J2000.0 at time t (UTC; TT − UTC, 69 s, is below the sun formula's resolution).
template <class T>
T days_since_j2000(const OnboardClock<T>& c, T t) noexcept {
    return c.midnight_days + seconds_of_epoch_day(c, t) / T(86400);
}
// Greenwich mean sidereal time (rad, [0, 2π)) at time t: the IAU 1982 value at midnight plus the Earth's
// sidereal rate times the seconds since.
template <class T>
T gmst_at(const OnboardClock<T>& c, T t) noexcept;
// Decimal year at time t (a year of 365.25 days after the epoch: 1e-3 day off per year at most).
template <class T>
T decimal_year_at(const OnboardClock<T>& c, T t) noexcept {
    return c.epoch_year + t / T(365.25 * 86400.0);
}

extern template OnboardClock<float> make_onboard_clock(const CalendarInstant&) noexcept;
extern template OnboardClock<double> make_onboard_clock(const CalendarInstant&) noexcept;
extern template float gmst_at(const OnboardClock<float>&, float) noexcept;
extern template double gmst_at(const OnboardClock<double>&, double) noexcept;

}  // namespace attitude_estimator
