#include "environment/time_scales.hpp"

#include <cmath>
#include <stdexcept>

#include "environment/constants.hpp"
#include "ground/almanac_formulas.hpp"
#include "orbit/calendar.hpp"

namespace environment {

namespace {
bool is_leap_year(int y) {
    return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
}
}  // namespace

double julian_date(const UtcDate& d) {
    if (d.month < 1 || d.month > 12 || d.day < 1 || d.day > 31 || d.hour < 0 || d.hour > 23 || d.minute < 0 ||
        d.minute > 59 || !(d.second >= 0.0 && d.second < 61.0)) {
        throw std::invalid_argument("julian_date: calendar field out of range");
    }
    // Meeus, Astronomical Algorithms (2nd ed.), eq. 7.1, Gregorian calendar.
    // (orbit/calendar.hpp, shared with the TLE epochs and the on-board computer)
    const double day_fraction = (d.hour + (d.minute + d.second / 60.0) / 60.0) / 24.0;
    return orbit::julian_date_at_midnight(d.year, d.month, d.day) + day_fraction;
}

double gmst(double jd_ut1) {
    // IAU 1982 GMST (Vallado eq. 3-47), seconds of time; T in Julian centuries of UT1 from J2000.
    // (almanac_formulas.hpp, shared with the on-board computer)
    return ground::formulas::gmst_seconds((jd_ut1 - kJulianDateJ2000) / 36525.0) / kSecondsPerDay * 2.0 * kPi;
}

double decimal_year(double jd) {
    // Start from the Julian-year estimate and correct by the calendar so that Jan 1 00:00 is exact.
    int year = static_cast<int>(std::floor(2000.0 + (jd - kJulianDateJ2000) / 365.25));
    double start = julian_date(UtcDate{year, 1, 1, 0, 0, 0.0});
    if (jd < start) {
        --year;
        start = julian_date(UtcDate{year, 1, 1, 0, 0, 0.0});
    } else if (jd >= julian_date(UtcDate{year + 1, 1, 1, 0, 0, 0.0})) {
        ++year;
        start = julian_date(UtcDate{year, 1, 1, 0, 0, 0.0});
    }
    const double length = is_leap_year(year) ? 366.0 : 365.0;
    return year + (jd - start) / length;
}

}  // namespace environment
