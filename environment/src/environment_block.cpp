#include "environment/environment_block.hpp"

#include <array>
#include <cmath>
#include <cstring>
#include <exception>
#include <string>
#include <utility>

#include "environment/circular_orbit.hpp"
#include "environment/constants.hpp"
#include "fmu/errors.hpp"
#include "orbit/tle.hpp"

namespace environment {

namespace {

constexpr double kTwoPi = 2.0 * kPi;

UtcDate utc_date(std::int32_t year, std::int32_t month, std::int32_t day, std::int32_t hour, std::int32_t minute,
                 double second) {
    return UtcDate{.year = year, .month = month, .day = day, .hour = hour, .minute = minute, .second = second};
}

// The core's julian_date() accepts day 1..31 in any month (30 February would silently be 2 March).
void check_calendar_day(const char* what, std::int32_t year, std::int32_t month, std::int32_t day) {
    static constexpr std::array<int, 12> days = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    if (month < 1 || month > 12) throw fmu::Error(std::string(what) + ": month must be 1..12");
    const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
    const int last = days[month - 1] + (month == 2 && leap ? 1 : 0);
    if (day < 1 || day > last) {
        throw fmu::Error(std::string(what) + ": day " + std::to_string(day) + " does not exist in month " +
                         std::to_string(month) + " of " + std::to_string(year));
    }
}

}  // namespace

EnvironmentParams environment_params(const EnvironmentData& d) {
    EnvironmentParams p;
    p.attitude_mode = d.attitude_mode;
    p.spin = SpinParams{
        .phi0 = d.spin_phi0, .theta0 = d.spin_theta0, .phi_dot = d.spin_phi_dot, .theta_dot = d.spin_theta_dot};
    p.rigid_body = RigidBodyParams{.inertia = d.inertia, .q0 = d.q0, .omega0 = d.omega0};
    p.orbit_model = d.orbit_model;
    if (d.orbit_model == OrbitModel::tle) {
        if (d.tle_line1.view().empty() && d.tle_line2.view().empty()) {
            // The set as numbers, with the checks the parser makes on the text.
            try {
                p.tle = orbit::checked_tle_from_elements(d.tle_elements);
            } catch (const orbit::TleElementsError& e) {
                throw fmu::Error(std::string("environment: the element set in tle_elements is refused (tle_line1 and "
                                             "tle_line2 are empty): tle_elements") +
                                 e.what());
            }
        } else {
            try {
                p.tle = orbit::parse_tle(d.tle_line1.view(), d.tle_line2.view());
            } catch (const orbit::TleError& e) {
                throw fmu::Error(std::string("environment: the element set in tle_line1, tle_line2 is refused: ") +
                                 e.what());
            }
        }
    }
    p.orbit = OrbitParams{.altitude = d.orbit_altitude,
                          .inclination = d.orbit_inclination,
                          .raan = d.orbit_raan,
                          .argument_of_latitude0 = d.orbit_argument_of_latitude0};
    p.epoch = utc_date(d.epoch_year, d.epoch_month, d.epoch_day, d.epoch_hour, d.epoch_minute, d.epoch_second);
    p.sun_model = d.sun_model;
    p.vernal_equinox =
        utc_date(d.equinox_year, d.equinox_month, d.equinox_day, d.equinox_hour, d.equinox_minute, d.equinox_second);
    p.seed002_elevation_amplitude = d.seed002_elevation_amplitude;
    p.solar_constant = d.solar_constant;
    p.eclipse_enabled = d.eclipse_enabled;
    p.field_model = d.field_model;
    p.igrf_max_degree = d.igrf_max_degree;
    p.albedo = AlbedoParams{.enabled = d.albedo_enabled,
                            .reflectivity = d.albedo_reflectivity,
                            .rings = d.albedo_rings,
                            .sectors = d.albedo_sectors,
                            .model = d.albedo_reflectivity_model,
                            .reflectivity_equator = d.albedo_reflectivity_equator,
                            .reflectivity_pole = d.albedo_reflectivity_pole,
                            .interval = d.albedo_interval,
                            .degree = d.albedo_degree};
    p.albedo.response = d.albedo_response;
    p.disturbance_torques = d.disturbance_torques;
    p.body = SpacecraftBody{.size = d.body_size,
                            .centre_of_mass = d.centre_of_mass,
                            .drag_coefficient = d.drag_coefficient,
                            .specular_reflectivity = d.specular_reflectivity,
                            .diffuse_reflectivity = d.diffuse_reflectivity,
                            .dipole_moment = d.dipole_moment};
    return p;
}

void EnvironmentBlock::declare(fmu::Table<EnvironmentData>& t) {
    using D = EnvironmentData;
    // Attitude motion.
    t.choice("attitude_mode", &D::attitude_mode,
             {{"spin", AttitudeMode::spin}, {"rigid_body", AttitudeMode::rigid_body}},
             "Attitude motion: spin (seed 000 section 4, a pure function of time) or rigid_body (Euler equations "
             "under the disturbance torques, states q and omega)");
    t.parameter("spin_phi0", &D::spin_phi0, "rad",
                "Spin mode: phi at t = 0 in s_body = (sin phi sin theta, cos phi "
                "sin theta, cos theta)")
        .applies_when("attitude_mode", {"spin"});
    t.parameter("spin_theta0", &D::spin_theta0, "rad", "Spin mode: theta at t = 0")
        .applies_when("attitude_mode", {"spin"});
    t.parameter("spin_phi_dot", &D::spin_phi_dot, "rad/s", "Spin mode: rate of phi (seed 000: 1.26 rad/s)")
        .applies_when("attitude_mode", {"spin"});
    t.parameter("spin_theta_dot", &D::spin_theta_dot, "rad/s", "Spin mode: rate of theta (seed 000: 6.28 rad/s)")
        .applies_when("attitude_mode", {"spin"});
    t.parameter("inertia", &D::inertia, "kg.m2",
                "Rigid-body mode: inertia matrix about the centre of mass in body axes, row-major (symmetric, positive "
                "definite, principal moments obeying the triangle inequality)")
        .applies_when("attitude_mode", {"rigid_body"});
    t.parameter("q0", &D::q0, "1",
                "Rigid-body mode: initial attitude quaternion [x, y, z, w], ECI to body (normalised on use)")
        .range(-1.0, 1.0)
        .applies_when("attitude_mode", {"rigid_body"});
    t.parameter("omega0", &D::omega0, "rad/s", "Rigid-body mode: initial angular velocity, body axes")
        .range(-100.0, 100.0)
        .applies_when("attitude_mode", {"rigid_body"})
        // Small satellites leave their deployer at a few deg/s; 1 rad/s (57 deg/s) is already a violent tumble.
        .plausible(-1.0, 1.0,
                   "a small satellite tumbles at a few deg/s after deployment; more than 1 rad/s (57 deg/s) per axis "
                   "is a violent tumble (deg/s given as rad/s?)");
    t.parameter("quaternion_norm_gain", &D::quaternion_norm_gain, "1/s",
                "Rigid-body mode: gain k of the term k(1 - |q|^2) q added to dq/dt that pulls |q| back to 1 at the "
                "rate 2k under any integrator (zero on |q| = 1; 0 disables it). An explicit fixed-step host needs "
                "steps below 1/k")
        .range(0.0, 1e3);
    // The spacecraft the torques act on.
    t.parameter("disturbance_torques", &D::disturbance_torques, "",
                "Rigid-body mode: gravity gradient, residual dipole, aerodynamic and solar pressure torques in "
                "Euler's equations (false: torque-free, and the torque outputs are zero)");
    t.parameter("body_size", &D::body_size, "m",
                "The spacecraft's box: edges along body x, y, z (faces +x, -x, +y, -y, +z, -z; default a 3U, "
                "100 x 100 x 340 mm)")
        .range(1e-3, 100.0);
    t.parameter("centre_of_mass", &D::centre_of_mass, "m",
                "Centre of mass from the box's geometric centre, body axes (inside the box)")
        .range(-50.0, 50.0);
    t.parameter("drag_coefficient", &D::drag_coefficient, "1",
                "Drag coefficient of each face in free-molecular flow (flat plate: about 2.2)")
        .range(0.0, 10.0);
    t.parameter("specular_reflectivity", &D::specular_reflectivity, "1",
                "Faces' specular reflectivity to sunlight (specular + diffuse <= 1, the rest absorbed)")
        .range(0.0, 1.0);
    t.parameter("diffuse_reflectivity", &D::diffuse_reflectivity, "1", "Faces' diffuse (Lambertian) reflectivity")
        .range(0.0, 1.0);
    t.parameter("dipole_moment", &D::dipole_moment, "A.m2",
                "Residual magnetic dipole, body axes: the torque m x B (set it to the magnetometer's dipole_moment, "
                "the same spacecraft)")
        .range(-100.0, 100.0);
    // Orbit.
    t.choice("orbit_model", &D::orbit_model, {{"circular", OrbitModel::circular}, {"tle", OrbitModel::tle}},
             "Truth orbit: circular (Kepler, from orbit_altitude, orbit_inclination, orbit_raan, "
             "orbit_argument_of_latitude0) or tle (SGP4 from the element set tle_line1, tle_line2 or tle_elements, "
             "TEME rotated to J2000; its epoch may differ from the epoch_* parameters by up to "
             "orbit::kMaxElementSetAgeDays, 366 days)");
    t.parameter("tle_line1", &D::tle_line1, "",
                "orbit_model tle: line 1 of the two-line element set (69 columns, checksum in column 69)")
        .applies_when("orbit_model", {"tle"});
    t.parameter("tle_line2", &D::tle_line2, "",
                "orbit_model tle: line 2 of the two-line element set (near-Earth: period below 225 min)")
        .applies_when("orbit_model", {"tle"});
    t.parameter("tle_elements", &D::tle_elements, "1",
                "orbit_model tle, when tle_line1 and tle_line2 are empty: the element set as numbers in its own "
                "units: epoch (Julian date, UTC), mean motion (rev/day), eccentricity, inclination, right ascension "
                "of the node, argument of perigee, mean anomaly (deg), B* (1/Earth radii); default the bundled set")
        .applies_when("orbit_model", {"tle"});
    t.parameter("orbit_altitude", &D::orbit_altitude, "m",
                "Circular orbit: altitude above the equatorial radius 6378.137 km (seed 004: about 570 km)")
        .range(1.0, 1e9)
        .applies_when("orbit_model", {"circular"});
    t.parameter("orbit_inclination", &D::orbit_inclination, "rad", "Circular orbit: inclination (seed 004: 64.9 deg)")
        .range(0.0, kPi)
        .applies_when("orbit_model", {"circular"});
    t.parameter("orbit_raan", &D::orbit_raan, "rad", "Circular orbit: right ascension of the ascending node (J2000)")
        .range(-kTwoPi, kTwoPi)
        .applies_when("orbit_model", {"circular"});
    t.parameter("orbit_argument_of_latitude0", &D::orbit_argument_of_latitude0, "rad",
                "Circular orbit: argument of latitude at t = 0 (angle from the ascending node)")
        .range(-kTwoPi, kTwoPi)
        .applies_when("orbit_model", {"circular"});
    // Epoch.
    t.parameter("epoch_year", &D::epoch_year, "", "Epoch (UTC at t = 0): year; IGRF-14 covers 2025.0 to 2030.0")
        .range(2025, 2029);
    t.parameter("epoch_month", &D::epoch_month, "", "Epoch (UTC at t = 0): month 1..12").range(1, 12);
    t.parameter("epoch_day", &D::epoch_day, "", "Epoch (UTC at t = 0): day of the month").range(1, 31);
    t.parameter("epoch_hour", &D::epoch_hour, "", "Epoch (UTC at t = 0): hour 0..23").range(0, 23);
    t.parameter("epoch_minute", &D::epoch_minute, "", "Epoch (UTC at t = 0): minute 0..59").range(0, 59);
    t.parameter("epoch_second", &D::epoch_second, "s", "Epoch (UTC at t = 0): second of the minute").range(0.0, 61.0);
    // Sun.
    t.choice("sun_model", &D::sun_model, {{"almanac", SunModel::almanac}, {"seed002", SunModel::seed002}},
             "Sun position: almanac (Astronomical Almanac low-precision formula, about 0.01 deg) or seed002 "
             "(seed 002 eq. 21-23, 1 AU)");
    t.parameter("equinox_year", &D::equinox_year, "",
                "seed002 sun: vernal equinox the days are counted from (UTC), year")
        .range(1900, 2100);
    t.parameter("equinox_month", &D::equinox_month, "", "seed002 sun: vernal equinox, month").range(1, 12);
    t.parameter("equinox_day", &D::equinox_day, "", "seed002 sun: vernal equinox, day").range(1, 31);
    t.parameter("equinox_hour", &D::equinox_hour, "", "seed002 sun: vernal equinox, hour").range(0, 23);
    t.parameter("equinox_minute", &D::equinox_minute, "", "seed002 sun: vernal equinox, minute").range(0, 59);
    t.parameter("equinox_second", &D::equinox_second, "s", "seed002 sun: vernal equinox, second").range(0.0, 61.0);
    t.parameter("seed002_elevation_amplitude", &D::seed002_elevation_amplitude, "rad",
                "seed002 sun: amplitude of the sun's elevation (default the obliquity 23.439 deg; the paper prints "
                "2 pi/180)")
        .range(-kPi / 2.0, kPi / 2.0);
    t.parameter("solar_constant", &D::solar_constant, "W/m2",
                "Solar irradiance at 1 AU (seed 000: 1367 W/m2), scaled by the actual distance")
        .range(0.0, 1e5)
        .tunable();
    t.parameter("eclipse_enabled", &D::eclipse_enabled, "",
                "Earth shadow: conical umbra and smooth penumbra (false: always lit)")
        .tunable();
    // Field.
    t.choice("field_model", &D::field_model, {{"igrf14", FieldModel::igrf14}, {"dipole", FieldModel::dipole}},
             "Geomagnetic field: igrf14 (IGRF-14 spherical harmonics) or dipole (tilted centred dipole from "
             "IGRF-14's degree-1 terms)");
    t.parameter("igrf_max_degree", &D::igrf_max_degree, "", "igrf14 field: highest degree of the synthesis (1..13)")
        .range(1, 13)
        .applies_when("field_model", {"igrf14"});
    // Albedo.
    t.parameter("albedo_enabled", &D::albedo_enabled, "", "Earth albedo on the six faces (false: albedo_face = 0)")
        .tunable();
    t.parameter("albedo_reflectivity", &D::albedo_reflectivity, "1",
                "Earth's reflectivity (Lambertian; mean Bond albedo about 0.3)")
        .range(0.0, 1.0)
        .tunable();
    t.parameter("albedo_rings", &D::albedo_rings, "",
                "Albedo quadrature: Gauss-Legendre points in the central angle over the visible cap")
        .range(1, 1000);
    t.parameter("albedo_sectors", &D::albedo_sectors, "", "Albedo quadrature: midpoint points in azimuth")
        .range(3, 4000);
    t.choice("albedo_response", &D::albedo_response,
             {{"cosine", AlbedoResponse::cosine}, {"kelly", AlbedoResponse::kelly}},
             "Angular response the faces weigh albedo with: cosine (ideal) or kelly (seed 000 fig. 4, set it as the "
             "plant's angular_response: albedo_face is then the equivalent normal-incidence irradiance)");
    t.choice("albedo_reflectivity_model", &D::albedo_reflectivity_model,
             {{"uniform", ReflectivityModel::uniform}, {"zonal", ReflectivityModel::zonal}},
             "Earth's reflectivity: uniform (albedo_reflectivity everywhere) or zonal (rising from "
             "albedo_reflectivity_equator to albedo_reflectivity_pole as the square of the sine of latitude)");
    t.parameter("albedo_reflectivity_equator", &D::albedo_reflectivity_equator, "1",
                "Zonal model: reflectivity at the equator (assumed 0.2)")
        .range(0.0, 1.0)
        .tunable()
        .applies_when("albedo_reflectivity_model", {"zonal"});
    t.parameter("albedo_reflectivity_pole", &D::albedo_reflectivity_pole, "1",
                "Zonal model: reflectivity at the poles (assumed 0.6)")
        .range(0.0, 1.0)
        .tunable()
        .applies_when("albedo_reflectivity_model", {"zonal"});
    t.parameter("albedo_interval", &D::albedo_interval, "s",
                "Albedo: seconds between the integrations over the cap, each expanded in spherical harmonics to "
                "albedo_degree; between them the expansion is interpolated (cubic spline) and only the faces' "
                "response is evaluated (0: the full integration at every evaluation). The default (10 s, degree 12) "
                "is within 0.35 W/m2 of it on every face along an orbit (docs/speed.md)")
        .range(0.0, 86400.0);
    t.parameter("albedo_degree", &D::albedo_degree, "",
                "Albedo: degree of the spherical-harmonic expansion used when albedo_interval > 0")
        .range(2, 40);
    t.calculated_parameter("orbit_period", &D::orbit_period, "s",
                           "Orbital period: the circular orbit's 2 pi sqrt(a^3/mu), or the element set's mean period "
                           "at its epoch");

    // States: used in rigid_body mode only (derivatives 0 in spin mode).
    auto q = t.state("q", &D::q, &D::der_q, "1",
                     "Rigid-body mode: attitude quaternion [x, y, z, w], ECI to body (its norm is held at 1 by "
                     "quaternion_norm_gain)");
    q.calculated_start();
    t.state("omega", &D::omega, &D::der_omega, "rad/s", "Rigid-body mode: angular velocity, body axes")
        .nominal(0.01)  // body rates of a tumbling satellite: about 1 deg/s
        .calculated_start()
        .derivative_depends_on({"q", "omega"});  // the torques depend on the attitude
    q.derivative_depends_on({"q", "omega"});     // after omega is declared

    t.output("sun_body", &D::sun_body, "1", "Unit vector satellite to sun, body axes").depends_on({"q"});
    t.output("sun_eci", &D::sun_eci, "1", "Unit vector satellite to sun, ECI (J2000)").depends_on({});
    t.output("irradiance", &D::irradiance, "W/m2",
             "Solar irradiance at the satellite: solar_constant (1 AU / distance)^2, times the visible fraction of "
             "the solar disc (0 in umbra)")
        .depends_on({});
    t.output("albedo_face", &D::albedo_face, "W/m2", "Earth-albedo irradiance on the faces +x, -x, +y, -y, +z, -z")
        .depends_on({"q"});
    t.output("sun_face", &D::sun_face, "W/m2",
             "Direct solar irradiance on the faces +x, -x, +y, -y, +z, -z: irradiance times max(0, cos) of the sun's "
             "angle to the face normal (no angular law, no albedo)")
        .depends_on({"q"});
    t.output("mag_body", &D::mag_body, "T", "Geomagnetic flux density at the satellite, body axes").depends_on({"q"});
    t.output("mag_eci", &D::mag_eci, "T", "Geomagnetic flux density at the satellite, ECI (J2000)").depends_on({});
    t.output("q_true", &D::q_true, "1", "True attitude quaternion [x, y, z, w] (scalar last), ECI to body, unit")
        .depends_on({"q"});
    t.output("omega_body", &D::omega_body, "rad/s", "True angular velocity, body axes").depends_elementwise({"omega"});
    t.output("r_eci", &D::r_eci, "m", "Satellite position, ECI (J2000)").depends_on({});
    t.output("v_eci", &D::v_eci, "m/s", "Satellite velocity, ECI (J2000)").depends_on({});
    t.output("nadir_body", &D::nadir_body, "1", "Unit vector satellite to the Earth's centre, body axes")
        .depends_on({"q"});
    t.output("orbit_radius_ratio", &D::orbit_radius_ratio, "1", "Orbit radius over the Earth's radius, r / R_E")
        .depends_on({});
    t.output("albedo_source", &D::albedo_source, "W/m2",
             "Albedo flux scale for a panel heat balance: reflectivity times the sun's irradiance at the Earth times "
             "the cosine of its zenith angle at the sub-satellite point (0 over the night side)")
        .depends_on({});

    t.output("torque_gravity_gradient", &D::torque_gravity_gradient, "N.m",
             "Gravity-gradient torque 3 mu/r^5 r_b x (J r_b), body axes (0 with disturbance_torques off)")
        .depends_on({"q"});
    t.output("torque_magnetic", &D::torque_magnetic, "N.m",
             "Torque of the residual dipole in the field, m x B, body axes")
        .depends_on({"q"});
    t.output("torque_aerodynamic", &D::torque_aerodynamic, "N.m",
             "Aerodynamic torque of the faces in the relative wind (exponential atmosphere), body axes")
        .depends_on({"q"});
    t.output("torque_solar_pressure", &D::torque_solar_pressure, "N.m",
             "Solar radiation pressure torque of the lit faces (0 in the umbra), body axes")
        .depends_on({"q"});

    t.local("sunlight_fraction", &D::sunlight_fraction, "1", "Visible fraction of the solar disc (1 lit, 0 umbra)");
    t.output("sun_distance", &D::sun_distance, "m",
             "Distance satellite to sun (what an on-board ephemeris knows: scales the expected panel currents)")
        .depends_on({});
}

fmu::ModelInfo EnvironmentBlock::describe() {
    fmu::ModelInfo info;
    info.model_identifier = "environment";
    info.model_name = "environment";
    info.description =
        "Truth for the sensors: attitude motion, orbit (circular or SGP4 from a TLE), sun and eclipse, geomagnetic "
        "field, Earth albedo";
    info.documentation_html =
        "<p>Everything the sensors see and the truth the estimate is scored against. Inertial frame ECI (J2000); "
        "time t is seconds since the epoch parameters (UTC). Quaternions scalar-last [x, y, z, w], "
        "A(q) = (w&sup2; &minus; |Q|&sup2;) I + 2QQ<sup>T</sup> &minus; 2w[Q&times;] maps ECI to body; faces in the "
        "order +x, &minus;x, +y, &minus;y, +z, &minus;z.</p>"
        "<ul>"
        "<li><b>Attitude</b> (<code>attitude_mode</code>): <code>spin</code> (default) is seed 000 section 4: the "
        "sun in body axes is s = (sin &phi; sin &theta;, cos &phi; sin &theta;, cos &theta;), &phi; = "
        "&phi;<sub>0</sub> "
        "+ &phi;&#775; t, &theta; = &theta;<sub>0</sub> + &theta;&#775; t, exactly for the sun direction at the "
        "epoch; the attitude is a pure function of time and the states q, omega are idle (derivatives 0). "
        "<code>rigid_body</code> integrates Euler's equations J&omega;&#775; = &minus;&omega; &times; "
        "J&omega; + &tau; under the disturbance torques &tau; (gravity gradient, the residual dipole in the field, "
        "the faces' drag and solar pressure; outputs torque_*, <code>disturbance_torques = false</code> for the "
        "torque-free body) and q&#775; = &frac12;&Omega;(&omega;)q + k(1 &minus; |q|&sup2;)q as the continuous states "
        "q[1..4], "
        "omega[1..3] (initial values q0, omega0). The second term (k = <code>quaternion_norm_gain</code>, default "
        "0.01/s) is zero on |q| = 1 and pulls the norm back at the rate 2k under any integrator, so |q| does not "
        "drift (an explicit fixed-step host needs steps below 1/k = 100 s); outputs use q/|q|.</li>"
        "<li><b>Orbit</b> (<code>orbit_model</code>): <code>circular</code> (default), a Kepler orbit from altitude, "
        "inclination, RAAN and argument of latitude at t = 0 (defaults 570 km, 64.9&deg;, seed 004); or "
        "<code>tle</code>, SGP4 (Vallado et al. 2006, WGS-72) from the two-line element set "
        "<code>tle_line1</code>, <code>tle_line2</code> (checksums verified; near-Earth sets only), its TEME "
        "state rotated to J2000 through the IAU 1980 nutation and IAU 1976 precession. The set's epoch may lie "
        "before or after the <code>epoch_*</code> instant.</li>"
        "<li><b>Sun</b> (<code>sun_model</code>): the Astronomical Almanac's low-precision formula "
        "(<code>almanac</code>) or seed 002 eq. 21&ndash;23 (<code>seed002</code>, counted from the "
        "<code>equinox_*</code> date). Irradiance = solar_constant &middot; (1 AU/d)&sup2; &middot; &nu;, &nu; the "
        "visible fraction of the solar disc from a conical umbra/penumbra model (0 in umbra). &nu; is continuous "
        "through the penumbra, so eclipse entry and exit need no events and the FMU declares none.</li>"
        "<li><b>Field</b> (<code>field_model</code>): IGRF-14 to degree <code>igrf_max_degree</code> (default 13) "
        "with its secular variation, or the tilted dipole of its degree-1 terms; valid 2025.0&ndash;2030.0 (a "
        "time outside is an error).</li>"
        "<li><b>Albedo</b>: Lambertian Earth of reflectivity <code>albedo_reflectivity</code> (0.3), the exact "
        "view factor integrated over the sunlit visible cap, per face; <code>albedo_enabled = false</code> gives "
        "zeros.</li>"
        "</ul>"
        "<p>Outputs: sun_body, sun_eci (unit), sun_distance (m), irradiance, albedo_face, sun_face, mag_body, mag_eci "
        "(T), "
        "q_true, omega_body, "
        "r_eci (m), v_eci (m/s). In spin mode sun_body = A(q_true) sun_eci is the seed formula up to the sun's orbital "
        "parallax "
        "(&lt; 5e-5 rad) and its motion of 2e-7 rad/s. Default experiment: the seed scenario, 10 s in 0.01 s "
        "steps.</p>";
    info.default_experiment = {.start_time = 0.0, .stop_time = 10.0, .tolerance = 1e-6, .step_size = 0.01};
    return info;
}

void EnvironmentBlock::configure() {
    core_.reset();
    try {
        core_.emplace(environment_params(data()));
    } catch (const fmu::Error&) {
        throw;
    } catch (const std::exception& e) {
        throw fmu::Error(std::string("environment: ") + e.what());
    }
}

const Environment& EnvironmentBlock::core() const {
    if (!core_) throw fmu::Error("environment: used before configure()");  // the runtime configures first
    return *core_;
}

void EnvironmentBlock::validate() const {
    // The calendar; everything else the core checks (inertia, q0, IGRF validity at the epoch, albedo
    // grid) is refused by configure(), which the runtime calls right after, at exit of initialization.
    const auto& d = data();
    check_calendar_day("epoch", d.epoch_year, d.epoch_month, d.epoch_day);
    check_calendar_day("equinox", d.equinox_year, d.equinox_month, d.equinox_day);
}

void EnvironmentBlock::initialize(double) {
    auto& d = data();
    // The states start from the parameters, q normalised (a zero q0 is left as is; validate() refuses it).
    double n2 = 0.0;
    for (double c : d.q0) n2 += c * c;
    const double n = std::sqrt(n2);
    for (int i = 0; i < 4; ++i) d.q[i] = n > 0.0 ? d.q0[i] / n : d.q0[i];
    d.omega = d.omega0;
    d.orbit_period = core().orbit_period();
}

void EnvironmentBlock::evaluate_derivatives(double t) {
    const Environment& env = core();
    auto& d = data();
    if (env.params().attitude_mode != AttitudeMode::rigid_body) {
        d.der_q = {};
        d.der_omega = {};
        return;
    }
    const RigidBodyState x{d.q[0], d.q[1], d.q[2], d.q[3], d.omega[0], d.omega[1], d.omega[2]};
    RigidBodyState dx{};
    env.derivative(t, x.data(), dx.data());
    store_derivatives(dx);
}

void EnvironmentBlock::store_derivatives(const RigidBodyState& dx) {
    auto& d = data();
    // Norm stabilization (header): k (1 - |q|^2) q, zero on the unit sphere.
    const double n2 = d.q[0] * d.q[0] + d.q[1] * d.q[1] + d.q[2] * d.q[2] + d.q[3] * d.q[3];
    const double pull = d.quaternion_norm_gain * (1.0 - n2);
    for (int i = 0; i < 4; ++i) d.der_q[i] = dx[i] + pull * d.q[i];
    for (int i = 0; i < 3; ++i) d.der_omega[i] = dx[4 + i];
}

void EnvironmentBlock::evaluate(double t) {
    const Environment& env = core();
    auto& d = data();
    EnvironmentOutputs o;
    if (env.params().attitude_mode == AttitudeMode::rigid_body) {
        const RigidBodyState x{d.q[0], d.q[1], d.q[2], d.q[3], d.omega[0], d.omega[1], d.omega[2]};
        o = env.evaluate(t, &x);  // normalises q before use
        // The derivative under the torques just evaluated (the same as env.derivative(t, x), without
        // computing the orbit, sun and field twice).
        const Eigen::Vector3d torque(
            o.torque_gravity_gradient[0] + o.torque_magnetic[0] + o.torque_aerodynamic[0] + o.torque_solar_pressure[0],
            o.torque_gravity_gradient[1] + o.torque_magnetic[1] + o.torque_aerodynamic[1] + o.torque_solar_pressure[1],
            o.torque_gravity_gradient[2] + o.torque_magnetic[2] + o.torque_aerodynamic[2] + o.torque_solar_pressure[2]);
        RigidBodyState dx{};
        env.derivative(x.data(), torque, dx.data());
        store_derivatives(dx);
    } else {
        d.der_q = {};
        d.der_omega = {};
        o = env.evaluate(t);
    }
    d.sun_body = o.sun_body;
    d.sun_eci = o.sun_eci;
    d.irradiance = o.irradiance;
    d.albedo_face = o.albedo_face;
    d.sun_face = o.sun_face;
    d.mag_body = o.mag_body;
    d.mag_eci = o.mag_eci;
    d.q_true = o.q_true;
    d.omega_body = o.omega_body;
    d.r_eci = o.r_eci;
    d.v_eci = o.v_eci;
    d.sunlight_fraction = o.sunlight_fraction;
    d.sun_distance = o.sun_distance;
    d.nadir_body = o.nadir_body;
    d.orbit_radius_ratio = o.orbit_radius_ratio;
    d.albedo_source = o.albedo_source;
    d.torque_gravity_gradient = o.torque_gravity_gradient;
    d.torque_magnetic = o.torque_magnetic;
    d.torque_aerodynamic = o.torque_aerodynamic;
    d.torque_solar_pressure = o.torque_solar_pressure;
}

}  // namespace environment

FMU_BLOCK(environment::EnvironmentBlock)
