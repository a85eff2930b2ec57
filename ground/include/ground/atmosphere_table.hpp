#pragma once
// The thermosphere's density as the truth (environment/) and the on-board computer (attitude_estimator/core,
// also flashed onto the Cortex-M4F firmware) both evaluate it for the aerodynamic torque: an exponential
// model in altitude bands,
//
//   ρ(h) = ρ₀ exp(−(h − h₀) / H)        for h₀ ≤ h < h₁ (the band's base and the next one's),
//
// with the base densities ρ₀ and scale heights H of D. A. Vallado, Fundamentals of Astrodynamics and
// Applications, 4th ed., Microcosm Press, 2013, table 8-4 (from CIRA-72, mean solar activity), 0 to
// 1000 km; above 1000 km the last band continues. The altitude is taken above the WGS-84 ellipsoid, to
// first order in the flattening (the local radius a(1 − f sin²φ), φ the geocentric latitude).
//
// For the truth this is the atmosphere; for the flight software it is knowledge carried as a constant (a
// table of mean activity), and the real density departs from it by a factor of several over the solar cycle:
// the on-board filter's model says so in its own parameters (attitude_estimator/docs/filter.md, "Drag").
// Header-only, templated on the float type, no heap, no exceptions, no Eigen (the environment's
// atmosphere_density refuses an altitude below the surface; here one below 0 takes the lowest band).
#include <array>
#include <cmath>
#include <cstddef>

namespace ground::atmosphere {

struct Band {
    double base;     // km
    double density;  // kg/m³ at the base
    double scale;    // km, scale height
};

// Vallado (2013), table 8-4: exponential atmosphere from CIRA-72.
inline constexpr std::array<Band, 28> kBands = {{
    {0.0, 1.225, 7.249},        {25.0, 3.899e-2, 6.349},    {30.0, 1.774e-2, 6.682},    {40.0, 3.972e-3, 7.554},
    {50.0, 1.057e-3, 8.382},    {60.0, 3.206e-4, 7.714},    {70.0, 8.770e-5, 6.549},    {80.0, 1.905e-5, 5.799},
    {90.0, 3.396e-6, 5.382},    {100.0, 5.297e-7, 5.877},   {110.0, 9.661e-8, 7.263},   {120.0, 2.438e-8, 9.473},
    {130.0, 8.484e-9, 12.636},  {140.0, 3.845e-9, 16.149},  {150.0, 2.070e-9, 22.523},  {180.0, 5.464e-10, 29.740},
    {200.0, 2.789e-10, 37.105}, {250.0, 7.248e-11, 45.546}, {300.0, 2.418e-11, 53.628}, {350.0, 9.518e-12, 53.298},
    {400.0, 3.725e-12, 58.515}, {450.0, 1.585e-12, 60.828}, {500.0, 6.967e-13, 63.822}, {600.0, 1.454e-13, 71.835},
    {700.0, 3.614e-14, 88.667}, {800.0, 1.170e-14, 124.64}, {900.0, 5.245e-15, 181.05}, {1000.0, 3.019e-15, 268.00},
}};

inline constexpr double kWgs84EquatorialRadius = 6378137.0;  // m
inline constexpr double kWgs84Flattening = 1.0 / 298.257223563;
inline constexpr double kEarthRotationRate = 7.292115e-5;  // rad/s (WGS-84): the atmosphere co-rotates

/// Density (kg/m³) at the altitude h (m) above the ellipsoid; h below 0 (not finite: NaN) takes band 0.
template <class T>
T density(T altitude) {
    const T h = altitude / T(1000);  // km
    std::size_t k = kBands.size() - 1;
    while (k > 0 && !(static_cast<T>(kBands[k].base) <= h)) --k;
    const Band& b = kBands[k];
    return static_cast<T>(b.density) * std::exp(-(h - static_cast<T>(b.base)) / static_cast<T>(b.scale));
}

/// Altitude (m) of the point (x, y, z) (m, Earth-centred, any frame whose z is the Earth's axis) above the
/// WGS-84 ellipsoid, to first order in the flattening.
template <class T>
T ellipsoid_altitude(T x, T y, T z) {
    const T rn = std::sqrt(x * x + y * y + z * z);
    const T sin_lat = z / rn;
    return rn - static_cast<T>(kWgs84EquatorialRadius) * (T(1) - static_cast<T>(kWgs84Flattening) * sin_lat * sin_lat);
}

}  // namespace ground::atmosphere
