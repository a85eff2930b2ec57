#include "ssr_plant/shunt_regulator.hpp"

#include <algorithm>

namespace ssr_plant {

double controller_duty(const Parameters& p, double v_bus) {
    // Higher bus voltage → shunt more of the period (eq. 4: I_bus = (1 − D) I).
    return std::clamp(p.controller_gain * (v_bus - p.bus_voltage_reference), 0.0, 1.0);
}

std::array<double, 3> differential_currents(const std::array<double, 6>& i) {
    // eq. 5 / seed 001 eq. 2 numerators: opposite faces' short-circuit currents subtract.
    return {i[0] - i[1], i[2] - i[3], i[4] - i[5]};
}

}  // namespace ssr_plant
