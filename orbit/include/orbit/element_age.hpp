#pragma once
// An element set moved to another epoch along SGP4's own secular rates: the mean anomaly, the argument of
// perigee and the node advanced by their J2, J2² and J4 rates (Sgp4's initialization, Vallado et al. 2006),
// the mean motion, eccentricity, inclination and B* kept. How the scenario's set becomes the on-board
// computer's older uplinked set (uplink_age), and how a campaign moves a set to the date it draws.
// It is the method of attitude_estimator/study/older_tle.py (tested against it), with the epoch crossing
// year boundaries. SGP4 propagating the moved set does not land exactly on the original: its drag term
// (B*) acts over the difference and its periodic terms start from another phase; that difference is the
// age error an older set carries.
//
// Header-only, no heap, no exceptions, double arithmetic at configure time: the firmware derives its set
// with it too. The plausibility rule (how far from its epoch a set may be used) is element_plausibility.hpp.
#include <cmath>

#include "orbit/sgp4.hpp"
#include "orbit/tle.hpp"

namespace orbit {

/// The secular rates of a set (deg/day), from SGP4's initialization; all zero when SGP4 cannot start from
/// the set (the caller has checked it: parse_tle, checked_tle_from_elements).
struct SecularRates {
    double mean_anomaly_deg_per_day = 0.0;
    double arg_perigee_deg_per_day = 0.0;
    double raan_deg_per_day = 0.0;
};

inline SecularRates secular_rates(const Tle& tle) noexcept {
    Sgp4<double> sgp4;
    if (sgp4.initialize(tle.mean_elements<double>()) != Sgp4Status::ok) return {};
    constexpr double per_day = 1440.0 * 180.0 / 3.14159265358979323846;  // rad/min -> deg/day
    return {sgp4.mean_anomaly_rate() * per_day, sgp4.arg_perigee_rate() * per_day, sgp4.raan_rate() * per_day};
}

namespace element_age_detail {
inline double wrap_degrees(double a) noexcept {
    a = std::fmod(a, 360.0);
    return a < 0.0 ? a + 360.0 : a;
}
}  // namespace element_age_detail

/// The set at another epoch (Julian date, UTC): angles advanced by their secular rates over the difference
/// and wrapped to [0, 360), the epoch's year and day of year those of the new date (any year boundary).
inline Tle reepoched(const Tle& tle, double epoch_jd_utc) noexcept {
    const SecularRates r = secular_rates(tle);
    const double days = epoch_jd_utc - tle.epoch_jd_utc;
    TleElements e = elements_of(tle);
    e[0] = epoch_jd_utc;
    e[4] = element_age_detail::wrap_degrees(tle.raan_deg + r.raan_deg_per_day * days);
    e[5] = element_age_detail::wrap_degrees(tle.arg_perigee_deg + r.arg_perigee_deg_per_day * days);
    e[6] = element_age_detail::wrap_degrees(tle.mean_anomaly_deg + r.mean_anomaly_deg_per_day * days);
    Tle out = tle_from_elements(e);
    out.catalog_number = tle.catalog_number;
    return out;
}

/// The same satellite's set `age_seconds` older (its epoch that much earlier; a negative age is newer).
inline Tle older_set(const Tle& tle, double age_seconds) noexcept {
    return reepoched(tle, tle.epoch_jd_utc - age_seconds / 86400.0);
}

}  // namespace orbit
