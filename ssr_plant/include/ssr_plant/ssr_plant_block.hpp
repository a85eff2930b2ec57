// The power system as an FMU block: the variable table over the plant core (core/), and the
// mapping of the core's event-driven protocol onto the runtime's equations.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "fmu/block.hpp"
#include "fmu/fixed_string.hpp"
#include "ssr_plant/plant.hpp"

namespace ssr_plant {

// Every variable of the block. Defaults are the core's (parameters.hpp says which are the seed's and
// which are assumed), taken from its default-constructed structs so that they are written once (a test
// checks that every parameter matches), except angular_response: the FMU defaults to the measured Kelly
// cosine of a real panel (seed 000 fig. 4); the seed-scenario systems select cosine, the law eq. 5 assumes.
inline constexpr Parameters core_defaults{};

struct SsrPlantData {
    // inputs
    std::array<double, 3> sun_body = Inputs{}.sun_body;
    double irradiance = Inputs{}.irradiance;
    std::array<double, 6> albedo_face = Inputs{}.albedo_face;
    std::array<double, 6> panel_temperature = Inputs{}.panel_temperature;
    // parameters: selections
    Fidelity fidelity = core_defaults.fidelity;
    AngularResponse angular_response = AngularResponse::kelly;
    Modulation modulation = core_defaults.modulation;
    // panel datasheet
    double rated_irradiance = core_defaults.panel.rated_irradiance;
    double panel_isc = core_defaults.panel.short_circuit_current;
    double panel_voc = core_defaults.panel.open_circuit_voltage;
    double panel_imp = core_defaults.panel.max_power_current;
    double panel_vmp = core_defaults.panel.max_power_voltage;
    std::int32_t cells_in_series = core_defaults.panel.cells_in_series;
    double panel_shunt_resistance = core_defaults.panel.shunt_resistance;
    double cell_temperature = core_defaults.panel.cell_temperature;
    double isc_temperature_coefficient = core_defaults.panel.isc_temperature_coefficient;
    double voc_temperature_coefficient = core_defaults.panel.voc_temperature_coefficient;
    // regulator and bus
    double or_diode_forward_voltage = core_defaults.or_diode_forward_voltage;
    double or_diode_resistance = core_defaults.or_diode_resistance;
    double shunt_switch_resistance = core_defaults.shunt_switch_resistance;
    double pwm_frequency = core_defaults.pwm_frequency;
    double bus_capacitance = core_defaults.bus_capacitance;
    double load_resistance = core_defaults.load_resistance;
    double bus_voltage_reference = core_defaults.bus_voltage_reference;
    double controller_gain = core_defaults.controller_gain;
    // battery
    // (the chemistry's published characteristic and charger settings: battery_preset(), battery.hpp)
    BatteryChemistry battery_chemistry = core_defaults.battery.chemistry;
    double battery_capacity = core_defaults.battery.capacity;
    double charge_path_resistance = core_defaults.battery.charge_path_resistance;
    double battery_diode_forward_voltage = core_defaults.battery.diode_forward_voltage;
    double battery_diode_resistance = core_defaults.battery.diode_resistance;
    double soc_connect = core_defaults.battery.soc_connect;
    double soc_disconnect = core_defaults.battery.soc_disconnect;
    ChargeControl charge_control = core_defaults.battery.charge_control;
    // injected faults (core/include/ssr_plant/faults.hpp); face 0 = none, 1 … 6 = +x, −x, +y, −y, +z, −z
    std::int32_t fault_string_open_face = core_defaults.faults.string_open.face;
    double fault_string_open_onset = core_defaults.faults.string_open.onset;
    double fault_string_open_end = core_defaults.faults.string_open.end;
    std::int32_t fault_cell_short_face = core_defaults.faults.cell_short.face;
    std::int32_t fault_cell_short_cells = core_defaults.faults.shorted_cells;
    double fault_cell_short_onset = core_defaults.faults.cell_short.onset;
    double fault_cell_short_end = core_defaults.faults.cell_short.end;
    std::int32_t fault_degradation_face = core_defaults.faults.degradation.face;
    double fault_degradation_rate = core_defaults.faults.degradation_rate;
    double fault_degradation_onset = core_defaults.faults.degradation.onset;
    std::int32_t fault_shadow_face = core_defaults.faults.shadow.face;
    double fault_shadow_fraction = core_defaults.faults.shadow_fraction;
    double fault_shadow_onset = core_defaults.faults.shadow.onset;
    double fault_shadow_end = core_defaults.faults.shadow.end;
    std::int32_t fault_switch_face = core_defaults.faults.shunt_switch.face;
    SwitchStuck fault_switch_stuck = core_defaults.faults.switch_stuck;
    double fault_switch_onset = core_defaults.faults.shunt_switch.onset;
    double fault_switch_end = core_defaults.faults.shunt_switch.end;
    std::int32_t fault_hall_face = core_defaults.faults.hall.face;
    HallFault fault_hall_mode = core_defaults.faults.hall_mode;
    double fault_hall_offset = core_defaults.faults.hall_offset;
    double fault_hall_onset = core_defaults.faults.hall.onset;
    double fault_hall_end = core_defaults.faults.hall.end;
    std::int32_t fault_appendage_face = core_defaults.faults.appendage.face;
    std::array<double, 3> fault_appendage_center = core_defaults.faults.appendage_center;
    std::array<double, 3> fault_appendage_side_a = core_defaults.faults.appendage_side_a;
    std::array<double, 3> fault_appendage_side_b = core_defaults.faults.appendage_side_b;
    std::array<double, 3> fault_appendage_box = core_defaults.faults.appendage_box;
    double fault_appendage_onset = core_defaults.faults.appendage.onset;
    double fault_appendage_end = core_defaults.faults.appendage.end;
    // continuous states and derivatives
    double v_cap = 15.0;
    double soc_state = 0.9;
    double der_v_cap = 0.0;
    double der_soc_state = 0.0;
    // outputs
    std::array<double, 3> i_sh{};
    std::array<double, 6> i_face_sh{};
    std::array<double, 6> i_sc{};
    std::array<double, 6> i_panel{};
    std::array<double, 6> i_shunt{};
    std::array<double, 6> i_string{};
    double v_bus = 15.0;
    double v_batt = 0.0;
    double i_batt = 0.0;
    double soc = 0.9;
    double duty = 0.0;
    bool gate = false;
    std::int32_t pwm_period = 0;
    double i_load = 0.0;
    // discrete state of the core (PWM period, S/H, charge switch)
    DiscreteState discrete{};
};

class SsrPlantBlock : public fmu::Block<SsrPlantBlock, SsrPlantData> {
public:
    static void declare(fmu::Table<SsrPlantData>& t);
    static fmu::ModelInfo describe();

    void initialize(double t) override;
    void evaluate(double t) override;
    // The bus balance alone (no Hall or short-circuit solves): what a solver needs between outputs.
    void evaluate_derivatives(double t) override;
    std::size_t event_indicator_count() const override { return indicator_count; }
    void event_indicators(double t, std::span<double> z) override;
    fmu::EventUpdate event_update(double t, bool time_event_due) override;
    double next_time_event() const override;
    void validate() const override;
    void check_state() const override;
    // Co-Simulation between PWM edges: the core's exact step of the bus (advance_between_edges), in place of
    // the solver's CVODE, which would restart at every edge (switching fidelity; averaged: CVODE).
    std::optional<fmu::SpanReached> advance_between_events(double t, double t_stop, double rtol,
                                                           const std::function<void(double)>& move_to) override;

    // Fits the plant (panel fit ~0.2 ms) to the parameters: the runtime calls it after a parameter
    // change, a state restore or a reset.
    void configure() override;
    // The core's parameters from the table: what configure() fits (checked parameter by parameter by
    // tests/parameters_reach_core_test.cpp).
    Parameters parameters() const;

private:
    const ssr_plant::Model& plant() const;
    // What the current inputs fix (panel photocurrents, short-circuit and Hall currents), recomputed
    // only when the input values changed (inputs are constant over a step); checked on every use.
    // An illumination also depends on the faults in effect, and on t while a degradation is.
    const Illumination& illumination(const ssr_plant::Model& m, double t) const;
    Inputs inputs() const;
    State state() const;
    bool gate_output() const;
    std::int32_t pwm_period_output() const;

    // Derived from the parameters by configure(), outside the FMU state.
    std::optional<ssr_plant::Model> model_;
    mutable std::optional<Illumination> illumination_;
    mutable Inputs illumination_inputs_{};
    mutable FaultState illumination_faults_{};
    mutable double illumination_time_ = 0.0;  // used only while a degradation is in effect
    // The last bus-side panel solves (see BusSideMemo), emptied with every new illumination (and so
    // with every refit, which drops the illumination).
    mutable BusSideMemo bus_side_memo_;
};

}  // namespace ssr_plant
