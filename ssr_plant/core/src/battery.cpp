#include "ssr_plant/battery.hpp"

#include <algorithm>
#include <cmath>

namespace ssr_plant {

double lithium_ion_cell_open_circuit_voltage(double soc) {
    const double s = std::clamp(soc, 0.0, 1.0);
    return -1.031 * std::exp(-35.0 * s) + 3.685 + s * (0.2156 + s * (-0.1178 + s * 0.3201));
}

double lithium_ion_cell_resistance(double soc) {
    const double s = std::clamp(soc, 0.0, 1.0);
    const double series = 0.1562 * std::exp(-24.37 * s) + 0.07446;
    const double transient_short = 0.3208 * std::exp(-29.14 * s) + 0.04669;
    const double transient_long = 6.603 * std::exp(-155.2 * s) + 0.04984;
    return series + transient_short + transient_long;
}

BatteryParameters battery_preset(BatteryChemistry chemistry) {
    BatteryParameters b;  // the lead-acid battery
    if (chemistry == BatteryChemistry::lithium_ion) {
        b.chemistry = chemistry;
        b.charge_voltage = lithium_ion_series_cells * 4.10;
        b.v_connect = lithium_ion_series_cells * 4.05;
        b.charge_end_current = 0.1;  // C/20 of 2 Ah
        b.charge_polarization = 0.0;
        b.charge_efficiency = 0.99;
    }
    return b;
}

double open_circuit_voltage(const BatteryParameters& b, double soc) {
    if (b.chemistry == BatteryChemistry::lithium_ion)
        return lithium_ion_series_cells * lithium_ion_cell_open_circuit_voltage(soc);
    const auto& v = b.open_circuit_voltage;
    const double n = static_cast<double>(v.size() - 1);
    const double s = std::clamp(soc, 0.0, 1.0) * n;
    const auto i = std::min(static_cast<std::size_t>(s), v.size() - 2);
    const double f = s - static_cast<double>(i);
    return v[i] + f * (v[i + 1] - v[i]);
}

double battery_resistance(const BatteryParameters& b, double soc) {
    if (b.chemistry == BatteryChemistry::lithium_ion)
        return lithium_ion_series_cells * lithium_ion_cell_resistance(soc) * lithium_ion_model_cell_capacity /
               lithium_ion_pack_capacity;
    return b.internal_resistance;
}

double stored_charge_rate(const BatteryParameters& b, double current) {
    return current > 0.0 ? b.charge_efficiency * current : current;
}

double charge_polarization_resistance(const BatteryParameters& b, double soc) {
    const double s = std::clamp(soc, 0.0, 1.0);
    return b.charge_polarization * s / (1.0 - s + 0.01);
}

BatteryPoint battery_operating_point(const BatteryParameters& b, double soc, double v_bus, bool charge_connected) {
    const double emf = open_circuit_voltage(b, soc);
    const double r_own = battery_resistance(b, soc);
    if (charge_connected && v_bus > emf) {
        // Charging: the diode is reverse-biased (terminal below the bus), one series loop.
        const double r_batt = r_own + charge_polarization_resistance(b, soc);
        double i = (v_bus - emf) / (b.charge_path_resistance + r_batt);
        if (b.charge_voltage > 0.0) i = std::min(i, std::max(0.0, (b.charge_voltage - emf) / r_batt));
        return {i, emf + i * r_batt};
    }
    const double g_int = 1.0 / r_own;  // not charging: the plain network
    const double g_sw = charge_connected ? 1.0 / b.charge_path_resistance : 0.0;
    const double g_d = 1.0 / b.diode_resistance;

    // Diode blocking: the terminal node is a conductance divider between EMF and bus (KCL).
    double vt = (g_int * emf + g_sw * v_bus) / (g_int + g_sw);
    if (vt - v_bus > b.diode_forward_voltage) {
        // Diode conducting: it is a source V_f with resistance R_d from terminal to bus.
        vt = (g_int * emf + g_sw * v_bus + g_d * (v_bus + b.diode_forward_voltage)) / (g_int + g_sw + g_d);
    }
    return {(vt - emf) * g_int, vt};
}

bool charge_voltage_binds(const BatteryParameters& b, double soc, double v_bus) {
    if (b.charge_voltage <= 0.0) return false;
    const double emf = open_circuit_voltage(b, soc);
    const double r_batt = battery_resistance(b, soc) + charge_polarization_resistance(b, soc);
    return (v_bus - emf) / (b.charge_path_resistance + r_batt) >= (b.charge_voltage - emf) / r_batt;
}

}  // namespace ssr_plant
