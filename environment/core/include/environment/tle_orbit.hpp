#pragma once
// The truth orbit from a two-line element set: SGP4 in double (orbit/sgp4.hpp, Vallado et al. 2006) in
// TEME, rotated to J2000 (orbit/frames.hpp: IAU 1980 nutation, full 106 terms, and IAU 1976 precession),
// positions in metres. Time t is seconds since the environment's epoch; the element set's own epoch may
// lie before or after it (the offset is a parameter of the propagation, not an error).
#include <Eigen/Core>

#include "environment/node_interpolator.hpp"
#include "environment/time_scales.hpp"
#include "orbit/sgp4.hpp"
#include "orbit/tle.hpp"

namespace environment {

class TleOrbit {
public:
    /// Throws std::invalid_argument when SGP4 cannot start from the set (tle.hpp's parse_tle refuses those
    /// already; this guards a Tle filled by hand).
    TleOrbit(const orbit::Tle& tle, const UtcDate& epoch);

    /// J2000 position (m) and velocity (m/s) at t s after the environment's epoch. Throws
    /// std::domain_error naming the time and SGP4's reason when it cannot propagate (the satellite has
    /// decayed, or drag drove the mean elements out of range).
    struct State {
        Eigen::Vector3d position;
        Eigen::Vector3d velocity;
    };
    State state_eci(double t) const;

    /// The rotation TEME -> J2000 is evaluated at nodes this far apart and interpolated linearly between:
    /// its entries' second derivatives are below 1e-16 /s^2 (the nutation's 13.7-day term: 1e-6 rad at
    /// (5.3e-6 rad/s)^2), so the interpolation is within 60^2/8 * 1e-16 < 1e-13 rad, 1 um of the orbit.
    static constexpr double kFrameInterval = 60.0;  // s

    /// Minutes from the element set's epoch to the environment's (t = 0), from whole days and day fractions
    /// apart: one Julian date in a double resolves only 40 us, 0.3 m of the orbit.
    double minutes_from_tle_epoch() const { return minutes_offset_; }
    /// The mean orbital period at the set's epoch (s), from SGP4's un-Kozai'd mean motion.
    double period() const { return 60.0 * sgp4_.period_minutes(); }
    const orbit::Tle& tle() const { return tle_; }

private:
    orbit::Tle tle_;
    orbit::Sgp4<double> sgp4_;
    double epoch_jd_;
    double minutes_offset_;
    mutable NodeInterpolator frame_{kFrameInterval, 9};  // j2000_from_teme, column-major
};

}  // namespace environment
