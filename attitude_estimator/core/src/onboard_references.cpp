#include "attitude_estimator/onboard_references.hpp"

#include <cmath>

#include "ground/atmosphere_table.hpp"

namespace attitude_estimator {

template <class T>
orbit::Sgp4Status make_reference_config(OnboardReferenceConfig<T>& c, const CalendarInstant& clock_epoch,
                                        const orbit::MeanElements<double>& elements, double tle_epoch_julian_date,
                                        std::int32_t field_degree, double period) noexcept {
    c.clock = make_onboard_clock<T>(clock_epoch);
    c.field = make_field_model<T>(field_degree);
    c.period = static_cast<T>(period);
    const double midnight = static_cast<double>(c.clock.midnight_days) + 2451545.0;  // exact: a half-integer
    c.tle_minutes_at_midnight = static_cast<T>((midnight - tle_epoch_julian_date) * 1440.0);
    return c.orbit.initialize(elements.as<T>());
}

template <class T>
ReferenceKnot<T> evaluate_references(const OnboardReferenceConfig<T>& c, T t) noexcept {
    ReferenceKnot<T> k;
    k.t = t;
    const SunReference<T> sun = onboard_sun(c.clock, t);
    k.sun = sun.direction;
    k.sun_distance = sun.distance;
    orbit::OrbitState<T> state;
    const T minutes = c.tle_minutes_at_midnight + seconds_of_epoch_day(c.clock, t) / T(60);
    k.valid = c.orbit.propagate(minutes, state) == orbit::Sgp4Status::ok;
    if (!k.valid) return k;
    const Vec3<T> r_teme{state.position_km[0], state.position_km[1], state.position_km[2]};
    k.position = r_teme;
    // TEME → Earth-fixed: R3(GMST).
    const T a = gmst_at(c.clock, t);
    const T ca = std::cos(a), sa = std::sin(a);
    const Vec3<T> r_ecef{T(1000) * (ca * r_teme[0] + sa * r_teme[1]), T(1000) * (-sa * r_teme[0] + ca * r_teme[1]),
                         T(1000) * r_teme[2]};
    const Vec3<T> b_ecef = field_ecef(c.field, r_ecef, decimal_year_at(c.clock, t));
    // Earth-fixed → J2000: the transpose of ecef_from_j2000.
    const Matrix3RowMajor<T> m = ecef_from_j2000(c.clock, t);
    for (int i = 0; i < 3; ++i) k.field[i] = m[i] * b_ecef[0] + m[3 + i] * b_ecef[1] + m[6 + i] * b_ecef[2];
    // The drag's wind: the velocity in the Earth-fixed frame, where the air is at rest (the atmosphere co-rotates),
    // d/dt (R3(GMST) r) = R3(GMST) v − ω_E ẑ × r_ecef, turned to J2000 as the field is.
    const Vec3<T> v_teme{T(1000) * state.velocity_km_s[0], T(1000) * state.velocity_km_s[1],
                         T(1000) * state.velocity_km_s[2]};
    const T omega_earth = static_cast<T>(ground::atmosphere::kEarthRotationRate);
    const Vec3<T> v_ecef{ca * v_teme[0] + sa * v_teme[1] + omega_earth * r_ecef[1],
                         -sa * v_teme[0] + ca * v_teme[1] - omega_earth * r_ecef[0], v_teme[2]};
    for (int i = 0; i < 3; ++i) k.air_velocity[i] = m[i] * v_ecef[0] + m[3 + i] * v_ecef[1] + m[6 + i] * v_ecef[2];
    k.altitude = ground::atmosphere::ellipsoid_altitude(r_ecef[0], r_ecef[1], r_ecef[2]);
    return k;
}

template <class T>
References<T> onboard_references(ReferenceState<T>& s, const OnboardReferenceConfig<T>& c, T t) noexcept {
    const bool inside = s.started && t >= s.before.t && t < s.after.t;
    if (!inside) {
        const auto index = static_cast<std::int64_t>(std::floor(t / c.period));
        if (s.started && index == s.index + 1) {
            s.before = s.after;  // the next interval: one evaluation
        } else {
            s.before = evaluate_references(c, static_cast<T>(index) * c.period);
        }
        s.after = evaluate_references(c, static_cast<T>(index + 1) * c.period);
        s.index = index;
        s.started = true;
    }
    const T w = (t - s.before.t) / (s.after.t - s.before.t);
    References<T> r;
    r.valid = s.before.valid && s.after.valid;
    T norm = T(0);
    for (int i = 0; i < 3; ++i) {
        r.sun[i] = s.before.sun[i] + w * (s.after.sun[i] - s.before.sun[i]);
        r.field[i] = s.before.field[i] + w * (s.after.field[i] - s.before.field[i]);
        r.position[i] = s.before.position[i] + w * (s.after.position[i] - s.before.position[i]);
        r.air_velocity[i] = s.before.air_velocity[i] + w * (s.after.air_velocity[i] - s.before.air_velocity[i]);
        norm += r.sun[i] * r.sun[i];
    }
    norm = std::sqrt(norm);
    for (auto& v : r.sun) v /= norm;
    r.sun_distance = s.before.sun_distance + w * (s.after.sun_distance - s.before.sun_distance);
    r.altitude = s.before.altitude + w * (s.after.altitude - s.before.altitude);
    return r;
}

template orbit::Sgp4Status make_reference_config(OnboardReferenceConfig<float>&, const CalendarInstant&,
                                                 const orbit::MeanElements<double>&, double, std::int32_t,
                                                 double) noexcept;
template orbit::Sgp4Status make_reference_config(OnboardReferenceConfig<double>&, const CalendarInstant&,
                                                 const orbit::MeanElements<double>&, double, std::int32_t,
                                                 double) noexcept;
template ReferenceKnot<float> evaluate_references(const OnboardReferenceConfig<float>&, float) noexcept;
template ReferenceKnot<double> evaluate_references(const OnboardReferenceConfig<double>&, double) noexcept;
template References<float> onboard_references(ReferenceState<float>&, const OnboardReferenceConfig<float>&,
                                              float) noexcept;
template References<double> onboard_references(ReferenceState<double>&, const OnboardReferenceConfig<double>&,
                                               double) noexcept;

}  // namespace attitude_estimator
