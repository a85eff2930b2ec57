#include "ssr_plant/battery.hpp"

#include <algorithm>
#include <cmath>

namespace ssr_plant {

double open_circuit_voltage(const BatteryParameters& b, double soc) {
    const auto& v = b.open_circuit_voltage;
    const double n = static_cast<double>(v.size() - 1);
    const double s = std::clamp(soc, 0.0, 1.0) * n;
    const auto i = std::min(static_cast<std::size_t>(s), v.size() - 2);
    const double f = s - static_cast<double>(i);
    return v[i] + f * (v[i + 1] - v[i]);
}

double charge_polarization_resistance(const BatteryParameters& b, double soc) {
    const double s = std::clamp(soc, 0.0, 1.0);
    return b.charge_polarization * s / (1.0 - s + 0.01);
}

BatteryPoint battery_operating_point(const BatteryParameters& b, double soc, double v_bus, bool charge_connected) {
    const double emf = open_circuit_voltage(b, soc);
    if (charge_connected && v_bus > emf) {
        // Charging: the diode is reverse-biased (terminal below the bus), one series loop.
        const double r_batt = b.internal_resistance + charge_polarization_resistance(b, soc);
        double i = (v_bus - emf) / (b.charge_path_resistance + r_batt);
        if (b.charge_voltage > 0.0) i = std::min(i, std::max(0.0, (b.charge_voltage - emf) / r_batt));
        return {i, emf + i * r_batt};
    }
    const double g_int = 1.0 / b.internal_resistance;
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

}  // namespace ssr_plant
