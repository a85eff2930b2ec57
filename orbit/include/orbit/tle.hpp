#pragma once
// A two-line element set (the fixed-column format of NORAD / CelesTrak) and its parser.
#include <array>
#include <stdexcept>
#include <string>
#include <string_view>

#include "orbit/calendar.hpp"
#include "orbit/sgp4.hpp"

namespace orbit {

/// The mean elements of a two-line element set, in the set's own units.
struct Tle {
    int catalog_number = 0;                // columns 3-7 of both lines (Alpha-5 letters accepted: A = 10, ..., Z = 33)
    int epoch_year = 0;                    // four digits (the set's two: 57-99 are 19xx, 00-56 are 20xx)
    double epoch_day = 0.0;                // day of the year and its fraction, UTC; 1.0 is 1 January 00:00
    double epoch_jd_utc = 0.0;             // the same epoch as a Julian date (UTC)
    double mean_motion_rev_per_day = 0.0;  // Kozai mean motion
    double eccentricity = 0.0;
    double inclination_deg = 0.0;
    double raan_deg = 0.0;  // right ascension of the ascending node
    double arg_perigee_deg = 0.0;
    double mean_anomaly_deg = 0.0;
    double bstar_per_earth_radius = 0.0;  // B*, the SGP4 drag term

    /// The elements in SGP4's units (rad, rad/min), converted in double and then to T.
    template <typename T>
    MeanElements<T> mean_elements() const noexcept;
};

/// A malformed or unusable element set: the message names the line (1 or 2), the column (1-based; 0 when
/// the fault is the set as a whole) and the reason.
class TleError : public std::invalid_argument {
public:
    TleError(int line, int column, const std::string& reason);
    int line() const noexcept { return line_; }
    int column() const noexcept { return column_; }

private:
    int line_;
    int column_;
};

/// An element set as eight numbers in the set's own units, the layout of the blocks' `tle_elements[1..8]`:
/// epoch (Julian date, UTC), mean motion (rev/day), eccentricity, inclination, right ascension of the node,
/// argument of perigee, mean anomaly (deg), B* (1/Earth radii). How the firmware and an SSP tool without
/// String parameters get a set.
inline constexpr std::size_t kTleElementCount = 8;
using TleElements = std::array<double, kTleElementCount>;

/// The numbers of a set (no check; the catalog number is 0, the epoch's year and day of year derived).
/// Header-only and noexcept: the firmware converts its numbers with it.
inline Tle tle_from_elements(const TleElements& e) noexcept;
/// The eight numbers of a set.
inline TleElements elements_of(const Tle& t) noexcept {
    return {t.epoch_jd_utc, t.mean_motion_rev_per_day, t.eccentricity,     t.inclination_deg,
            t.raan_deg,     t.arg_perigee_deg,         t.mean_anomaly_deg, t.bstar_per_earth_radius};
}

/// A set given as numbers that is refused: the message names the element (`[k]`, 1-based as the blocks'
/// tle_elements[k]) and the reason.
class TleElementsError : public std::invalid_argument {
public:
    TleElementsError(int element, const std::string& reason);
    int element() const noexcept { return element_; }  // 1..8; 0 for the set as a whole

private:
    int element_;
};

/// The set of the numbers after the checks the text's parser makes (parse_tle): every number finite, the
/// epoch within the format's years 1957-2056, a positive mean motion, 0 <= e < 1, the angles within their
/// ranges, near-Earth (period < 225 min), and SGP4 able to start from it. Throws TleElementsError.
Tle checked_tle_from_elements(const TleElements& e);

/// Parses and validates a two-line element set: each line at least 69 columns (trailing blanks and a
/// carriage return allowed), its line number in column 1, blanks where the format has them, every field
/// a number of its format, the modulo-10 checksum in column 69 of each line, the same catalog number on
/// both, elements within their ranges. Refuses a deep-space set (period >= 225 min, which needs SDP4)
/// and one SGP4 cannot start from (e.g. a perigee below the Earth's surface). Throws TleError.
Tle parse_tle(std::string_view line1, std::string_view line2);

/// The modulo-10 checksum of a line's first 68 columns (digits count their value, '-' counts 1).
int tle_checksum(std::string_view line);

inline Tle tle_from_elements(const TleElements& e) noexcept {
    Tle t;
    t.epoch_jd_utc = e[0];
    const CalendarDay day = calendar_day(e[0]);
    t.epoch_year = day.year;
    t.epoch_day = e[0] - julian_date_at_midnight(day.year, 1, 1) + 1.0;
    t.mean_motion_rev_per_day = e[1];
    t.eccentricity = e[2];
    t.inclination_deg = e[3];
    t.raan_deg = e[4];
    t.arg_perigee_deg = e[5];
    t.mean_anomaly_deg = e[6];
    t.bstar_per_earth_radius = e[7];
    return t;
}

template <typename T>
MeanElements<T> Tle::mean_elements() const noexcept {
    constexpr double pi = 3.14159265358979323846;
    constexpr double deg = pi / 180.0;
    const MeanElements<double> e{mean_motion_rev_per_day / (1440.0 / (2.0 * pi)),
                                 eccentricity,
                                 inclination_deg * deg,
                                 raan_deg * deg,
                                 arg_perigee_deg * deg,
                                 mean_anomaly_deg * deg,
                                 bstar_per_earth_radius};
    return e.as<T>();
}

}  // namespace orbit
