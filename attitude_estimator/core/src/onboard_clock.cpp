#include "attitude_estimator/onboard_clock.hpp"

#include <cmath>

#include "ground/almanac_formulas.hpp"
#include "orbit/calendar.hpp"

namespace attitude_estimator {

namespace f = ground::formulas;

template <class T>
OnboardClock<T> make_onboard_clock(const CalendarInstant& e) noexcept {
    const double midnight = orbit::julian_date_at_midnight(e.year, e.month, e.day);
    const double seconds = e.hour * 3600.0 + e.minute * 60.0 + e.second;
    // Decimal year as the environment counts it (the calendar year's actual length).
    const double jan1 = orbit::julian_date_at_midnight(e.year, 1, 1);
    const double length = orbit::julian_date_at_midnight(e.year + 1, 1, 1) - jan1;
    OnboardClock<T> c;
    c.midnight_days = static_cast<T>(midnight - f::kJ2000);
    c.epoch_seconds = static_cast<T>(seconds);
    c.gmst_midnight = static_cast<T>(f::gmst_seconds((midnight - f::kJ2000) / 36525.0) / 86400.0 * f::kTwoPi);
    c.epoch_julian_date = midnight + seconds / 86400.0;
    c.epoch_year = static_cast<T>(e.year + (c.epoch_julian_date - jan1) / length);
    return c;
}

template <class T>
T gmst_at(const OnboardClock<T>& c, T t) noexcept {
    // The turns since midnight reduced before they are added: float keeps the angle to 1e-6 rad.
    const T turns = seconds_of_epoch_day(c, t) * T(f::kEarthRotationRate / f::kTwoPi);
    const T fraction = turns - std::floor(turns);
    T a = c.gmst_midnight + fraction * T(f::kTwoPi);
    if (a >= T(f::kTwoPi)) a -= T(f::kTwoPi);
    return a;
}

template OnboardClock<float> make_onboard_clock(const CalendarInstant&) noexcept;
template OnboardClock<double> make_onboard_clock(const CalendarInstant&) noexcept;
template float gmst_at(const OnboardClock<float>&, float) noexcept;
template double gmst_at(const OnboardClock<double>&, double) noexcept;

}  // namespace attitude_estimator
