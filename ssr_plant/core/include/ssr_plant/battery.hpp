// The 12 V battery of fig. 5 and its two paths to the bus: the series diode that lets it carry the load
// when the bus falls (eclipse), and the charge MOSFET commanded by the hysteresis charge controller.
#pragma once

#include "ssr_plant/parameters.hpp"

namespace ssr_plant {

// Open-circuit voltage at a state of charge: linear in the table, held outside [0, 1].
double open_circuit_voltage(const BatteryParameters& b, double soc);

struct BatteryPoint {
    double current = 0.0;           // A into the battery (+ charging) = current drawn from the bus
    double terminal_voltage = 0.0;  // V, behind the internal resistance: OCV + I · R_int
};

// Polarization resistance of charging at a state of charge: K soc / (1 − soc + 0.01), soc held in [0, 1].
double charge_polarization_resistance(const BatteryParameters& b, double soc);

// Solves the piecewise-linear network
//   battery EMF (OCV) — R_int — terminal node ─┬─ [charge switch + charge-path R] ─ bus  (if connected)
//                                              └─ [diode V_f, R_d], terminal → bus
// exactly: first with the diode blocking, then, if its forward voltage is exceeded, conducting.
// While the switch is closed and the bus is above the EMF the battery charges through R_path, R_int and the
// polarization resistance R_p, its terminal voltage (EMF + I (R_int + R_p)) held at most at charge_voltage
// by the charger: I = min((v_bus − EMF)/(R_path + R_int + R_p), (charge_voltage − EMF)/(R_int + R_p)) ≥ 0.
// Continuous in v_bus and soc (kinks where the diode starts to conduct and where the voltage limit starts).
BatteryPoint battery_operating_point(const BatteryParameters& b, double soc, double v_bus, bool charge_connected);

}  // namespace ssr_plant
