// The 12 V-class battery of fig. 5 and its two paths to the bus: the series diode that lets it carry the load
// when the bus falls (eclipse), and the charge MOSFET commanded by the hysteresis charge controller.
//
// Each chemistry is a published characteristic (full references in ssr_plant/README.md and docs/references.md):
// - lead_acid: the rested open-circuit voltage of a 12 V battery from Trojan Battery Company's state-of-charge
//   table (BatteryParameters::open_circuit_voltage); charge efficiency 0.85.
// - lithium_ion: three cells in series, each the model of M. Chen, G. A. Rincón-Mora, "Accurate electrical
//   battery model capable of predicting runtime and I–V performance", IEEE Trans. Energy Conversion 21 (2006)
//   504–511, fitted by them to a TCL PL-383562 cell (850 mAh): open-circuit voltage
//     V_oc(s) = −1.031 e^(−35 s) + 3.685 + 0.2156 s − 0.1178 s² + 0.3201 s³  V,
//   series resistance R_s(s) = 0.1562 e^(−24.37 s) + 0.07446 Ω and the two RC pairs' resistances
//   R_TS(s) = 0.3208 e^(−29.14 s) + 0.04669 Ω, R_TL(s) = 6.603 e^(−155.2 s) + 0.04984 Ω. The RC pairs' time
//   constants (≤ 4 min) are short against an orbit's eclipse and charge (~35 min), so the pack is taken at its
//   steady state: R = R_s + R_TS + R_TL (no extra states). The pack is three 2 Ah cells (or strings of cells
//   in parallel making 2 Ah): the model cell's resistances scaled by 850 mAh / 2 Ah. Charge efficiency 0.99.
// The chemistry's resistances and charger settings are those of the 2 Ah battery whatever `capacity` says:
// `capacity` sets the stored charge alone (the tests use batteries of a few coulombs that fill in seconds).
#pragma once

#include "ssr_plant/parameters.hpp"

namespace ssr_plant {

inline constexpr int lithium_ion_series_cells = 3;                 // a 12 V-class pack: 3 × 3.7 V nominal
inline constexpr double lithium_ion_model_cell_capacity = 3060.0;  // C, Chen & Rincón-Mora's cell: 850 mAh
inline constexpr double lithium_ion_pack_capacity = 7200.0;        // C, the pack the resistances are for: 2 Ah

// One lithium-ion cell of Chen & Rincón-Mora at a state of charge (held in [0, 1]).
double lithium_ion_cell_open_circuit_voltage(double soc);
double lithium_ion_cell_resistance(double soc);  // Ω, R_s + R_TS + R_TL of the 850 mAh cell

// The published values of a chemistry's 2 Ah battery: the open-circuit voltage, the resistance, the charger's
// constant-voltage limit, the reconnect voltage, the end-of-charge current, the charge polarization and the
// charge efficiency. The other fields keep BatteryParameters' defaults (lead_acid: the defaults themselves).
//   lead_acid:   14.4 V (2.40 V/cell), reconnect 12.50 V (rested soc 0.8), end 0.04 A (C/50), K = 2.9 Ω,
//                efficiency 0.85.
//   lithium_ion: 12.30 V (4.10 V/cell, the model cell's rested voltage at soc 1), reconnect 12.15 V (4.05 V/cell,
//                rested soc 0.94), end 0.1 A (C/20), no polarization (the model's resistances), efficiency 0.99.
BatteryParameters battery_preset(BatteryChemistry chemistry);

// Open-circuit voltage (the EMF) at a state of charge: the chemistry's curve, held outside [0, 1].
double open_circuit_voltage(const BatteryParameters& b, double soc);

// The battery's own resistance at a state of charge: lead-acid internal_resistance; lithium-ion the pack's.
double battery_resistance(const BatteryParameters& b, double soc);

// Rate of change of the stored charge (C/s) for a current into the battery: charge_efficiency × I while
// charging, I while discharging.
double stored_charge_rate(const BatteryParameters& b, double current);

struct BatteryPoint {
    double current = 0.0;           // A into the battery (+ charging) = current drawn from the bus
    double terminal_voltage = 0.0;  // V, behind the battery's resistance: OCV + I · R
};

// Polarization resistance of charging at a state of charge: K soc / (1 − soc + 0.01), soc held in [0, 1].
double charge_polarization_resistance(const BatteryParameters& b, double soc);

// Solves the piecewise-linear network
//   battery EMF (OCV) — R — terminal node ─┬─ [charge switch + charge-path R] ─ bus  (if connected)
//                                          └─ [diode V_f, R_d], terminal → bus
// exactly: first with the diode blocking, then, if its forward voltage is exceeded, conducting.
// While the switch is closed and the bus is above the EMF the battery charges through R_path, R and the
// polarization resistance R_p, its terminal voltage (EMF + I (R + R_p)) held at most at charge_voltage
// by the charger: I = min((v_bus − EMF)/(R_path + R + R_p), (charge_voltage − EMF)/(R + R_p)) ≥ 0.
// Continuous in v_bus and soc (kinks where the diode starts to conduct and where the voltage limit starts).
BatteryPoint battery_operating_point(const BatteryParameters& b, double soc, double v_bus, bool charge_connected);

// Whether the charger's voltage limit sets the charge current at this bus voltage (connected, charging):
// (v_bus − EMF)/(R_path + R + R_p) ≥ (charge_voltage − EMF)/(R + R_p). False without a limit (charge_voltage 0).
bool charge_voltage_binds(const BatteryParameters& b, double soc, double v_bus);

}  // namespace ssr_plant
