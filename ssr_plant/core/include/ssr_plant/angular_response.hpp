// Relative response of a panel's photocurrent to the sun's incidence angle β (0 = normal incidence): the
// plant's face of panel_response/ (one definition of the curves, shared with the estimator that inverts
// them).
#pragma once

#include "ssr_plant/parameters.hpp"

namespace ssr_plant {

// eq. 1: cos β, zero beyond 90° (the face does not see the sun). Argument: cos β.
double cosine_response(double cos_beta);

// Kelly cosine of the incidence angle β (radians): Patel's (1999) table, reproduced as fig. 4 of seed 000
// (panel_response::kKellyTable): cos β up to 30°, then a monotone cubic Hermite (Fritsch–Butland slopes)
// through the table, C¹ at 30° (slope of cos) and at 85° (slope 0), zero from 85°.
double kelly_response(double beta);

// The selected law as a function of cos β (the dot product of the sun direction and the face normal).
double angular_response(AngularResponse law, double cos_beta);

}  // namespace ssr_plant
