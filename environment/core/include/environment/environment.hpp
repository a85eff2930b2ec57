#pragma once
// The truth the sensors see: one plain parameter struct in, one plain output struct out.
//
//   environment::EnvironmentParams p;                 // defaults: seed scenario, 570 km / 64.9 deg orbit
//   environment::Environment env(p);                  // validates (throws std::invalid_argument)
//   auto out = env.evaluate(t);                       // spin mode: a pure function of time
//   // rigid_body mode: x = env.initial_state(); integrate env.derivative(t, x, dx) externally,
//   // call RigidBody::renormalize(x) after each step, and evaluate(t, &x).
#include <array>
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

#include "environment/circular_orbit.hpp"
#include "environment/disturbance_torques.hpp"
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
    /// The spacecraft's box, centre of mass, drag and optical properties and residual dipole: what the
    /// disturbance torques act on (disturbance_torques.hpp; the inertia is rigid_body.inertia).
    SpacecraftBody body;
    /// Gravity gradient, residual dipole, aerodynamic and solar pressure torques in Euler's equations
    /// (rigid_body mode); false: the torque-free body, and the torque outputs are zero.
    bool disturbance_torques = true;
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
    // The disturbance torques at the attitude (N m, body axes; zero with disturbance_torques off). In
    // rigid_body mode their sum drives Euler's equations; in spin mode they are what would act.
    std::array<double, 3> torque_gravity_gradient{};
    std::array<double, 3> torque_magnetic{};
    std::array<double, 3> torque_aerodynamic{};
    std::array<double, 3> torque_solar_pressure{};
};

class Environment {
public:
    explicit Environment(const EnvironmentParams& params);

    /// All outputs at t (s since epoch). In rigid_body mode `state` is required (the integrator's x);
    /// in spin mode it is ignored. Throws std::invalid_argument / std::domain_error on bad input
    /// (missing state, NaN, date outside IGRF-14's validity).
    EnvironmentOutputs evaluate(double t, const RigidBodyState* state = nullptr) const;

    /// Rigid body mode: the continuous states and their derivative at t (see rigid_body.hpp) under the
    /// disturbance torques at t and x (torque-free with disturbance_torques off). Costs the orbit, the sun,
    /// the eclipse and the field at t (no albedo).
    RigidBodyState initial_state() const { return rigid_body_.initial_state(); }
    void derivative(double t, const double* x, double* dx) const;
    /// The derivative under a torque already known (e.g. the sum of evaluate()'s torque outputs at t, x).
    void derivative(const double* x, const Eigen::Vector3d& torque_body, double* dx) const {
        rigid_body_.derivative(x, torque_body, dx);
    }

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
    void orbit_state(double t, Eigen::Vector3d& r, Eigen::Vector3d& v) const;  // m, m/s, ECI
    Eigen::Vector3d field_eci(double t, const Eigen::Vector3d& r) const;       // T (t s since epoch)
    /// The four torques at the attitude A (ECI -> body) from the orbit state, the field, the unit sun
    /// direction (ECI) and the irradiance at the satellite (after the eclipse).
    DisturbanceTorques torques(const Eigen::Matrix3d& A, const Eigen::Vector3d& r, const Eigen::Vector3d& v,
                               const Eigen::Vector3d& b_eci, const Eigen::Vector3d& sun_eci, double irradiance) const;

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
    std::array<Face, 6> faces_;  // from params.body
};

}  // namespace environment
