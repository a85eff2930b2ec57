// Relative response of a panel's photocurrent to the sun's incidence angle β (0 = normal incidence).
#pragma once

#include <array>

#include "ssr_plant/parameters.hpp"

namespace ssr_plant {

// The Kelly cosine as tabulated by Patel (1999), "Wind and solar power systems", reproduced as fig. 4
// of seed 000: relative response at the sun angle (degrees). Below 30° it equals the mathematical cosine.
struct KellyPoint {
    double angle_deg;
    double response;
};
inline constexpr std::array<KellyPoint, 6> kelly_table = {{
    {0.0, 1.000}, {30.0, 0.866}, {50.0, 0.635}, {60.0, 0.450}, {80.0, 0.100}, {85.0, 0.000}}};

// eq. 1: cos β, zero beyond 90° (the face does not see the sun). Argument: cos β.
double cosine_response(double cos_beta);

// Kelly cosine of the incidence angle β (radians): cos β up to 30°, then a monotone cubic Hermite
// (Fritsch–Carlson) through the table, C¹ at 30° (slope of cos) and at 85° (slope 0), zero from 85°.
double kelly_response(double beta);

// The selected law as a function of cos β (the dot product of the sun direction and the face normal).
double angular_response(AngularResponse law, double cos_beta);

}  // namespace ssr_plant
