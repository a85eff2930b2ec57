#pragma once
// Physical constants used by the environment model (SI units).

namespace environment {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kDegToRad = kPi / 180.0;
inline constexpr double kRadToDeg = 180.0 / kPi;

inline constexpr double kEarthRadius = 6378137.0;  // m, WGS-84 equatorial radius (orbit altitude, shadow, albedo)
inline constexpr double kEarthGravitationalParameter = 3.986004418e14;  // m^3/s^2, WGS-84 / EGM96 mu
inline constexpr double kIgrfReferenceRadius = 6371200.0;               // m, the IGRF's magnetic reference sphere
inline constexpr double kAstronomicalUnit = 1.495978707e11;             // m, IAU 2012 definition
inline constexpr double kSunRadius = 6.957e8;                           // m, IAU 2015 nominal solar radius
inline constexpr double kSolarConstant = 1367.0;                        // W/m^2 at 1 AU, seed 000 section 4
inline constexpr double kJulianDateJ2000 = 2451545.0;                   // 2000-01-01 12:00 TT
inline constexpr double kSecondsPerDay = 86400.0;

}  // namespace environment
