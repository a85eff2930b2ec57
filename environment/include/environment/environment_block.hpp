#pragma once
// The environment core as an FMU block (environment.fmu): the variable table, and a thin evaluate()
// that builds environment::EnvironmentParams from the parameters, runs environment::Environment and
// copies its outputs. Time t of the FMU is seconds since the epoch parameters (UTC).
//
// Continuous states: q[1..4] (scalar-last, ECI -> body) and omega[1..3] (rad/s, body), always declared.
// In rigid_body mode they are the core's rigid body under the disturbance torques (torque-free with
// disturbance_torques = false), with a stabilizing term added to the
// quaternion kinematics so that |q| = 1 is attracting for any host integrator:
//   dq/dt = 1/2 Omega(w) q + k (1 - |q|^2) q,   k = quaternion_norm_gain [1/s]
// On |q| = 1 the added term vanishes, so the exact solution is unchanged; off it, d|q|^2/dt =
// 2k (1 - |q|^2)|q|^2 pulls the norm back with rate 2k (a Baumgarte-type stabilization). Outputs use
// q/|q|. Default k = 0.01/s (time constant 50 s): an explicit fixed-step host stays stable for steps
// h < 1/k = 100 s, and a host's norm error settles at about h |w|^2 / (16 k) instead of growing. In spin mode the derivatives are 0 and the outputs are pure functions of time.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "environment/environment.hpp"
#include "fmu/block.hpp"
#include "fmu/fixed_string.hpp"

namespace environment {

// Every variable of the block. Defaults: the core's (seed scenario, environment/README.md).
struct EnvironmentData {
    // --- parameters: attitude motion
    AttitudeMode attitude_mode = EnvironmentParams{}.attitude_mode;
    double spin_phi0 = 0.0;                                     // rad
    double spin_theta0 = 0.0;                                   // rad
    double spin_phi_dot = 1.26;                                 // rad/s, seed 000 section 4
    double spin_theta_dot = 6.28;                               // rad/s, seed 000 section 4
    std::array<double, 9> inertia = RigidBodyParams{}.inertia;  // kg m^2, row-major
    std::array<double, 4> q0 = RigidBodyParams{}.q0;            // [x, y, z, w], normalised on use
    std::array<double, 3> omega0 = RigidBodyParams{}.omega0;    // rad/s, body
    double quaternion_norm_gain = 0.01;                         // 1/s, k above (see its description)
    // --- parameters: the spacecraft the torques act on (docs/design.md, "The spacecraft")
    bool disturbance_torques = EnvironmentParams{}.disturbance_torques;
    std::array<double, 3> body_size = SpacecraftBody{}.size;                 // m
    std::array<double, 3> centre_of_mass = SpacecraftBody{}.centre_of_mass;  // m, from the box's centre
    double drag_coefficient = SpacecraftBody{}.drag_coefficient;             // 1
    double specular_reflectivity = SpacecraftBody{}.specular_reflectivity;   // 1
    double diffuse_reflectivity = SpacecraftBody{}.diffuse_reflectivity;     // 1
    std::array<double, 3> dipole_moment = SpacecraftBody{}.dipole_moment;    // A m^2, body
    // --- parameters: orbit
    OrbitModel orbit_model = EnvironmentParams{}.orbit_model;
    // The element set for orbit_model = tle: two lines (69 columns each; parsed by orbit::parse_tle in
    // configure()), or, when both are empty, its numbers in tle_elements (orbit::TleElements' layout, the
    // estimator's: epoch JD UTC, rev/day, e, i, node, perigee, M in deg, B* in 1/Earth radii). Default: the
    // bundled synthetic set matching the circular default (environment/README.md), as numbers
    // ("1 90001U          26079.00000000  .00002000  00000-0  15000-3 0  9995",
    //  "2 90001  64.9000   0.0000 0012000  90.0000 270.0000 14.98524078  1001").
    fmu::FixedString<80> tle_line1{};
    fmu::FixedString<80> tle_line2{};
    std::array<double, 8> tle_elements{2461119.5, 14.98524078, 0.0012, 64.9, 0.0, 90.0, 270.0, 1.5e-4};
    double orbit_altitude = OrbitParams{}.altitude;        // m
    double orbit_inclination = OrbitParams{}.inclination;  // rad
    double orbit_raan = 0.0;                               // rad
    double orbit_argument_of_latitude0 = 0.0;              // rad
    // --- parameters: epoch (UTC at t = 0)
    std::int32_t epoch_year = UtcDate{}.year;
    std::int32_t epoch_month = UtcDate{}.month;
    std::int32_t epoch_day = UtcDate{}.day;
    std::int32_t epoch_hour = UtcDate{}.hour;
    std::int32_t epoch_minute = UtcDate{}.minute;
    double epoch_second = UtcDate{}.second;  // s
    // --- parameters: sun
    SunModel sun_model = EnvironmentParams{}.sun_model;
    std::int32_t equinox_year = EnvironmentParams{}.vernal_equinox.year;
    std::int32_t equinox_month = EnvironmentParams{}.vernal_equinox.month;
    std::int32_t equinox_day = EnvironmentParams{}.vernal_equinox.day;
    std::int32_t equinox_hour = EnvironmentParams{}.vernal_equinox.hour;
    std::int32_t equinox_minute = EnvironmentParams{}.vernal_equinox.minute;
    double equinox_second = EnvironmentParams{}.vernal_equinox.second;                     // s
    double seed002_elevation_amplitude = EnvironmentParams{}.seed002_elevation_amplitude;  // rad
    double solar_constant = EnvironmentParams{}.solar_constant;                            // W/m^2
    bool eclipse_enabled = true;
    // --- parameters: field
    FieldModel field_model = EnvironmentParams{}.field_model;
    std::int32_t igrf_max_degree = EnvironmentParams{}.igrf_max_degree;
    // --- parameters: albedo
    bool albedo_enabled = true;
    double albedo_reflectivity = AlbedoParams{}.reflectivity;  // 1
    std::int32_t albedo_rings = AlbedoParams{}.rings;
    std::int32_t albedo_sectors = AlbedoParams{}.sectors;
    AlbedoResponse albedo_response = AlbedoParams{}.response;  // the faces' angular response to albedo
    ReflectivityModel albedo_reflectivity_model = AlbedoParams{}.model;
    double albedo_reflectivity_equator = AlbedoParams{}.reflectivity_equator;  // 1
    double albedo_reflectivity_pole = AlbedoParams{}.reflectivity_pole;        // 1
    double albedo_interval = AlbedoParams{}.interval;                          // s
    std::int32_t albedo_degree = AlbedoParams{}.degree;
    // --- calculated parameter
    double orbit_period = 0.0;  // s
    // --- continuous states and derivatives
    std::array<double, 4> q = {0.0, 0.0, 0.0, 1.0};
    std::array<double, 4> der_q{};
    std::array<double, 3> omega{};
    std::array<double, 3> der_omega{};
    // --- outputs
    std::array<double, 3> sun_body{};
    std::array<double, 3> sun_eci{};
    double irradiance = 0.0;
    std::array<double, 6> albedo_face{};
    std::array<double, 6> sun_face{};
    std::array<double, 3> mag_body{};
    std::array<double, 3> mag_eci{};
    std::array<double, 4> q_true = {0.0, 0.0, 0.0, 1.0};
    std::array<double, 3> omega_body{};
    std::array<double, 3> r_eci{};
    std::array<double, 3> v_eci{};
    std::array<double, 3> nadir_body{};
    double orbit_radius_ratio = 1.0;
    double albedo_source = 0.0;                       // W/m2
    std::array<double, 3> torque_gravity_gradient{};  // N m, body
    std::array<double, 3> torque_magnetic{};
    std::array<double, 3> torque_aerodynamic{};
    std::array<double, 3> torque_solar_pressure{};
    // --- locals
    double sunlight_fraction = 1.0;
    double sun_distance = 0.0;  // m
};

/// The core's parameters as set in the block's data; with orbit_model = tle the element set is parsed by
/// orbit::parse_tle (throws fmu::Error naming the parameter, line, column and reason).
EnvironmentParams environment_params(const EnvironmentData& d);

class EnvironmentBlock : public fmu::Block<EnvironmentBlock, EnvironmentData> {
public:
    static void declare(fmu::Table<EnvironmentData>& t);
    static fmu::ModelInfo describe();

    void initialize(double t) override;
    void evaluate(double t) override;
    // The rigid-body derivatives alone (the torques' orbit, sun, eclipse and field, but no albedo): what a
    // solver's Jacobian needs.
    void evaluate_derivatives(double t) override;
    void validate() const override;

    // The core object for the parameters (built by configure()).
    void configure() override;

private:
    const Environment& core() const;
    // der_q, der_omega from the rigid body's dx plus the norm stabilization (zeros in spin mode).
    void store_derivatives(const RigidBodyState& dx);

    // Derived from the parameters by configure(), outside the FMU state; a plain copyable member, so
    // clone() copies it along.
    std::optional<Environment> core_;
};

}  // namespace environment
