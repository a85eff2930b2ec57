#pragma once
// SGP4, the near-Earth part of the NORAD general perturbations model, as published in Vallado, Crawford,
// Hujsak & Kelso (2006), "Revisiting Spacetrack Report #3", AIAA 2006-6753, with its reference code's
// WGS-72 constants (Hoots & Roehrich 1980, Spacetrack Report #3, is the original).
//
// Templated on the floating type: double for the simulation's truth, float for the Cortex-M4F firmware.
// initialize() and propagate() use no heap, no exceptions and no I/O. Deep-space element sets (period
// >= 225 min, SDP4) are refused with Sgp4Status::deep_space.
//
// Output: position (km) and velocity (km/s) in TEME, the true-equator, mean-equinox frame of the
// element set's epoch (frames.hpp takes them to J2000).
#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <type_traits>

namespace orbit {

template <typename T>
using Vector3 = Eigen::Matrix<T, 3, 1>;

/// The mean elements SGP4 starts from, in its own units (a TLE's, converted: tle.hpp's mean_elements()).
template <typename T>
struct MeanElements {
    T mean_motion_rad_per_min{};  // Kozai mean motion, as a TLE carries it
    T eccentricity{};
    T inclination_rad{};
    T raan_rad{};  // right ascension of the ascending node
    T arg_perigee_rad{};
    T mean_anomaly_rad{};
    T bstar_per_earth_radius{};  // drag term B*

    template <typename U>
    MeanElements<U> as() const noexcept {
        return {static_cast<U>(mean_motion_rad_per_min), static_cast<U>(eccentricity),
                static_cast<U>(inclination_rad),         static_cast<U>(raan_rad),
                static_cast<U>(arg_perigee_rad),         static_cast<U>(mean_anomaly_rad),
                static_cast<U>(bstar_per_earth_radius)};
    }
};

/// The reference code's error codes (same numbers), plus deep_space for an element set SGP4 alone cannot
/// propagate.
enum class Sgp4Status : std::uint8_t {
    ok = 0,
    mean_eccentricity = 1,       // mean eccentricity out of [-0.001, 1) (drag drove it out, or bad input)
    mean_motion = 2,             // mean motion <= 0 (drag)
    perturbed_eccentricity = 3,  // (deep space only in the reference code; kept for the numbering)
    semi_latus_rectum = 4,       // semi-latus rectum < 0
    decayed = 6,                 // the satellite is below the Earth's surface: it has decayed
    deep_space = 7,              // period >= 225 min: needs SDP4, which is not implemented
};

/// A sentence naming the status (static storage; no allocation).
inline const char* describe(Sgp4Status status) noexcept;

/// WGS-72 as the reference implementation uses it (Vallado et al. 2006, getgravconst "wgs72").
struct Wgs72 {
    static constexpr double mu_km3_s2 = 398600.8;
    static constexpr double earth_radius_km = 6378.135;
    static constexpr double j2 = 0.001082616;
    static constexpr double j3 = -0.00000253881;
    static constexpr double j4 = -0.00000165597;
};

/// The boundary between SGP4 and SDP4 (minutes of the un-Kozai'd mean motion's period).
inline constexpr double kDeepSpacePeriodMinutes = 225.0;

/// Position (km) and velocity (km/s) in the frame the producer names (TEME from Sgp4, J2000 from frames.hpp).
template <typename T>
struct OrbitState {
    Vector3<T> position_km = Vector3<T>::Zero();
    Vector3<T> velocity_km_s = Vector3<T>::Zero();
};

template <typename T>
class Sgp4 {
    static_assert(std::is_floating_point_v<T>, "Sgp4 is for float or double");

public:
    /// Computes the propagation coefficients; returns ok, deep_space, or the error of the epoch state.
    Sgp4Status initialize(const MeanElements<T>& elements) noexcept;

    /// Position and velocity in TEME at `minutes` since the element set's epoch (negative: before it).
    /// On an error the state holds what the model computed (meaningless for codes 1, 2 and 4).
    Sgp4Status propagate(T minutes, OrbitState<T>& state) const noexcept;

    bool initialized() const noexcept { return initialized_; }
    /// The orbital period (min) from SGP4's un-Kozai'd mean motion at epoch.
    T period_minutes() const noexcept;
    /// The mean semi-major axis at epoch (km).
    T semi_major_axis_km() const noexcept;
    /// The secular rates of the mean anomaly, the argument of perigee and the node (rad/min): the J2, J2²
    /// and J4 terms of the initialization (drag's are not in them). element_age.hpp moves a set with them.
    T mean_anomaly_rate() const noexcept { return mdot_; }
    T arg_perigee_rate() const noexcept { return argpdot_; }
    T raan_rate() const noexcept { return nodedot_; }
    const MeanElements<T>& elements() const noexcept { return elements_; }

private:
    MeanElements<T> elements_{};
    bool initialized_ = false;
    bool simple_ = false;  // isimp: perigee below 220 km, the truncated drag expansion
    T mean_motion_{};      // no_unkozai (rad/min)
    T ao_{}, eta_{}, con41_{}, x1mth2_{}, x7thm1_{};
    T cc1_{}, cc4_{}, cc5_{}, d2_{}, d3_{}, d4_{};
    T mdot_{}, argpdot_{}, nodedot_{}, nodecf_{}, omgcof_{}, xmcof_{}, xlcof_{}, aycof_{};
    T t2cof_{}, t3cof_{}, t4cof_{}, t5cof_{}, delmo_{}, sinmao_{};
};

}  // namespace orbit

#include "orbit/sgp4_model.hpp"  // the template's definitions (header-only for the firmware's float build)
