#include "panel_thermal/panel_thermal_block.hpp"

#include "fmu/errors.hpp"

namespace panel_thermal {

namespace {

ThermalParams params_of(const PanelThermalData& d) {
    return ThermalParams{.absorptance = d.absorptance,
                         .emissivity = d.emissivity,
                         .areal_heat_capacity = d.heat_capacity,
                         .earth_infrared = d.earth_infrared,
                         .inner_conductance = d.inner_conductance,
                         .body_temperature = d.body_temperature};
}

Eigen::Vector3d vec(const std::array<double, 3>& a) {
    return {a[0], a[1], a[2]};
}

}  // namespace

void PanelThermalBlock::declare(fmu::Table<PanelThermalData>& t) {
    using D = PanelThermalData;
    t.input("irradiance", &D::irradiance, "W/m2", "Direct sunlight at the satellite, 0 in eclipse (environment)")
        .min(0.0);
    t.input("sun_body", &D::sun_body, "1", "Sun direction, body axes, any length (environment sun_body)");
    t.input("nadir_body", &D::nadir_body, "1", "Unit direction to the Earth's centre, body axes (environment)");
    t.input("orbit_radius_ratio", &D::orbit_radius_ratio, "1", "Orbit radius over the Earth's radius (environment)")
        .range(1.0001, 1000.0);
    t.input("albedo_source", &D::albedo_source, "W/m2",
            "Reflectivity x sun irradiance at the Earth x cos of its zenith below the satellite (environment)")
        .min(0.0);
    t.parameter("absorptance", &D::absorptance, "1", "Solar absorptance of a cell-covered face (assumed 0.90)")
        .range(0.0, 1.0);
    t.parameter("emissivity", &D::emissivity, "1", "Infrared emissivity of a face (assumed 0.85)").range(1e-3, 1.0);
    t.parameter("heat_capacity", &D::heat_capacity, "J/(m2.K)",
                "Heat capacity of a face per unit area (assumed 2500: about 1.5 kg/m2 of panel)")
        .min(1.0);
    t.parameter("earth_infrared", &D::earth_infrared, "W/m2", "Earth's emitted infrared flux at its surface (237)")
        .range(0.0, 1000.0);
    t.parameter("inner_conductance", &D::inner_conductance, "W/(m2.K)",
                "Heat exchange of a face with the body through its inner side (assumed 2)")
        .range(0.0, 1e4);
    t.parameter("body_temperature", &D::body_temperature, "K", "Temperature of the body the faces exchange heat with")
        .range(100.0, 500.0);
    t.state("t_face", &D::t_face, &D::der_t_face, "K", "Temperature of each face +x, -x, +y, -y, +z, -z")
        .nominal(300.0)
        .derivative_depends_on(
            {"t_face", "sun_body", "irradiance", "nadir_body", "orbit_radius_ratio", "albedo_source"});
    t.output("face_temperature", &D::face_temperature, "K",
             "Temperature of each face, the states t_face (ssr_plant panel_temperature)")
        .depends_elementwise({"t_face"});
    t.output("heat_input", &D::heat_input, "W/m2", "Heat absorbed on each face's outer side: sun, albedo, infrared")
        .depends_on({"sun_body", "irradiance", "nadir_body", "orbit_radius_ratio", "albedo_source"});
}

fmu::ModelInfo PanelThermalBlock::describe() {
    fmu::ModelInfo info;
    info.model_identifier = "panel_thermal";
    info.model_name = "panel_thermal";
    info.description = "Temperature of the six body-mounted solar panels from their heat balance";
    info.documentation_html =
        "<p>Each face is a thin plate: C dT/dt = &alpha; (E<sub>sun</sub> max(0, n&middot;s) + E<sub>albedo</sub>) + "
        "&epsilon; E<sub>IR</sub> &minus; &epsilon; &sigma; T<sup>4</sup> &minus; h (T &minus; T<sub>body</sub>), "
        "the Earth terms through the exact view factor of a flat plate to a sphere, the albedo by the usual "
        "thermal-design approximation (reflectivity &times; solar irradiance &times; the sun's zenith cosine "
        "below the satellite &times; view factor). Inputs from the environment block, output "
        "<code>face_temperature</code> to ssr_plant's <code>panel_temperature</code>. Faces in the order "
        "+x, &minus;x, +y, &minus;y, +z, &minus;z.</p>";
    info.default_experiment = {.start_time = 0.0, .stop_time = 6000.0, .tolerance = 1e-6, .step_size = 10.0};
    return info;
}

void PanelThermalBlock::validate() const {
    (void)params_of(data());  // the table's ranges cover every parameter
}

void PanelThermalBlock::evaluate(double) {
    auto& d = data();
    const Eigen::Vector3d s = vec(d.sun_body), n = vec(d.nadir_body);
    // Directions of any length (a host's interpolation between unit vectors), normalized; zero: none.
    const Eigen::Vector3d sun = s.norm() > 0.0 ? Eigen::Vector3d(s.normalized()) : Eigen::Vector3d::Zero();
    const Eigen::Vector3d nadir = n.norm() > 0.0 ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d(0, 0, -1);
    const ThermalParams p = params_of(d);
    d.heat_input = face_heat_input(p, sun, d.irradiance, nadir, d.orbit_radius_ratio, d.albedo_source);
    d.der_t_face = face_temperature_derivative(p, d.t_face, d.heat_input);
    d.face_temperature = d.t_face;
}

}  // namespace panel_thermal

FMU_BLOCK(panel_thermal::PanelThermalBlock)
