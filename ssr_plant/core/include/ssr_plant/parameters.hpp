// The plant's parameters: one plain, trivially copyable struct with documented defaults.
// Values marked "seed" are from paper 000 §4 / 001 §4; the others are assumptions for a plausible
// small-satellite power system (a 10 Wp, 36-cell panel per face charging a 12 V battery from a 15 V bus)
// and say so.
#pragma once

#include <array>
#include <cstdint>

#include "ssr_plant/fault_parameters.hpp"

namespace ssr_plant {

// How the plant is solved in time. Both use the same equations (plant.cpp); only the shunt fraction
// and the sample/hold differ.
enum class Fidelity : std::int32_t {
    switching = 0,  // every PWM edge is a time event; the S/H tracks while the gate is on, holds while off
    averaged = 1,   // state-space average over one PWM period (eq. 4): no PWM events; the S/H output is
                    // the continuous differential short-circuit current
};

// The panel's relative response to the sun's incidence angle β.
enum class AngularResponse : std::int32_t {
    cosine = 0,  // eq. 1: I_sc = I_sc|β=0 · cos β
    kelly = 1,   // Kelly cosine, seed 000 fig. 4 (after Patel 1999), see angular_response.hpp
};

// Datasheet of one panel at the rated irradiance (standard test conditions, cell temperature below).
// Assumed values of a common 36-cell 10 Wp silicon module: Pmp = 17.5 V · 0.5714 A = 10.0 W, fill
// factor 0.750. Its open-circuit voltage (21.5 V) leaves room for a 15 V bus plus an OR diode.
struct PanelDatasheet {
    double rated_irradiance = 1000.0;     // W/m², seed: 10 Wp at 1000 W/m²
    double short_circuit_current = 0.62;  // A, Isc (assumed)
    double open_circuit_voltage = 21.5;   // V, Voc (assumed)
    double max_power_current = 0.5714;    // A, Imp (assumed)
    double max_power_voltage = 17.5;      // V, Vmp (assumed); Vmp·Imp = 10.0 W (seed: 10 Wp)
    std::int32_t cells_in_series = 36;    // (assumed)
    // Ω, R_sh of fig. 2 for the whole panel (assumed; the datasheet points fix the other four unknowns).
    // 2000 Ω gives the fit n ≈ 1.28, R_s ≈ 1.34 Ω (37 mΩ per cell); a much lower R_sh cannot reach this
    // fill factor with a physical ideality (500 Ω would need n ≈ 0.42).
    double shunt_resistance = 2000.0;
    double cell_temperature = 298.15;  // K, the datasheet's (and the fit's) cell temperature, V_T = k T / q of eq. 2
    // Temperature coefficients of a crystalline-silicon module (typical datasheet values, assumed):
    // Isc +0.05 %/K; Voc −74 mV/K for 36 cells (−2.06 mV/K per cell, −0.34 %/K of 21.5 V). How a panel at
    // another temperature is derived from the fit: pv_panel.hpp, at_temperature().
    double isc_temperature_coefficient = 0.0005;  // 1/K, relative
    double voc_temperature_coefficient = -0.074;  // V/K, whole panel

    friend bool operator==(const PanelDatasheet&, const PanelDatasheet&) = default;
};

// What the battery's hysteresis charge controller watches (seed 000 §2: it "connects the battery to the
// power bus when its voltage level is the minimum" and disconnects it "when the maximum charge is reached").
enum class ChargeControl : std::int32_t {
    // The battery's terminal voltage, what the computer measures: connect when it falls to v_connect (and
    // the bus can charge it), disconnect when the charge current has fallen to charge_end_current (the
    // taper of the constant-voltage phase: full charge; also when the bus stops charging it).
    voltage = 0,
    // The state of charge itself (soc_connect, soc_disconnect): an idealisation the computer cannot measure.
    state_of_charge = 1,
};

// The battery's chemistry: which published characteristic gives its open-circuit voltage, its resistance and its
// charge (coulombic) efficiency (battery.hpp; sources in ssr_plant/README.md and docs/references.md).
enum class BatteryChemistry : std::int32_t {
    // A 12 V lead-acid monobloc (6 cells): rested voltage vs state of charge from Trojan Battery Company's
    // published table (consistent with Linden's rule OCV = specific gravity + 0.84 V per cell), the table below.
    lead_acid = 0,
    // Three lithium-ion cells in series (a 12 V-class pack): each cell the Chen & Rincón-Mora (2006) model of
    // their TCL PL-383562 cell, its open-circuit voltage and its series and transient resistances as the
    // published functions of the state of charge, the resistances scaled to a 2 Ah pack.
    lithium_ion = 1,
};

// A 12 V-class battery. The defaults are the lead-acid one (= battery_preset(BatteryChemistry::lead_acid));
// battery_preset() gives each chemistry's published values, and the FMU takes its battery from it.
struct BatteryParameters {
    BatteryChemistry chemistry = BatteryChemistry::lead_acid;
    double capacity = 7200.0;  // C (= 2 Ah, assumed)
    // Lead-acid only: rested open-circuit voltage at soc = 0, 0.1, …, 1 (Trojan Battery Company's table for a
    // 12 V battery, 10 … 100 %; the 0 % point 11.30 V extrapolates it). Linear between points, held outside [0, 1].
    std::array<double, 11> open_circuit_voltage = {11.30, 11.51, 11.66, 11.81, 11.96, 12.10,
                                                   12.24, 12.37, 12.50, 12.62, 12.73};  // V
    double internal_resistance = 0.05;  // Ω, lead-acid only (assumed); lithium-ion: Chen & Rincón-Mora's
    // Charge path bus → charge MOSFET → current-limiting resistor → battery. Without a limit the
    // 15 V bus against a 12.5 V battery would draw tens of amperes; 5 Ω gives about C/4 (assumed).
    double charge_path_resistance = 5.0;  // Ω
    // Discharge path battery → series diode → bus (fig. 5): carries the load in eclipse.
    double diode_forward_voltage = 0.6;  // V (assumed)
    double diode_resistance = 0.05;      // Ω, forward slope of the piecewise-linear diode (assumed)
    // Hysteresis charge control (seed 000 §2): connect for charging when soc falls to the low
    // threshold, disconnect when it reaches full charge. The band makes the switching count finite.
    double soc_connect = 0.80;     // (assumed)
    double soc_disconnect = 1.00;  // "maximum charge" (seed)
    ChargeControl charge_control = ChargeControl::voltage;
    // Voltage control: connect when the terminal voltage has fallen to v_connect (lead-acid 12.50 V, the
    // table's rested voltage at soc 0.8, assumed); disconnect when the charge current has tapered to
    // charge_end_current (lead-acid C/50: 0.04 A of 2 Ah).
    double v_connect = 12.50;          // V
    double charge_end_current = 0.04;  // A
    // Charge model. The charger holds the terminal voltage at most at charge_voltage (the constant-voltage
    // phase; lead-acid 2.40 V per cell; 0 = no limit), and charging sees a polarization resistance that grows
    // as the battery fills, R_p = K soc / (1 − soc + 0.01) (the Shepherd form: C. M. Shepherd, J. Electrochem.
    // Soc. 112 (1965) 657; O. Tremblay, L.-A. Dessaint, World Electric Vehicle Journal 3 (2009)). Lead-acid:
    // K = 2.9 Ω for 2 Ah, fitted so that the charge through the 5 Ω path from the 15 V bus reaches 14.4 V
    // (2.40 V per cell) at soc 0.85, the middle of the published 80–90 % (battery.hpp); at half charge it
    // then sits at 13.16 V (2.19 V per cell, 0.37 A). Discharge does not see it. K = 0: no overpotential.
    double charge_voltage = 14.4;      // V
    double charge_polarization = 2.9;  // Ω (K)
    // Charge (coulombic) efficiency: the fraction of the charging current that is stored (the rest drives
    // side reactions: gassing in lead-acid). Lead-acid ~0.85, lithium-ion > 0.99 (battery.hpp).
    double charge_efficiency = 0.85;

    friend bool operator==(const BatteryParameters&, const BatteryParameters&) = default;
};

// How the switching plant's PWM turns the controller output into gate pulses (switching fidelity only).
enum class Modulation : std::int32_t {
    // Regularly sampled: the controller is sampled at each period start and the gate stays on for D·T
    // (a time event). Stable only while the loop gain per period, I_pv·T·K/C, stays below 2: about
    // K < 12 /V here. At the seed's 300 /V it is ≈ 48 and the bus falls into a 0/1 limit cycle.
    regular = 0,
    // Naturally sampled trailing-edge modulator with a latch: the clock turns the gate on at each period
    // start (when D > 0) and the comparator turns it off the first time the live controller output
    // D(v_bus(t)) falls to the rising carrier (t − t_k)/T (a state event); it stays off until the next
    // period start (one turn-off per period: no chatter). What an analogue PWM IC (clocked latch and
    // comparator) does; stable at the seed's 300 /V.
    latched_natural = 1,
};

struct Parameters {
    Fidelity fidelity = Fidelity::switching;
    Modulation modulation = Modulation::latched_natural;
    AngularResponse angular_response = AngularResponse::cosine;
    PanelDatasheet panel;
    double or_diode_forward_voltage = 0.6;  // V, the fast OR diode between each panel and the bus (assumed)
    double or_diode_resistance = 0.05;      // Ω, its forward slope (assumed)
    double shunt_switch_resistance = 0.05;  // Ω, R_DS(on) of each shunt MOSFET (assumed)

    // Sequential Shunt Regulator (fig. 5 / fig. 7).
    double pwm_frequency = 5000.0;        // Hz (seed)
    double bus_capacitance = 1500e-6;     // F (seed)
    double load_resistance = 90.0;        // Ω (seed)
    double bus_voltage_reference = 15.0;  // V (seed)
    // Proportional controller, seed gain 300 (000 §4: "a proportional controller, which gain is adjusted to
    // 300", with "null error"), per volt of bus error:
    //   D = clamp(controller_gain · (v_bus − v_ref), 0, 1)   (D = fraction of the period shunted).
    // At 300 /V the steady-state offset of the P controller is D/K ≈ 0.85/300 = 2.8 mV: the seed's "null
    // error". The averaged plant and the latched_natural modulator are stable there; the regular one is
    // not (see Modulation). 3 /V with the regular modulator is this model's earlier reading (300 %/V).
    double controller_gain = 300.0;  // 1/V (seed)

    BatteryParameters battery;

    // Injected faults (faults.hpp); the defaults inject none.
    FaultParameters faults;
    friend bool operator==(const Parameters&, const Parameters&) = default;
};

}  // namespace ssr_plant
