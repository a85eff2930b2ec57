#pragma once
// Calendar date -> Julian date, Greenwich mean sidereal time, decimal year.

namespace environment {

/// A UTC calendar instant (Gregorian calendar).
struct UtcDate {
    int year = 2026;
    int month = 3;
    int day = 20;
    int hour = 0;
    int minute = 0;
    double second = 0.0;
};

/// Julian date of a Gregorian calendar instant (Meeus, Astronomical Algorithms, ch. 7).
/// Throws std::invalid_argument on an impossible date.
double julian_date(const UtcDate& date);

/// Greenwich mean sidereal time in radians, [0, 2 pi), IAU 1982 model (Aoki et al. 1982, as in
/// Vallado, Fundamentals of Astrodynamics, eq. 3-47). UT1 is approximated by UTC (|UT1-UTC| < 0.9 s,
/// i.e. < 4e-3 deg of Earth rotation).
double gmst(double julian_date_ut1);

/// Decimal year (e.g. 2026.2137) of a Julian date, counting the actual length of the calendar year;
/// the time argument of the IGRF.
double decimal_year(double julian_date);

}  // namespace environment
