#include "orbit/orbit_classes.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "orbit/element_age.hpp"
#include "orbit/sgp4.hpp"

namespace orbit {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
constexpr double kJ2000 = 2451545.0;

void check_altitude(double altitude_km) {
    if (!(altitude_km >= kMinOrbitAltitudeKm && altitude_km <= kMaxOrbitAltitudeKm))
        throw std::invalid_argument("orbit altitude " + std::to_string(altitude_km) + " km outside [" +
                                    std::to_string(kMinOrbitAltitudeKm) + ", " + std::to_string(kMaxOrbitAltitudeKm) +
                                    "] km (kMinOrbitAltitudeKm, kMaxOrbitAltitudeKm)");
}

double wrap(double a, double period) {
    a = std::fmod(a, period);
    return a < 0.0 ? a + period : a;
}

}  // namespace

double kozai_mean_motion_for_altitude(double altitude_km, double eccentricity, double inclination_deg) {
    check_altitude(altitude_km);
    // SGP4's initialization (Vallado et al. 2006, initl): from the Kozai n_K, ak = (xke/n_K)^(2/3),
    // δ1 = d1/ak², adel = ak (1 - δ1² - δ1 (1/3 + 134 δ1²/81)), δ0 = d1/adel², n = n_K / (1 + δ0), and the
    // mean axis a = (xke/n)^(2/3) Earth radii. Given a: n, then n_K = n (1 + δ0(n_K)) by iteration (δ0 ~ 1e-3).
    const double xke =
        60.0 / std::sqrt(Wgs72::earth_radius_km * Wgs72::earth_radius_km * Wgs72::earth_radius_km / Wgs72::mu_km3_s2);
    const double a = (Wgs72::earth_radius_km + altitude_km) / Wgs72::earth_radius_km;
    const double n = xke / std::pow(a, 1.5);  // rad/min
    const double cosi = std::cos(inclination_deg * kDeg);
    const double omeosq = 1.0 - eccentricity * eccentricity;
    const double d1 = 0.75 * Wgs72::j2 * (3.0 * cosi * cosi - 1.0) / (std::sqrt(omeosq) * omeosq);
    double kozai = n;
    for (int i = 0; i < 50; ++i) {
        const double ak = std::pow(xke / kozai, 2.0 / 3.0);
        const double del = d1 / (ak * ak);
        const double adel = ak * (1.0 - del * del - del * (1.0 / 3.0 + 134.0 * del * del / 81.0));
        kozai = n * (1.0 + d1 / (adel * adel));
    }
    return kozai * 1440.0 / (2.0 * kPi);
}

Tle circular_orbit_set(double epoch_jd_utc, double altitude_km, double inclination_deg, double raan_deg,
                       double arg_latitude_deg, double bstar, double eccentricity) {
    const TleElements e{epoch_jd_utc,
                        kozai_mean_motion_for_altitude(altitude_km, eccentricity, inclination_deg),
                        eccentricity,
                        inclination_deg,
                        wrap(raan_deg, 360.0),
                        0.0,
                        wrap(arg_latitude_deg, 360.0),
                        bstar};
    return checked_tle_from_elements(e);
}

double mean_sun_right_ascension_deg(double jd_utc) {
    return wrap(280.460 + kMeanSunRateDegPerDay * (jd_utc - kJ2000), 360.0);
}

double sun_synchronous_inclination_deg(double altitude_km, double eccentricity) {
    check_altitude(altitude_km);
    // SGP4's nodal rate grows (towards the east) as cos i falls below 0: bisection on i in (90, 180).
    const auto rate = [&](double inclination_deg) {
        Tle t = tle_from_elements({kJ2000, kozai_mean_motion_for_altitude(altitude_km, eccentricity, inclination_deg),
                                   eccentricity, inclination_deg, 0.0, 0.0, 0.0, 0.0});
        return secular_rates(t).raan_deg_per_day;
    };
    double low = 90.0, high = 180.0;  // rate(90) = 0 < target, rate(180) > target for every LEO altitude
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (low + high);
        (rate(mid) < kMeanSunRateDegPerDay ? low : high) = mid;
    }
    return 0.5 * (low + high);
}

double raan_for_ltan_deg(double ltan_hours, double jd_utc) {
    if (!(ltan_hours >= 0.0 && ltan_hours < 24.0))
        throw std::invalid_argument("local time of the ascending node " + std::to_string(ltan_hours) +
                                    " h outside [0, 24)");
    return wrap(mean_sun_right_ascension_deg(jd_utc) + 15.0 * (ltan_hours - 12.0), 360.0);
}

double ltan_hours(double raan_deg, double jd_utc) {
    return wrap(12.0 + (raan_deg - mean_sun_right_ascension_deg(jd_utc)) / 15.0, 24.0);
}

Tle sun_synchronous_set(double epoch_jd_utc, double altitude_km, double ltan, double arg_latitude_deg, double bstar) {
    return circular_orbit_set(epoch_jd_utc, altitude_km, sun_synchronous_inclination_deg(altitude_km),
                              raan_for_ltan_deg(ltan, epoch_jd_utc), arg_latitude_deg, bstar);
}

}  // namespace orbit
