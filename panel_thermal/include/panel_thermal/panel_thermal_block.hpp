// The temperature of the six body-mounted panels as an FMU block (panel_thermal.fmu): six continuous
// states, one per face, from the heat balance of face_thermal.hpp, with the geometry and the light the
// environment block gives. Its output feeds ssr_plant's panel_temperature. A block of its own, so that a
// system without it (the seed scenario) integrates exactly what it did before.
#pragma once

#include <array>

#include "fmu/block.hpp"
#include "panel_thermal/face_thermal.hpp"

namespace panel_thermal {

struct PanelThermalData {
    // inputs (start values: a lit +x face at 570 km, Earth below −z)
    double irradiance = 1367.0;
    std::array<double, 3> sun_body{1.0, 0.0, 0.0};
    std::array<double, 3> nadir_body{0.0, 0.0, -1.0};
    double orbit_radius_ratio = (6378137.0 + 570e3) / 6378137.0;
    double albedo_source = 0.0;
    // parameters
    double absorptance = ThermalParams{}.absorptance;
    double emissivity = ThermalParams{}.emissivity;
    double heat_capacity = ThermalParams{}.areal_heat_capacity;
    double earth_infrared = ThermalParams{}.earth_infrared;
    double inner_conductance = ThermalParams{}.inner_conductance;
    double body_temperature = ThermalParams{}.body_temperature;
    // states: start at ssr_plant's datasheet temperature, where the panels are their fit
    std::array<double, 6> t_face{298.15, 298.15, 298.15, 298.15, 298.15, 298.15};
    std::array<double, 6> der_t_face{};
    // outputs
    std::array<double, 6> face_temperature{};
    std::array<double, 6> heat_input{};  // W/m2, absorbed on each face's outer side
};

class PanelThermalBlock : public fmu::Block<PanelThermalBlock, PanelThermalData> {
public:
    static void declare(fmu::Table<PanelThermalData>& t);
    static fmu::ModelInfo describe();

    void evaluate(double t) override;
    void validate() const override;
};

}  // namespace panel_thermal
