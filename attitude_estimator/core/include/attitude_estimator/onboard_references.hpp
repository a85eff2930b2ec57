// The on-board computer's reference vectors, computed from what a flight computer has: its own two-line
// element set propagated by SGP4 (the orbit/ library), the almanac sun (onboard_sun.hpp) and IGRF-14
// truncated to a degree (onboard_field.hpp), all at its own clock (onboard_clock.hpp). No truth enters.
//
// Rate: a flight computer evaluates its orbit and field models slower than it samples its sensors. Here
// they are evaluated on a grid of `period` seconds (default 10 s) of the clock, always one knot ahead,
// and each sample interpolates linearly between the two knots around it. The field's direction in J2000
// turns at about twice the orbital rate (2.2e-3 rad/s at 570 km), so the chord of a 10 s interval is off
// by at most ω²Δ²/8 = 6e-5 rad (0.003°), well below the degree-8 model's 0.08°; the cost is one orbit,
// field and sun evaluation every 200 samples at 20 Hz instead of every sample.
// Templated on float/double, no heap, no exceptions.
#pragma once

#include <cstdint>

#include "attitude_estimator/onboard_clock.hpp"
#include "attitude_estimator/onboard_field.hpp"
#include "attitude_estimator/onboard_sun.hpp"
#include "attitude_estimator/types.hpp"
#include "orbit/sgp4.hpp"

namespace attitude_estimator {

// Where the computer's reference vectors come from (the `reference_source` choice).
enum class ReferenceSource : std::int32_t {
    inputs = 0,   // fed from outside: a GPS receiver and its own models, or the truth-fed study
    onboard = 1,  // computed on board from its TLE, sun ephemeris and field model at its own clock
};

template <class T>
struct OnboardReferenceConfig {
    OnboardClock<T> clock{};
    FieldModel<T> field{};
    orbit::Sgp4<T> orbit{};            // initialized from the computer's own element set
    T tle_minutes_at_midnight = T(0);  // min from the element set's epoch to 0 h UTC of the clock's epoch day
    T period = T(10);                  // s between two evaluations of the models (> 0)
};

// The references at one instant of the clock.
template <class T>
struct ReferenceKnot {
    T t = T(0);              // s, the block's time
    Vec3<T> sun{};           // unit vector, J2000
    T sun_distance = T(0);   // m
    Vec3<T> field{};         // T, J2000
    Vec3<T> position{};      // km, TEME (the on-board orbit, for the record)
    Vec3<T> air_velocity{};  // m/s, J2000: the orbit's velocity against the co-rotating air (its Earth-fixed velocity)
    T altitude = T(0);       // m above the WGS-84 ellipsoid (ground/atmosphere_table.hpp)
    bool valid = false;      // SGP4 propagated without error
};

// The two knots around the last sample (trivially copyable: part of the computer's state).
template <class T>
struct ReferenceState {
    ReferenceKnot<T> before{};
    ReferenceKnot<T> after{};
    std::int64_t index = 0;  // `before` is knot index·period
    bool started = false;
};

template <class T>
struct References {
    Vec3<T> sun{};
    T sun_distance = T(0);
    Vec3<T> field{};
    Vec3<T> position{};      // km, TEME: the on-board orbit (zero when the references are the inputs)
    Vec3<T> air_velocity{};  // m/s, J2000: its velocity against the co-rotating air (zero: inputs)
    T altitude = T(0);       // m above the ellipsoid (0: inputs)
    bool valid = false;      // false when SGP4 failed (a decayed or unusable element set): the sample has no field
};

// The configuration from the computer's own element set (its mean elements and epoch, parsed from the
// text by the orbit library on the host: orbit::parse_tle), the clock's epoch, the field model's degree
// (1 … 13) and the evaluation period (s, > 0). Computed in double, rounded once to T. Returns SGP4's
// status at the element set's epoch (ok, deep_space, or an error of the elements).
template <class T>
orbit::Sgp4Status make_reference_config(OnboardReferenceConfig<T>& config, const CalendarInstant& clock_epoch,
                                        const orbit::MeanElements<double>& elements, double tle_epoch_julian_date,
                                        std::int32_t field_degree, double period) noexcept;

// One evaluation of the models at the block's time t: SGP4 at the clock's minutes since the element set's
// epoch, TEME → Earth-fixed by GMST (TEME's equinox is the mean one on the true equator: the equation of
// the equinoxes, < 1.2 s of rotation, is left out, as is nutation), the field there rotated to J2000 as the
// environment does (r_ecef = R3(GMST) P r_J2000), the sun.
template <class T>
ReferenceKnot<T> evaluate_references(const OnboardReferenceConfig<T>& config, T t) noexcept;

// The references at time t, interpolated between the knots of the evaluation grid (evaluating the next
// knot when t passes one, both when t is outside the pair, e.g. at the first sample).
template <class T>
References<T> onboard_references(ReferenceState<T>& state, const OnboardReferenceConfig<T>& config, T t) noexcept;

extern template orbit::Sgp4Status make_reference_config(OnboardReferenceConfig<float>&, const CalendarInstant&,
                                                        const orbit::MeanElements<double>&, double, std::int32_t,
                                                        double) noexcept;
extern template orbit::Sgp4Status make_reference_config(OnboardReferenceConfig<double>&, const CalendarInstant&,
                                                        const orbit::MeanElements<double>&, double, std::int32_t,
                                                        double) noexcept;
extern template ReferenceKnot<float> evaluate_references(const OnboardReferenceConfig<float>&, float) noexcept;
extern template ReferenceKnot<double> evaluate_references(const OnboardReferenceConfig<double>&, double) noexcept;
extern template References<float> onboard_references(ReferenceState<float>&, const OnboardReferenceConfig<float>&,
                                                     float) noexcept;
extern template References<double> onboard_references(ReferenceState<double>&, const OnboardReferenceConfig<double>&,
                                                      double) noexcept;

}  // namespace attitude_estimator
