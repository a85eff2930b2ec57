// The Sequential Shunt Regulator's controller and its sample/hold current sensing (fig. 5, fig. 7).
#pragma once

#include <array>

#include "ssr_plant/parameters.hpp"

namespace ssr_plant {

// Proportional bus-voltage controller (seed: gain 300 per volt, reference 15 V):
// D = clamp(K (v_bus − v_ref), 0, 1) (see Parameters::controller_gain).
// D is the fraction of the PWM period during which all six shunt MOSFETs are on.
double controller_duty(const Parameters& p, double v_bus);

// The per-axis differential Hall transducer (seed 001 §3): I(+axis) − I(−axis) of the short-circuited
// panels, from the six per-face currents in the face order +x, −x, +y, −y, +z, −z.
std::array<double, 3> differential_currents(const std::array<double, 6>& face_currents);

}  // namespace ssr_plant
