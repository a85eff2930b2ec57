#pragma once
// Orbit classes as SGP4 mean element sets: a circular orbit at a mean altitude, a sun-synchronous one by
// its local time of the ascending node, and the presets a campaign draws (ISS-like, polar, low
// inclination). Host only (throws std::invalid_argument on an altitude or time out of range).
//
// Altitude here is SGP4's mean semi-major axis (Sgp4::semi_major_axis_km) above WGS-72's 6378.135 km:
// the set is made so that SGP4 gives exactly that mean axis back.
#include "orbit/tle.hpp"

namespace orbit {

/// The presets' inclinations (deg) and the ISS-like altitude (km).
inline constexpr double kIssLikeInclinationDeg = 51.6;
inline constexpr double kIssLikeAltitudeKm = 420.0;
inline constexpr double kPolarInclinationDeg = 90.0;
inline constexpr double kLowInclinationDeg = 20.0;
/// Mean altitudes (km) the classes accept: above them SGP4's drag model is off; the upper bound keeps the
/// period below SDP4's 225 min by a wide margin.
inline constexpr double kMinOrbitAltitudeKm = 150.0;
inline constexpr double kMaxOrbitAltitudeKm = 2000.0;

/// The Kozai mean motion (rev/day, what a TLE carries) whose SGP4 mean semi-major axis is 6378.135 km +
/// altitude_km for this eccentricity and inclination (SGP4's un-Kozai step inverted by iteration).
double kozai_mean_motion_for_altitude(double altitude_km, double eccentricity, double inclination_deg);

/// A near-circular set (e = eccentricity, argument of perigee 0, the mean anomaly the argument of
/// latitude) at a mean altitude, epoch (JD UTC), inclination, node and B*; checked as a given set is.
Tle circular_orbit_set(double epoch_jd_utc, double altitude_km, double inclination_deg, double raan_deg,
                       double arg_latitude_deg, double bstar = 0.0, double eccentricity = 0.0);

/// The mean sun's rate (deg/day): 0.9856474, the Astronomical Almanac's rate of the sun's mean longitude
/// (one turn in 365.2422 days), what a sun-synchronous node must turn at.
inline constexpr double kMeanSunRateDegPerDay = 0.9856474;

/// The right ascension of the mean sun (deg, [0, 360)) at a Julian date: the Almanac's mean longitude
/// L = 280.460 + 0.9856474 n (n days from J2000), the reference of local mean time.
double mean_sun_right_ascension_deg(double jd_utc);

/// The inclination (deg, > 90) at which SGP4's secular nodal rate (J2, J2², J4) equals the mean sun's for
/// a mean altitude and eccentricity. J2 alone gives cos i = -2 ρ a^{7/2} (1-e²)² / (3 J2 R² √μ).
double sun_synchronous_inclination_deg(double altitude_km, double eccentricity = 0.0);

/// The node (deg, [0, 360)) of a local time of the ascending node (LTAN, hours of local mean time,
/// [0, 24)) at a date, and back: LTAN = 12 h + (Ω - α_mean sun) / 15°.
double raan_for_ltan_deg(double ltan_hours, double jd_utc);
double ltan_hours(double raan_deg, double jd_utc);

/// A sun-synchronous set at a date: its inclination from the nodal rate, its node from the LTAN.
Tle sun_synchronous_set(double epoch_jd_utc, double altitude_km, double ltan_hours, double arg_latitude_deg,
                        double bstar = 0.0);

}  // namespace orbit
