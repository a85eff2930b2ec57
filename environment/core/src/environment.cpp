#include "environment/environment.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "environment/atmosphere.hpp"
#include "environment/attitude.hpp"
#include "environment/constants.hpp"
#include "environment/earth_rotation.hpp"
#include "environment/eclipse.hpp"
#include "environment/geomagnetic_field.hpp"
#include "environment/sun_ephemeris.hpp"

namespace environment {

namespace {
std::array<double, 3> to_array(const Eigen::Vector3d& v) {
    return {v.x(), v.y(), v.z()};
}

void validate(const EnvironmentParams& p) {
    if (!(p.solar_constant >= 0.0) || !std::isfinite(p.solar_constant)) {
        throw std::invalid_argument("Environment: solar_constant must be finite and >= 0");
    }
    if (p.igrf_max_degree < 1 || p.igrf_max_degree > 13)
        throw std::invalid_argument("Environment: igrf_max_degree must be 1..13");
    const auto in_unit = [](double x) { return x >= 0.0 && x <= 1.0; };
    if (!in_unit(p.albedo.reflectivity) || !in_unit(p.albedo.reflectivity_equator) ||
        !in_unit(p.albedo.reflectivity_pole)) {
        throw std::invalid_argument("Environment: albedo reflectivities must be in [0, 1]");
    }
    if (p.albedo.rings < 1 || p.albedo.rings > 1000 || p.albedo.sectors < 3 || p.albedo.sectors > 4000) {
        throw std::invalid_argument("Environment: albedo grid must have 1..1000 rings and 3..4000 sectors");
    }
    if (!(p.albedo.interval >= 0.0) || !(p.albedo.interval <= 86400.0))
        throw std::invalid_argument("Environment: albedo interval must be 0 (every evaluation) to 86400 s");
    if (p.albedo.degree < 2 || p.albedo.degree > AlbedoHarmonics::kMaxDegree)
        throw std::invalid_argument("Environment: albedo degree must be 2 to " +
                                    std::to_string(AlbedoHarmonics::kMaxDegree));
    if (!std::isfinite(p.seed002_elevation_amplitude))
        throw std::invalid_argument("Environment: seed002 amplitude not finite");
    if (p.orbit_model == OrbitModel::tle && !(p.tle.mean_motion_rev_per_day > 0.0)) {
        throw std::invalid_argument("Environment: orbit_model tle needs an element set (orbit::parse_tle)");
    }
    validate(p.body);
}

Eigen::Vector3d vector3(const std::array<double, 3>& a) {
    return {a[0], a[1], a[2]};
}
}  // namespace

Environment::Environment(const EnvironmentParams& params)
    : params_((validate(params), params)),
      jd0_(julian_date(params.epoch)),
      jd_equinox_(julian_date(params.vernal_equinox)),
      orbit_(params.orbit),
      tle_orbit_(params.orbit_model == OrbitModel::tle
                     ? std::optional<TleOrbit>(std::in_place, params.tle, params.epoch)
                     : std::nullopt),
      rigid_body_(params.rigid_body),
      spin_(params.spin, sun_position_eci(jd0_)),
      faces_(box_faces(params.body)) {
    // Fail at construction, not at the first step, when the epoch lies outside IGRF-14's validity.
    if (params.field_model == FieldModel::igrf14 || params.field_model == FieldModel::dipole) {
        (void)igrf_coefficients(decimal_year(jd0_));
    }
    if (params.albedo.enabled && params.albedo.interval > 0.0) {
        albedo_harmonics_.emplace(params.albedo, params.albedo.degree);
        albedo_nodes_.emplace(params.albedo.interval, albedo_harmonics_->size(), NodeInterpolator::Order::cubic);
        albedo_coefficients_.assign(albedo_harmonics_->size(), 0.0);
    }
}

Eigen::Vector3d Environment::sun_position_at(double t) const {
    Eigen::Vector3d r_sun;
    sun_nodes_.evaluate(
        t,
        [this](double t_node, double* out) {
            Eigen::Map<Eigen::Vector3d>{out} = sun_position_eci(jd0_ + t_node / kSecondsPerDay);
        },
        r_sun.data());
    return r_sun;
}

Eigen::Matrix3d Environment::precession_at(double t) const {
    Eigen::Matrix3d p;
    precession_nodes_.evaluate(
        t,
        [this](double t_node, double* out) {
            Eigen::Map<Eigen::Matrix3d>{out} = precession_matrix(jd0_ + t_node / kSecondsPerDay);
        },
        p.data());
    return p;
}

void Environment::orbit_state(double t, Eigen::Vector3d& r, Eigen::Vector3d& v) const {
    if (tle_orbit_) {
        const TleOrbit::State x = tle_orbit_->state_eci(t);
        r = x.position;
        v = x.velocity;
    } else {
        r = orbit_.position_eci(t);
        v = orbit_.velocity_eci(t);
    }
}

Eigen::Vector3d Environment::sun_position_eci(double jd) const {
    const SunPosition s = (params_.sun_model == SunModel::seed002)
                              ? sun_seed002(jd, jd_equinox_, params_.seed002_elevation_amplitude)
                              : sun_almanac_j2000(jd);  // the field's frame too: one ECI, J2000
    return s.direction_eci * s.distance;
}

Eigen::Vector3d Environment::field_eci(double t, const Eigen::Vector3d& r) const {
    // Evaluated Earth-fixed, rotated back to ECI (precession from its nodes + GMST, earth_rotation.hpp).
    const double jd = jd0_ + t / kSecondsPerDay;
    const Eigen::Matrix3d to_ecef = earth_rotation_z(gmst(jd)) * precession_at(t);  // ecef_from_eci
    const GaussCoefficients c = igrf_coefficients(decimal_year(jd));
    const Eigen::Vector3d r_ecef = to_ecef * r;
    const Eigen::Vector3d b_ecef = (params_.field_model == FieldModel::dipole)
                                       ? dipole_field(c, r_ecef)
                                       : spherical_harmonic_field(c, params_.igrf_max_degree, r_ecef);
    return to_ecef.transpose() * b_ecef;
}

DisturbanceTorques Environment::torques(const Eigen::Matrix3d& A, const Eigen::Vector3d& r, const Eigen::Vector3d& v,
                                        const Eigen::Vector3d& b_eci, const Eigen::Vector3d& sun_eci,
                                        double irradiance) const {
    DisturbanceTorques tau;
    if (!params_.disturbance_torques) return tau;
    const SpacecraftBody& body = params_.body;
    tau.gravity_gradient = gravity_gradient_torque(rigid_body_.inertia(), A * r);
    tau.magnetic = magnetic_torque(vector3(body.dipole_moment), A * b_eci);
    // The air turns with the Earth (about the J2000 z axis: the precession's 0.3 deg is negligible here).
    const Eigen::Vector3d v_air = kEarthRotationRate * Eigen::Vector3d::UnitZ().cross(r);
    tau.aerodynamic =
        aerodynamic_torque(faces_, body.drag_coefficient, atmosphere_density(ellipsoid_altitude(r)), A * (v - v_air));
    tau.solar_pressure =
        solar_pressure_torque(faces_, body.specular_reflectivity, body.diffuse_reflectivity, irradiance, A * sun_eci);
    return tau;
}

void Environment::derivative(double t, const double* x, double* dx) const {
    if (!params_.disturbance_torques || params_.attitude_mode != AttitudeMode::rigid_body) {
        rigid_body_.derivative(x, dx);
        return;
    }
    if (!std::isfinite(t)) throw std::invalid_argument("Environment::derivative: time is not finite");
    RigidBodyState unit{};
    std::copy(x, x + unit.size(), unit.begin());
    RigidBody::renormalize(unit.data());
    const Eigen::Matrix3d A = attitude_matrix({unit[0], unit[1], unit[2], unit[3]});
    Eigen::Vector3d r;
    Eigen::Vector3d v;
    orbit_state(t, r, v);
    const Eigen::Vector3d r_sun = sun_position_at(t);
    const Eigen::Vector3d to_sun = r_sun - r;
    const double d_sun = to_sun.norm();
    const double fraction = params_.eclipse_enabled ? sunlight_fraction(r, r_sun) : 1.0;
    const double au_ratio = kAstronomicalUnit / d_sun;
    const double irradiance = params_.solar_constant * au_ratio * au_ratio * fraction;
    const DisturbanceTorques tau = torques(A, r, v, field_eci(t, r), to_sun / d_sun, irradiance);
    rigid_body_.derivative(x, tau.total(), dx);
}

EnvironmentOutputs Environment::evaluate(double t, const RigidBodyState* state) const {
    if (!std::isfinite(t)) throw std::invalid_argument("Environment::evaluate: time is not finite");
    EnvironmentOutputs out;
    out.time = t;
    out.julian_date = jd0_ + t / kSecondsPerDay;
    out.gmst = gmst(out.julian_date);

    // Orbit and sun.
    Eigen::Vector3d r;
    Eigen::Vector3d v;
    orbit_state(t, r, v);
    const Eigen::Vector3d r_sun = sun_position_at(t);
    const Eigen::Vector3d to_sun = r_sun - r;
    const double d_sun = to_sun.norm();
    const Eigen::Vector3d s = to_sun / d_sun;
    out.r_eci = to_array(r);
    out.v_eci = to_array(v);
    out.sun_eci = to_array(s);
    out.sun_distance = d_sun;
    out.sunlight_fraction = params_.eclipse_enabled ? sunlight_fraction(r, r_sun) : 1.0;
    const double au_ratio = kAstronomicalUnit / d_sun;
    out.irradiance = params_.solar_constant * au_ratio * au_ratio * out.sunlight_fraction;

    // Attitude.
    Eigen::Matrix3d A;
    if (params_.attitude_mode == AttitudeMode::spin) {
        A = spin_.attitude_matrix(t);
        out.q_true = quaternion_from_attitude_matrix(A);
        out.omega_body = to_array(spin_.angular_velocity_body(t));
    } else {
        if (state == nullptr) throw std::invalid_argument("Environment::evaluate: rigid_body mode needs the state");
        RigidBodyState x = *state;
        for (double v : x) {
            if (!std::isfinite(v)) throw std::invalid_argument("Environment::evaluate: state is not finite");
        }
        RigidBody::renormalize(x.data());
        out.q_true = {x[0], x[1], x[2], x[3]};
        out.omega_body = {x[4], x[5], x[6]};
        A = attitude_matrix(out.q_true);
    }
    out.sun_body = to_array(A * s);
    for (std::size_t k = 0; k < 6; ++k) {
        const double cos_beta = (k % 2 == 0 ? 1.0 : -1.0) * out.sun_body[k / 2];
        out.sun_face[k] = out.irradiance * std::max(0.0, cos_beta);
    }

    // Geomagnetic field.
    const Eigen::Vector3d b_eci = field_eci(t, r);
    out.mag_eci = to_array(b_eci);
    out.mag_body = to_array(A * b_eci);

    // Albedo: irradiance at the Earth (not reduced by the satellite's own eclipse).
    const double d_earth_sun = r_sun.norm();
    const double e_earth =
        params_.solar_constant * (kAstronomicalUnit / d_earth_sun) * (kAstronomicalUnit / d_earth_sun);
    if (albedo_harmonics_) {
        // The cap at the nodes (its own position, sun and irradiance there), the faces' response here.
        albedo_nodes_->evaluate(
            t,
            [this](double t_node, double* c) {
                Eigen::Vector3d r_node, v_node;
                orbit_state(t_node, r_node, v_node);
                const Eigen::Vector3d sun_node = sun_position_at(t_node);
                const double d = sun_node.norm();
                const double e = params_.solar_constant * (kAstronomicalUnit / d) * (kAstronomicalUnit / d);
                albedo_harmonics_->project(r_node, sun_node / d, e, c);
            },
            albedo_coefficients_.data());
        out.albedo_face = albedo_harmonics_->faces(albedo_coefficients_.data(), A);
    } else {
        out.albedo_face = earth_albedo(params_.albedo, r, r_sun / d_earth_sun, e_earth, A);
    }
    const double rn = r.norm();
    out.nadir_body = to_array(A * (-r / rn));
    out.orbit_radius_ratio = rn / kEarthRadius;
    const double cos_zss = r.dot(r_sun) / (rn * d_earth_sun);
    out.albedo_source =
        params_.albedo.enabled ? reflectivity_at(params_.albedo, r.z() / rn) * e_earth * std::max(0.0, cos_zss) : 0.0;

    const DisturbanceTorques tau = torques(A, r, v, b_eci, s, out.irradiance);
    out.torque_gravity_gradient = to_array(tau.gravity_gradient);
    out.torque_magnetic = to_array(tau.magnetic);
    out.torque_aerodynamic = to_array(tau.aerodynamic);
    out.torque_solar_pressure = to_array(tau.solar_pressure);
    return out;
}

}  // namespace environment
