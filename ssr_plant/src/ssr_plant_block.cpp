#include "ssr_plant/ssr_plant_block.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>

#include "fmu/errors.hpp"
#include "fmu/state_check.hpp"
#include "ssr_plant/battery.hpp"

namespace ssr_plant {

namespace {

// The injected faults (faults.hpp): each a physical change of the circuit from its onset (a time event).
void declare_faults(fmu::Table<SsrPlantData>& t) {
    using D = SsrPlantData;
    constexpr std::string_view face = "; 0 = no fault, 1 ... 6 = +x, -x, +y, -y, +z, -z";
    const auto onset = [&](const char* name, double D::*field, const char* what) {
        t.parameter(name, field, "s", std::string("Simulation time at which ") + what + " (a time event)");
    };
    const auto end = [&](const char* name, double D::*field, const char* what) {
        t.parameter(name, field, "s",
                    std::string("Simulation time at which ") + what + " clears (a time event); 0 = never");
    };
    t.parameter("fault_string_open_face", &D::fault_string_open_face, "",
                std::string("Face whose string opens: no current flows in it, to the bus or through its shunt "
                            "switch (its Hall channel reads 0)") +
                    std::string(face))
        .range(0, 6);
    onset("fault_string_open_onset", &D::fault_string_open_onset, "the string opens");
    end("fault_string_open_end", &D::fault_string_open_end, "the open string");
    t.parameter("fault_cell_short_face", &D::fault_cell_short_face, "",
                std::string("Face with shorted cells: its string has fault_cell_short_cells fewer cells in series "
                            "(open-circuit and maximum-power voltages scaled down, the current the same)") +
                    std::string(face))
        .range(0, 6);
    t.parameter("fault_cell_short_cells", &D::fault_cell_short_cells, "",
                "Cells shorted in the faulty string (1 ... cells_in_series - 1)")
        .range(1, 999);
    onset("fault_cell_short_onset", &D::fault_cell_short_onset, "the cells short");
    end("fault_cell_short_end", &D::fault_cell_short_end, "the cell short");
    t.parameter(
         "fault_degradation_face", &D::fault_degradation_face, "",
         std::string("Face whose photocurrent degrades (radiation, contamination), 7 = all faces") + std::string(face))
        .range(0, 7);
    t.parameter("fault_degradation_rate", &D::fault_degradation_rate, "1/year",
                "Fraction of the photocurrent (and so of Isc) lost per year from fault_degradation_onset, linear, "
                "down to 0 at most (a Julian year of 365.25 days)")
        .range(0.0, 1.0);
    onset("fault_degradation_onset", &D::fault_degradation_onset, "the degradation starts (it never clears)");
    t.parameter("fault_shadow_face", &D::fault_shadow_face, "",
                std::string("Face partly shadowed by an appendage (the shadow spread over all of its cells)") +
                    std::string(face))
        .range(0, 6);
    t.parameter("fault_shadow_fraction", &D::fault_shadow_fraction, "1",
                "Fraction of the face's area in the shadow: the direct sun's photocurrent falls by it (albedo "
                "is not shadowed)")
        .range(0.0, 1.0);
    onset("fault_shadow_onset", &D::fault_shadow_onset, "the shadow falls");
    end("fault_shadow_end", &D::fault_shadow_end, "the shadow");
    t.parameter("fault_switch_face", &D::fault_switch_face, "",
                std::string("Face whose shunt MOSFET is stuck (fault_switch_stuck)") + std::string(face))
        .range(0, 6);
    t.choice("fault_switch_stuck", &D::fault_switch_stuck, {{"on", SwitchStuck::on}, {"off", SwitchStuck::off}},
             "How the faulty shunt switch is stuck: on (its panel always shorted: nothing to the bus, its Hall "
             "channel always sees the short-circuit current) or off (its panel always on the bus, the regulator "
             "cannot shunt it; its Hall channel sees nothing)");
    onset("fault_switch_onset", &D::fault_switch_onset, "the shunt switch sticks");
    end("fault_switch_end", &D::fault_switch_end, "the stuck shunt switch");
    t.parameter("fault_hall_face", &D::fault_hall_face, "",
                std::string("Face whose Hall channel (the measured i_face_sh, not the physical current) is "
                            "faulty; i_sh is formed from the measured face channels") +
                    std::string(face))
        .range(0, 6);
    t.choice("fault_hall_mode", &D::fault_hall_mode, {{"offset", HallFault::offset}, {"stuck", HallFault::stuck}},
             "The Hall channel's fault: offset (reads fault_hall_offset too much) or stuck (keeps the value it "
             "read at the onset)");
    t.parameter("fault_hall_offset", &D::fault_hall_offset, "A", "Offset of the faulty Hall channel (mode offset)")
        .range(-100.0, 100.0)
        .applies_when("fault_hall_mode", {"offset"});
    onset("fault_hall_onset", &D::fault_hall_onset, "the Hall channel fails");
    end("fault_hall_end", &D::fault_hall_end, "the Hall channel's fault");
    t.parameter("fault_appendage_face", &D::fault_appendage_face, "",
                std::string("Face shadowed by a body-fixed appendage given by its geometry (a plate); the shadowed "
                            "fraction follows the sun") +
                    std::string(face))
        .range(0, 6);
    t.parameter("fault_appendage_center", &D::fault_appendage_center, "m",
                "Centre of the appendage's plate, body axes from the box's centre");
    t.parameter("fault_appendage_side_a", &D::fault_appendage_side_a, "m",
                "First side of the plate (its points: centre + s side_a + t side_b, s and t in -1/2 ... 1/2)");
    t.parameter("fault_appendage_side_b", &D::fault_appendage_side_b, "m", "Second side of the plate");
    t.parameter("fault_appendage_box", &D::fault_appendage_box, "m",
                "Edges of the box along body x, y, z, centred on the origin, each face covered by its panel "
                "(assumed 3U: 0.1, 0.1, 0.34)")
        .min(1e-3);
    onset("fault_appendage_onset", &D::fault_appendage_onset, "the appendage deploys and starts to shadow");
    end("fault_appendage_end", &D::fault_appendage_end, "the appendage's shadow");
}

}  // namespace

void SsrPlantBlock::declare(fmu::Table<SsrPlantData>& t) {
    using D = SsrPlantData;
    t.input("sun_body", &D::sun_body, "1", "Sun direction in body axes (normalized inside; zero: no direct sun)");
    t.input("irradiance", &D::irradiance, "W/m2", "Direct solar irradiance, 0 in eclipse").min(0.0);
    t.input("albedo_face", &D::albedo_face, "W/m2", "Earth albedo irradiance on each face (+x, -x, +y, -y, +z, -z)")
        .min(0.0);
    t.input("panel_temperature", &D::panel_temperature, "K",
            "Cell temperature of each face (+x, -x, +y, -y, +z, -z); at cell_temperature a face is the datasheet fit, "
            "elsewhere the temperature coefficients move its curve (panel_thermal face_temperature in leo_orbit)")
        .range(100.0, 500.0);

    t.choice("fidelity", &D::fidelity, {{"switching", Fidelity::switching}, {"averaged", Fidelity::averaged}},
             "switching: every PWM edge a time event, S/H tracks while the gate is on; averaged: state-space "
             "average over a PWM period, no PWM events, S/H replaced by the continuous differential current");
    t.choice("angular_response", &D::angular_response,
             {{"cosine", AngularResponse::cosine}, {"kelly", AngularResponse::kelly}},
             "Panel response to the incidence angle: cosine law (seed 000 eq. 1) or Kelly cosine (fig. 4)");
    t.choice("modulation", &D::modulation,
             {{"latched_natural", Modulation::latched_natural}, {"regular", Modulation::regular}},
             "PWM modulator (switching fidelity): latched_natural (default: gate on at each period start, off "
             "when the live controller output falls to the carrier, a state event; seed scenario 15.04 V) or "
             "regular (controller sampled once per period, pulse of D*T; a 0/1 limit cycle at 300 per volt, "
             "15.28 V at 3 per volt)")
        .applies_when("fidelity", {"switching"});
    t.parameter("rated_irradiance", &D::rated_irradiance, "W/m2",
                "Irradiance of the datasheet ratings (seed: 10 Wp at 1000 W/m2)")
        .min(1.0);
    t.parameter("panel_isc", &D::panel_isc, "A",
                "Panel short-circuit current at the rated irradiance (assumed 36-cell 10 Wp panel)")
        .min(1e-3);
    t.parameter("panel_voc", &D::panel_voc, "V", "Panel open-circuit voltage (assumed)").min(0.1);
    t.parameter("panel_imp", &D::panel_imp, "A", "Panel current at the maximum-power point (assumed)").min(1e-3);
    t.parameter("panel_vmp", &D::panel_vmp, "V", "Panel voltage at the maximum-power point (assumed; Vmp Imp = 10 Wp)")
        .min(0.1);
    t.parameter("cells_in_series", &D::cells_in_series, "", "Cells in series per panel").range(1, 1000);
    t.parameter("panel_shunt_resistance", &D::panel_shunt_resistance, "Ohm",
                "Shunt resistance R_sh of the panel (seed 000 fig. 2; assumed)")
        .min(1.0);
    t.parameter("cell_temperature", &D::cell_temperature, "K", "Cell temperature (thermal voltage of eq. 2)")
        .range(100.0, 500.0);
    t.parameter("isc_temperature_coefficient", &D::isc_temperature_coefficient, "1/K",
                "Relative change of the short-circuit current per kelvin (assumed +0.05 %/K, crystalline silicon)")
        .range(-0.01, 0.01);
    t.parameter("voc_temperature_coefficient", &D::voc_temperature_coefficient, "V/K",
                "Change of the panel's open-circuit voltage per kelvin (assumed -74 mV/K: -2.06 mV/K per cell)")
        .range(-1.0, 1.0);
    t.parameter("or_diode_forward_voltage", &D::or_diode_forward_voltage, "V",
                "Forward drop of each panel's OR diode (assumed)")
        .range(0.0, 2.0);
    t.parameter("or_diode_resistance", &D::or_diode_resistance, "Ohm", "Forward slope of the OR diode (assumed)")
        .range(1e-4, 10.0);
    t.parameter("shunt_switch_resistance", &D::shunt_switch_resistance, "Ohm",
                "On-resistance of each shunt MOSFET (assumed)")
        .range(1e-4, 10.0);
    t.parameter("pwm_frequency", &D::pwm_frequency, "Hz", "PWM frequency of the shunt switches (seed: 5 kHz)")
        .range(1.0, 1e6);
    t.parameter("bus_capacitance", &D::bus_capacitance, "F", "Bus capacitor (seed: 1500 uF)").min(1e-9);
    t.parameter("load_resistance", &D::load_resistance, "Ohm",
                "Resistive load on the bus (seed: 90 Ohm); tunable: a load step")
        .min(1e-3)
        .tunable();
    t.parameter("bus_voltage_reference", &D::bus_voltage_reference, "V",
                "Bus voltage reference of the controller (seed: 15 V)")
        .range(0.0, 100.0);
    t.parameter("controller_gain", &D::controller_gain, "1/V",
                "Proportional gain, duty per volt of bus error: D = clamp(K (v_bus - v_ref), 0, 1) (seed: 300 per "
                "volt, offset D/K = 2.8 mV). The regular modulator is unstable above about 12 per volt")
        .range(0.0, 1e5);
    t.choice("battery_chemistry", &D::battery_chemistry,
             {{"lead_acid", BatteryChemistry::lead_acid}, {"lithium_ion", BatteryChemistry::lithium_ion}},
             "Battery chemistry, each a published characteristic with its charger settings: lead_acid (12 V, Trojan "
             "rested-voltage table, charge to 14.4 V, reconnect at 12.5 V, end of charge C/50, charge efficiency "
             "0.85) or lithium_ion (3 cells in series, Chen and Rincon-Mora 2006 cell model, charge to 4.10 V per "
             "cell, reconnect at 4.05 V per cell, end of charge C/20, charge efficiency 0.99)");
    t.parameter("battery_capacity", &D::battery_capacity, "C", "Battery capacity (assumed 2 Ah = 7200 C)").min(1.0);
    t.parameter("charge_path_resistance", &D::charge_path_resistance, "Ohm",
                "Current-limiting resistance of the charge path (assumed)")
        .range(1e-3, 1e4);
    t.parameter("battery_diode_forward_voltage", &D::battery_diode_forward_voltage, "V",
                "Forward drop of the battery's series (discharge) diode")
        .range(0.0, 2.0);
    t.parameter("battery_diode_resistance", &D::battery_diode_resistance, "Ohm", "Forward slope of the battery diode")
        .range(1e-4, 10.0);
    t.parameter("soc_connect", &D::soc_connect, "1",
                "Hysteresis: connect the battery for charging when soc falls to this")
        .range(0.0, 1.0);
    t.parameter("soc_disconnect", &D::soc_disconnect, "1", "Hysteresis: disconnect at this state of charge (full)")
        .range(0.0, 1.0);
    t.choice("charge_control", &D::charge_control,
             {{"voltage", ChargeControl::voltage}, {"state_of_charge", ChargeControl::state_of_charge}},
             "What the charge hysteresis watches: voltage (default: connect when the battery's terminal voltage "
             "falls to the chemistry's reconnect voltage and the bus can charge it, disconnect when the charge "
             "current tapers to the chemistry's end-of-charge current in the charger's constant-voltage phase, or "
             "when the bus stops charging it) or state_of_charge (soc_connect, soc_disconnect)");

    declare_faults(t);

    auto v = t.state("v_cap", &D::v_cap, &D::der_v_cap, "V", "Bus capacitor voltage (the bus voltage)").nominal(15.0);
    auto q = t.state("soc_state", &D::soc_state, &D::der_soc_state, "1", "Battery state of charge (charge / capacity)")
                 .nominal(1.0);
    v.derivative_depends_on({"v_cap", "soc_state", "sun_body", "irradiance", "albedo_face", "panel_temperature"});
    q.derivative_depends_on({"v_cap", "soc_state"});

    t.output("i_sh", &D::i_sh, "A",
             "Sample/hold of the differential Hall current I(+axis) - I(-axis) of the short-circuited panels")
        .depends_on({"sun_body", "irradiance", "albedo_face", "panel_temperature"});
    t.output("i_face_sh", &D::i_face_sh, "A",
             "Sample/hold of each face's Hall channel (+x, -x, +y, -y, +z, -z), the current of its short-circuited "
             "panel: tracks while the gate is on, holds while it is off (averaged fidelity: the live current); "
             "i_sh[k] = i_face_sh[2k-1] - i_face_sh[2k]")
        .depends_on({"sun_body", "irradiance", "albedo_face", "panel_temperature"});
    t.output("i_sc", &D::i_sc, "A", "Each panel's true short-circuit current")
        .depends_on({"sun_body", "irradiance", "albedo_face", "panel_temperature"});
    t.output("i_panel", &D::i_panel, "A", "Each panel's current delivered to the bus (averaged over the PWM state)")
        .depends_on({"sun_body", "irradiance", "albedo_face", "panel_temperature", "v_cap"});
    t.output("i_shunt", &D::i_shunt, "A",
             "Each panel's current through its shunt switch averaged over the PWM period, D times the shorted "
             "panel's current (switching: D sampled at the period's start); for the magnetometer's field")
        .depends_on({"sun_body", "irradiance", "albedo_face", "panel_temperature", "v_cap"});
    t.output("i_string", &D::i_string, "A",
             "Each panel's cell current averaged over the PWM period: averaged fidelity i_panel + i_shunt; switching "
             "fidelity the shorted panel's current (the bus-side current is not solved while the gate is on; the "
             "panel works on the flat part of its curve); for the magnetometer's field")
        .depends_on({"sun_body", "irradiance", "albedo_face", "panel_temperature", "v_cap"});
    t.output("v_bus", &D::v_bus, "V", "Bus voltage").depends_on({"v_cap"});
    t.output("v_batt", &D::v_batt, "V", "Battery terminal voltage").depends_on({"v_cap", "soc_state"});
    t.output("i_batt", &D::i_batt, "A", "Battery current, positive charging").depends_on({"v_cap", "soc_state"});
    t.output("soc", &D::soc, "1", "Battery state of charge").depends_on({"soc_state"});
    t.output("duty", &D::duty, "1", "Shunt duty cycle (fraction of the PWM period the panels are shorted)")
        .depends_on({"v_cap"});
    t.output("pwm_period", &D::pwm_period, "",
             "Index of the PWM period in progress (the controller's samples so far; switching fidelity; 0 in averaged "
             "fidelity; saturates at 2^31 - 1, 5 days at 5 kHz)")
        .depends_on({});
    t.output("gate", &D::gate, "",
             "Shunt MOSFETs on (switching fidelity); always false in averaged fidelity, which has no gate")
        .depends_on({});
    t.output("i_load", &D::i_load, "A", "Load current").depends_on({"v_cap"});
}

fmu::ModelInfo SsrPlantBlock::describe() {
    fmu::ModelInfo info;
    info.model_identifier = "ssr_plant";
    info.model_name = "ssr_plant";
    info.description =
        "Six PV panels (one per face), Sequential Shunt Regulator, 12 V-class battery and Hall sample/hold";
    info.documentation_html =
        "<p>The power system of seed paper 000 sections 2-4 and 001 sections 3-4: six photovoltaic panels, one per "
        "box face (+x, -x, +y, -y, +z, -z), each a single-diode model (eq. 2) with series and shunt resistance "
        "fitted to its datasheet points, lit by irradiance f(beta) (cosine law, eq. 1, or the Kelly cosine of "
        "fig. 4) plus the face's albedo input. The Sequential Shunt Regulator (fig. 5/7) shorts all six panels "
        "during the PWM on-time (5 kHz, <code>switching</code> fidelity); a proportional controller of 300 per "
        "volt (the seed's) sets the duty D = K(v - v_ref), turned into pulses by a latched naturally sampled "
        "modulator (gate on at each period start, a time event; off when D(v(t)) meets the carrier, a state "
        "event; <code>modulation</code> = latched_natural) or a regularly sampled one (<code>regular</code>: "
        "pulse of D T, unstable above about 12 per volt); the 1500 uF bus feeds the 90 Ohm load; a "
        "12 V-class battery (lead-acid or lithium-ion) charges through a charge switch with hysteresis (state events) "
        "and carries the load "
        "through a series diode in eclipse. The Hall transducer of each axis measures I(+axis) - I(-axis) of the "
        "shorted panels; its sample/hold tracks while the gate is on and holds while it is off (seed 001 "
        "section 3): <code>i_sh / i_sc0</code> is the sun vector of eq. 5. The same sample/hold on each face's "
        "own Hall channel gives <code>i_face_sh[1..6]</code> (faces +x, -x, +y, -y, +z, -z), for an estimator "
        "that uses each panel separately: <code>i_sh[k] = i_face_sh[2k-1] - i_face_sh[2k]</code>.</p>"
        "<p>In <code>averaged</code> fidelity the PWM is replaced by its state-space average over one period (no "
        "PWM events) and the sample/hold by the continuous current (per axis and per face: the live current of "
        "the panel short-circuited through its shunt switch): use it for whole orbits.</p>"
        "<p>Faults (parameters <code>fault_...</code>, each on one face 1-6 from its onset to its end, both time "
        "events; face 0 = none): an open string (no current in it), shorted cells (fewer cells in series: the "
        "voltage of the curve scaled), a degradation of the photocurrent per year, a partial shadow of the direct "
        "sun (a fixed fraction, or a body-fixed appendage's from its geometry), a shunt switch stuck on or off, a Hall "
        "channel with an offset or stuck. See the block's README.</p>"
        "<p>Assumed values "
        "(not in the seeds): the panel datasheet, the battery curve and resistances, diode drops, thresholds.</p>";
    info.default_experiment = {.start_time = 0.0, .stop_time = 10.0, .tolerance = 1e-6, .step_size = 1e-3};
    return info;
}

Parameters SsrPlantBlock::parameters() const {
    const auto& d = data();
    Parameters p{};
    p.fidelity = d.fidelity;
    p.angular_response = d.angular_response;
    p.modulation = d.modulation;
    p.panel.rated_irradiance = d.rated_irradiance;
    p.panel.short_circuit_current = d.panel_isc;
    p.panel.open_circuit_voltage = d.panel_voc;
    p.panel.max_power_current = d.panel_imp;
    p.panel.max_power_voltage = d.panel_vmp;
    p.panel.cells_in_series = d.cells_in_series;
    p.panel.shunt_resistance = d.panel_shunt_resistance;
    p.panel.cell_temperature = d.cell_temperature;
    p.panel.isc_temperature_coefficient = d.isc_temperature_coefficient;
    p.panel.voc_temperature_coefficient = d.voc_temperature_coefficient;
    p.or_diode_forward_voltage = d.or_diode_forward_voltage;
    p.or_diode_resistance = d.or_diode_resistance;
    p.shunt_switch_resistance = d.shunt_switch_resistance;
    p.pwm_frequency = d.pwm_frequency;
    p.bus_capacitance = d.bus_capacitance;
    p.load_resistance = d.load_resistance;
    p.bus_voltage_reference = d.bus_voltage_reference;
    p.controller_gain = d.controller_gain;
    p.battery = battery_preset(d.battery_chemistry);
    p.battery.capacity = d.battery_capacity;
    p.battery.charge_path_resistance = d.charge_path_resistance;
    p.battery.diode_forward_voltage = d.battery_diode_forward_voltage;
    p.battery.diode_resistance = d.battery_diode_resistance;
    p.battery.soc_connect = d.soc_connect;
    p.battery.soc_disconnect = d.soc_disconnect;
    p.battery.charge_control = d.charge_control;
    auto& f = p.faults;
    f.string_open = {d.fault_string_open_face, d.fault_string_open_onset, d.fault_string_open_end};
    f.cell_short = {d.fault_cell_short_face, d.fault_cell_short_onset, d.fault_cell_short_end};
    f.shorted_cells = d.fault_cell_short_cells;
    f.degradation = {d.fault_degradation_face, d.fault_degradation_onset, 0.0};
    f.degradation_rate = d.fault_degradation_rate;
    f.shadow = {d.fault_shadow_face, d.fault_shadow_onset, d.fault_shadow_end};
    f.shadow_fraction = d.fault_shadow_fraction;
    f.shunt_switch = {d.fault_switch_face, d.fault_switch_onset, d.fault_switch_end};
    f.switch_stuck = d.fault_switch_stuck;
    f.hall = {d.fault_hall_face, d.fault_hall_onset, d.fault_hall_end};
    f.hall_mode = d.fault_hall_mode;
    f.hall_offset = d.fault_hall_offset;
    f.appendage = {d.fault_appendage_face, d.fault_appendage_onset, d.fault_appendage_end};
    f.appendage_center = d.fault_appendage_center;
    f.appendage_side_a = d.fault_appendage_side_a;
    f.appendage_side_b = d.fault_appendage_side_b;
    f.appendage_box = d.fault_appendage_box;
    return p;
}

namespace {
// The core reports bad parameters as ParameterError; the runtime's error type carries the same reason.
ssr_plant::Model fitted(const Parameters& p) {
    try {
        return make_model(p);
    } catch (const std::invalid_argument& e) {
        throw fmu::Error(e.what());
    }
}
}  // namespace

void SsrPlantBlock::configure() {
    model_ = fitted(parameters());  // throws fmu::Error with the core's reason
    illumination_.reset();
    bus_side_memo_.clear();
}

const ssr_plant::Model& SsrPlantBlock::plant() const {
    if (!model_) throw fmu::Error("ssr_plant: used before configure()");  // the runtime configures first
    return *model_;
}

const Illumination& SsrPlantBlock::illumination(const ssr_plant::Model& m, double t) const {
    const Inputs u = inputs();  // checked on every use: a bad input is reported where it is used
    const FaultState& faults = data().discrete.faults;
    // A degradation in effect makes the photocurrents a function of time.
    const bool timed = faults.phase[fault_degradation] == fault_active;
    if (!illumination_ || !(u == illumination_inputs_) || !(faults == illumination_faults_) ||
        (timed && t != illumination_time_)) {
        illumination_ = illuminate(m, u, faults, t);
        illumination_inputs_ = u;
        illumination_faults_ = faults;
        illumination_time_ = t;
        bus_side_memo_.clear();
    }
    return *illumination_;
}

bool SsrPlantBlock::gate_output() const {
    // The averaged plant has no gate, only a continuous duty (an output of its own).
    return plant().parameters.fidelity == Fidelity::switching && data().discrete.gate;
}

std::int32_t SsrPlantBlock::pwm_period_output() const {
    const auto index = data().discrete.period_index;
    return static_cast<std::int32_t>(std::clamp<std::int64_t>(index, 0, std::numeric_limits<std::int32_t>::max()));
}

Inputs SsrPlantBlock::inputs() const {
    const auto& d = data();
    Inputs u;
    u.sun_body = d.sun_body;
    u.irradiance = d.irradiance;
    u.albedo_face = d.albedo_face;
    u.panel_temperature = d.panel_temperature;
    try {
        check_inputs(u);
    } catch (const std::invalid_argument& e) {
        throw fmu::Error(e.what());  // a bad input value is the caller's error (fmi2Error), not a crash
    }
    return u;
}

State SsrPlantBlock::state() const {
    return {data().v_cap, data().soc_state};
}

// The core's discrete state (outside the table) of a state restored from bytes (issue 14 case 8).
void SsrPlantBlock::check_state() const {
    const auto& s = data().discrete;
    fmu::require_finite(s.period_origin, "discrete.period_origin");
    fmu::require_range(s.period_index, 0, 100'000'000'000, "discrete.period_index");
    if (!(s.duty >= 0.0 && s.duty <= 1.0)) throw fmu::Error("restored FMU state: discrete.duty is outside 0 ... 1");
    fmu::require_bool(s.gate, "discrete.gate");
    fmu::require_bool(s.off_edge_pending, "discrete.off_edge_pending");
    fmu::require_bool(s.charge_connected, "discrete.charge_connected");
    if (std::isnan(s.next_event_time)) throw fmu::Error("restored FMU state: discrete.next_event_time is NaN");
    fmu::require_finite(std::span<const double>(s.held_face_current.data(), s.held_face_current.size()),
                        "discrete.held_face_current");
    for (std::int32_t phase : s.faults.phase)
        fmu::require_range(phase, fault_pending, fault_cleared, "discrete.faults.phase");
    fmu::require_finite(s.faults.hall_stuck_value, "discrete.faults.hall_stuck_value");
}

void SsrPlantBlock::validate() const {
    // The core's own checks run in configure(), right after, at exit of initialization.
    if (!(data().soc_connect < data().soc_disconnect)) throw fmu::Error("soc_connect must be below soc_disconnect");
}

void SsrPlantBlock::initialize(double t) {
    auto& d = data();
    const ssr_plant::Model& m = plant();
    d.discrete = ssr_plant::initialize(m, inputs(), t, state());
    d.gate = gate_output();
    d.pwm_period = pwm_period_output();
}

void SsrPlantBlock::evaluate(double t) {
    auto& d = data();
    const ssr_plant::Model& m = plant();
    const Illumination& l = illumination(m, t);  // first: a new illumination empties the memo
    const Evaluation e = ssr_plant::evaluate(m, l, d.discrete, t, state(), bus_side_memo_);
    d.der_v_cap = e.derivatives[state_v_bus];
    d.der_soc_state = e.derivatives[state_soc];
    const Outputs& y = e.outputs;
    d.i_sh = y.i_sh;
    d.i_face_sh = y.i_face_sh;
    d.i_sc = y.i_sc;
    d.i_panel = y.i_panel;
    d.i_shunt = y.i_shunt;
    d.i_string = y.i_string;
    d.v_bus = y.v_bus;
    d.v_batt = y.v_batt;
    d.i_batt = y.i_batt;
    d.soc = y.soc;
    d.duty = y.duty;
    d.i_load = y.i_load;
    // gate is discrete: it changes only in initialize/event_update (see its description).
}

void SsrPlantBlock::evaluate_derivatives(double t) {
    auto& d = data();
    const State dx = ssr_plant::derivatives(plant(), inputs(), d.discrete, t, state());
    d.der_v_cap = dx[state_v_bus];
    d.der_soc_state = dx[state_soc];
}

void SsrPlantBlock::event_indicators(double t, std::span<double> z) {
    const ssr_plant::Model& m = plant();
    const Indicators g = ssr_plant::event_indicators(m, inputs(), data().discrete, t, state());
    std::copy(g.begin(), g.end(), z.begin());
}

fmu::EventUpdate SsrPlantBlock::event_update(double t, bool) {
    auto& d = data();
    const ssr_plant::Model& m = plant();
    const EventResult r = ssr_plant::event_update(m, illumination(m, t), d.discrete, t, state());
    d.discrete = r.discrete;
    d.gate = gate_output();
    d.pwm_period = pwm_period_output();
    return {};  // the core settles an instant in one call; states never jump
}

std::optional<fmu::SpanReached> SsrPlantBlock::advance_between_events(double t, double t_stop, double rtol,
                                                                      const std::function<void(double)>& move_to) {
    const ssr_plant::Model& m = plant();
    if (m.parameters.fidelity != Fidelity::switching) return std::nullopt;
    // The inputs at time s are what the runtime sets when its clock moves there (a host's interpolation).
    const auto inputs_at = [&](double s) {
        move_to(s);
        return inputs();
    };
    const auto r = advance_between_edges(m, inputs_at, data().discrete, t, state(), t_stop, rtol);
    if (!r) return std::nullopt;
    data().v_cap = r->x[state_v_bus];
    data().soc_state = r->x[state_soc];
    return fmu::SpanReached{r->t, r->state_event};
}

double SsrPlantBlock::next_time_event() const {
    return ssr_plant::next_time_event(plant(), data().discrete);  // PWM edges (switching), fault onsets and ends
}

}  // namespace ssr_plant

FMU_BLOCK(ssr_plant::SsrPlantBlock)
