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

// Solves the piecewise-linear network
//   battery EMF (OCV) — R_int — terminal node ─┬─ [charge switch + charge-path R] ─ bus  (if connected)
//                                              └─ [diode V_f, R_d], terminal → bus
// exactly: first with the diode blocking, then, if its forward voltage is exceeded, conducting.
// Continuous in v_bus and soc (a kink where the diode starts to conduct).
BatteryPoint battery_operating_point(const BatteryParameters& b, double soc, double v_bus, bool charge_connected);

}  // namespace ssr_plant
