#include "attitude_estimator/reference_error.hpp"

#include <cmath>

#include <Eigen/Dense>

namespace attitude_estimator {

namespace {
constexpr int kSamples = 72;         // points over one period
constexpr double kMu = 398600.4418;  // km³/s²: the period from the semi-major axis (its length only)
constexpr double kPi = 3.14159265358979323846;

// Earth-fixed → TEME axes by GMST (the turn is fitted in inertial axes, where the dynamics hold the spacecraft's
// angular momentum).
Eigen::Vector3d inertial(const Eigen::Vector3d& v, double gmst) {
    const double c = std::cos(gmst), s = std::sin(gmst);
    return {c * v(0) - s * v(1), s * v(0) + c * v(1), v(2)};
}

template <class T>
Eigen::Vector3d to_eigen(const Vec3<T>& v) {
    return {static_cast<double>(v[0]), static_cast<double>(v[1]), static_cast<double>(v[2])};
}

// The least-squares fit of one rotation θ to field errors e_k seen against fields B_k, e_k ≈ B_k × θ: its normal
// equations, accumulated.
struct TurnFit {
    Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
    Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
    void add(const Eigen::Vector3d& field, const Eigen::Vector3d& error) {
        Eigen::Matrix3d cross;
        cross << 0.0, -field(2), field(1), field(2), 0.0, -field(0), -field(1), field(0), 0.0;
        normal += cross.transpose() * cross;
        rhs += cross.transpose() * error;
    }
    // The fitted rotation's angle (rad); 0 when the fields do not fix it.
    double angle() const {
        const Eigen::LDLT<Eigen::Matrix3d> ldlt(normal);
        if (ldlt.info() != Eigen::Success || !(normal.trace() > 0.0)) return 0.0;
        const Eigen::Vector3d theta = ldlt.solve(rhs);
        return theta.allFinite() ? theta.norm() : 0.0;
    }
};

// TEME (km) → Earth-fixed (m) by GMST, in the model's type.
template <class T>
Vec3<T> earth_fixed(const Vec3<double>& r_km, double gmst) {
    const double c = std::cos(gmst), s = std::sin(gmst);
    return {static_cast<T>(1e3 * (c * r_km[0] + s * r_km[1])), static_cast<T>(1e3 * (-s * r_km[0] + c * r_km[1])),
            static_cast<T>(1e3 * r_km[2])};
}
}  // namespace

template <class T>
ReferenceFieldError reference_field_error(const FieldModel<T>& model, const CalendarInstant& clock_epoch,
                                          const orbit::MeanElements<double>& elements,
                                          double tle_epoch_julian_date) noexcept {
    orbit::Sgp4<double> dragged, undragged;
    orbit::MeanElements<double> no_drag = elements;
    no_drag.bstar_per_earth_radius = 0.0;
    if (dragged.initialize(elements) != orbit::Sgp4Status::ok || undragged.initialize(no_drag) != orbit::Sgp4Status::ok)
        return {};
    const OnboardClock<double> clock = make_onboard_clock<double>(clock_epoch);
    const double minutes_at_midnight = (clock.midnight_days + 2451545.0 - tle_epoch_julian_date) * 1440.0;
    const double a_km = dragged.semi_major_axis_km();
    const double period = 2.0 * kPi * std::sqrt(a_km * a_km * a_km / kMu);
    double displacement = 0.0, field = 0.0;  // m², T²
    TurnFit turn;
    for (int k = 0; k < kSamples; ++k) {
        const double t = period * k / kSamples;
        const double minutes = minutes_at_midnight + seconds_of_epoch_day(clock, t) / 60.0;
        orbit::OrbitState<double> with, without;
        if (dragged.propagate(minutes, with) != orbit::Sgp4Status::ok ||
            undragged.propagate(minutes, without) != orbit::Sgp4Status::ok)
            return {};
        const Vec3<double> r{with.position_km[0], with.position_km[1], with.position_km[2]};
        const Vec3<double> r0{without.position_km[0], without.position_km[1], without.position_km[2]};
        double d2 = 0.0;
        for (int i = 0; i < 3; ++i) d2 += 1e6 * (r[i] - r0[i]) * (r[i] - r0[i]);
        displacement += d2;
        const double gmst = gmst_at(clock, t);
        const T year = static_cast<T>(decimal_year_at(clock, t));
        const Vec3<T> b = field_ecef(model, earth_fixed<T>(r, gmst), year);
        const Vec3<T> b0 = field_ecef(model, earth_fixed<T>(r0, gmst), year);
        for (int i = 0; i < 3; ++i) {
            const double db = static_cast<double>(b[i]) - static_cast<double>(b0[i]);
            field += db * db;
        }
        turn.add(inertial(to_eigen(b), gmst), inertial(to_eigen(b) - to_eigen(b0), gmst));
    }
    ReferenceFieldError e;
    e.truncation = omitted_field_rms(model.degree, 1e3 * a_km, decimal_year_at(clock, 0.0));
    e.position = std::sqrt(field / (3.0 * kSamples));
    e.drag_displacement = std::sqrt(displacement / kSamples);
    e.rms = std::sqrt(e.truncation * e.truncation + e.position * e.position);
    e.turn = turn.angle();
    return e;
}

template ReferenceFieldError reference_field_error(const FieldModel<float>&, const CalendarInstant&,
                                                   const orbit::MeanElements<double>&, double) noexcept;
template ReferenceFieldError reference_field_error(const FieldModel<double>&, const CalendarInstant&,
                                                   const orbit::MeanElements<double>&, double) noexcept;

}  // namespace attitude_estimator
