#pragma once
// The truth the sensors see: one plain parameter struct in, one plain output struct out.
//
//   environment::EnvironmentParams p;                 // defaults: seed scenario, 570 km / 64.9 deg orbit
//   environment::Environment env(p);                  // validates (throws std::invalid_argument)
//   auto out = env.evaluate(t);                       // spin mode: a pure function of time
//   // rigid_body mode: x = env.initial_state(); integrate env.derivative(x, dx) externally,
//   // call RigidBody::renormalize(x) after each step, and evaluate(t, &x).
#include <array>
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

#include "environment/circular_orbit.hpp"
#include "environment/earth_albedo.hpp"
#include "environment/node_interpolator.hpp"
#include "environment/rigid_body.hpp"
#include "environment/spin_attitude.hpp"
#include "environment/time_scales.hpp"
#include "environment/tle_orbit.hpp"
#include "orbit/tle.hpp"

namespace environment {

enum class AttitudeMode { spin = 0, rigid_body = 1 };
enum class SunModel { almanac = 0, seed002 = 1 };
enum class FieldModel { igrf14 = 0, dipole = 1 };
/// The truth orbit: the circular Kepler orbit of `orbit`, or SGP4 from the element set `tle`.
enum class OrbitModel { circular = 0, tle = 1 };

struct EnvironmentParams {
    AttitudeMode attitude_mode = AttitudeMode::spin;
    SpinParams spin;
    RigidBodyParams rigid_body;
    OrbitModel orbit_model = OrbitModel::circular;
    OrbitParams orbit;  // circular
    orbit::Tle tle;     // tle: the parsed set (orbit::parse_tle); its epoch may differ from `epoch`
    UtcDate epoch;      // UTC at t = 0; default 2026-03-20 00:00:00 (inside IGRF-14's 2025-2030)
    SunModel sun_model = SunModel::almanac;
    /// seed002 model only: the vernal equinox it counts days from (UTC), and the elevation amplitude (rad).
    UtcDate vernal_equinox{2026, 3, 20, 14, 46, 0.0};
    double seed002_elevation_amplitude = 23.439 * 3.14159265358979323846 / 180.0;
    double solar_constant = 1367.0;  // W/m^2 at 1 AU (seed 000 section 4)
    bool eclipse_enabled = true;
    FieldModel field_model = FieldModel::igrf14;
    int igrf_max_degree = 13;
    AlbedoParams albedo;
};

struct EnvironmentOutputs {
    double time = 0.0;                    // s since epoch
    double julian_date = 0.0;             // UTC
    double gmst = 0.0;                    // rad
    std::array<double, 4> q_true{};       // [x, y, z, w], ECI -> body
    std::array<double, 3> omega_body{};   // rad/s
    std::array<double, 3> r_eci{};        // m
    std::array<double, 3> v_eci{};        // m/s
    std::array<double, 3> sun_eci{};      // unit, satellite -> sun
    std::array<double, 3> sun_body{};     // unit
    double sun_distance = 0.0;            // m, satellite -> sun
    double sunlight_fraction = 1.0;       // 1 lit, 0 umbra
    double irradiance = 0.0;              // W/m^2 at the satellite, after eclipse
    std::array<double, 3> mag_eci{};      // T
    std::array<double, 3> mag_body{};     // T
    std::array<double, 6> albedo_face{};  // W/m^2 on +x, -x, +y, -y, +z, -z
    // The direct sun on each face, irradiance × max(0, cos β) (W/m^2, +x … −z, no panel's angular law): the
    // truth a fault campaign judges a face's visibility by (harness/campaigns/faults.toml).
    std::array<double, 6> sun_face{};
    // What a panel's heat balance needs of the Earth (panel_thermal): where it is and how bright.
    std::array<double, 3> nadir_body{};  // unit, satellite -> Earth's centre, body axes
    double orbit_radius_ratio = 1.0;     // r / R_E
    double albedo_source = 0.0;          // W/m^2, rho E_earth max(0, cos z_ss), z_ss the sun's zenith below
};

class Environment {
public:
    explicit Environment(const EnvironmentParams& params);

    /// All outputs at t (s since epoch). In rigid_body mode `state` is required (the integrator's x);
    /// in spin mode it is ignored. Throws std::invalid_argument / std::domain_error on bad input
    /// (missing state, NaN, date outside IGRF-14's validity).
    EnvironmentOutputs evaluate(double t, const RigidBodyState* state = nullptr) const;

    /// Rigid body mode: the continuous states and their derivative (see rigid_body.hpp).
    RigidBodyState initial_state() const { return rigid_body_.initial_state(); }
    void derivative(const double* x, double* dx) const { rigid_body_.derivative(x, dx); }

    const EnvironmentParams& params() const { return params_; }
    double epoch_julian_date() const { return jd0_; }
    const CircularOrbit& orbit() const { return orbit_; }
    /// The orbital period (s): the circular orbit's, or the element set's mean period at its epoch.
    double orbit_period() const { return tle_orbit_ ? tle_orbit_->period() : orbit_.period(); }
    const SpinAttitude& spin() const { return spin_; }

    /// The sun's position and the precession are evaluated at nodes this far apart and interpolated
    /// linearly: the Earth's curved path bends the sun's position by 2.7 m in 60 s (sagitta), 2e-11 rad,
    /// against the almanac formula's 2e-4 rad; precession's second derivative is nil at this scale.
    static constexpr double kSlowInterval = 60.0;  // s

private:
    Eigen::Vector3d sun_position_eci(double julian_date) const;  // m, Earth centre -> Sun, exact
    Eigen::Vector3d sun_position_at(double t) const;             // the same, from the nodes (t s since epoch)
    Eigen::Matrix3d precession_at(double t) const;               // J2000 -> mean of date, from the nodes
    void orbit_state(double t, Eigen::Vector3d& r, Eigen::Vector3d& v) const;

    EnvironmentParams params_;
    double jd0_;
    double jd_equinox_;
    CircularOrbit orbit_;
    std::optional<TleOrbit> tle_orbit_;  // OrbitModel::tle only
    RigidBody rigid_body_;
    SpinAttitude spin_;
    // Memos of the slow quantities' nodes (node_interpolator.hpp: the values are functions of t alone, so an
    // FMU state restored or a step taken again gives the same numbers). One instance is used by one thread.
    mutable NodeInterpolator sun_nodes_{kSlowInterval, 3};
    mutable NodeInterpolator precession_nodes_{kSlowInterval, 9};
    mutable std::optional<AlbedoHarmonics> albedo_harmonics_;  // albedo.interval > 0
    mutable std::optional<NodeInterpolator> albedo_nodes_;
    mutable std::vector<double> albedo_coefficients_;
};

}  // namespace environment
