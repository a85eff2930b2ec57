// One photovoltaic panel as the single-diode circuit of fig. 2 (eq. 2 with series and shunt resistance):
//   I = I_ph − I_D (exp((V + I R_s) / a) − 1) − (V + I R_s) / R_sh,   a = n · N_s · V_T.
#pragma once

#include <stdexcept>

#include "ssr_plant/parameters.hpp"

namespace ssr_plant {

class ParameterError : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

// The circuit parameters of one panel, derived from its datasheet.
struct DiodeModel {
    double photocurrent_rated = 0.0;  // A, I_ph at the rated irradiance and normal incidence
    double saturation_current = 0.0;  // A, I_D of eq. 2
    double ideality_voltage = 0.0;    // V, a = n · N_s · V_T
    double ideality = 0.0;            // n (per cell)
    double series_resistance = 0.0;   // Ω, R_s
    double shunt_resistance = 0.0;    // Ω, R_sh
    double rated_irradiance = 0.0;    // W/m²
};

// Fits I_ph, I_D, n and R_s (R_sh given) so that the curve passes exactly through the datasheet's
// short-circuit point (0, Isc), open-circuit point (Voc, 0) and maximum-power point (Vmp, Imp), and
// has dP/dV = 0 there. Throws ParameterError if the datasheet is inconsistent or has no such fit.
DiodeModel fit_diode_model(const PanelDatasheet& sheet);

// The same panel at cell temperature T (K), from its fit at the datasheet's temperature T_ref: the
// photocurrent scales with (1 + α ΔT) (α = isc_temperature_coefficient), the diode's thermal voltage with
// T / T_ref, and the saturation current is what puts the open-circuit point at Voc + β ΔT (β =
// voc_temperature_coefficient) with the new photocurrent and thermal voltage, as in M. G. Villalva,
// J. R. Gazoli, E. Ruppert Filho, "Comprehensive approach to modeling and simulation of photovoltaic
// arrays", IEEE Trans. Power Electronics 24(5), 1198–1208, 2009 (their I_0(T) of eq. 7, with R_sh kept).
// Returns `ref` itself, bit for bit, at T == T_ref. Throws ParameterError for a temperature at which the
// panel would have no open-circuit voltage left.
DiodeModel at_temperature(const DiodeModel& ref, const PanelDatasheet& sheet, double temperature);

// Photocurrent at an effective irradiance (W/m², direct · angular response + albedo): linear in
// irradiance, as eq. 1 assumes.
double photocurrent(const DiodeModel& m, double effective_irradiance);

// The current the panel delivers at the terminal voltage V (eq. 2 solved for I), with
// `extra_series_resistance` in series outside the panel (a shunt switch's R_DS(on), say).
// Safeguarded Halley (Newton far from the root) on the diode voltage with a guaranteed bracket: always
// returns a finite value for finite arguments (photocurrent ≥ 0).
double panel_current(const DiodeModel& m, double photocurrent, double voltage, double extra_series_resistance = 0.0);

}  // namespace ssr_plant
