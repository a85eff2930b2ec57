// What plant.cpp and the step between PWM edges (between_edges.cpp) share, not part of the core's interface.
#pragma once

#include <array>

#include "ssr_plant/battery.hpp"
#include "ssr_plant/plant.hpp"

namespace ssr_plant::detail {

// The bus node and the battery at one instant: what derivatives() and outputs() share.
struct BusBalance {
    double sigma = 0.0;                              // shunt fraction
    std::array<double, face_count> sigma_face = {};  // each face's (a stuck switch's own)
    std::array<double, face_count> i_pv = {};        // A, bus-side panel currents with the shunts open
    BatteryPoint batt;
    State dx = {};
};

// The panels without any solve: each face's circuit, photocurrent and the faults that change its wiring.
// A shadow takes its fraction of the direct sun (the albedo comes from the Earth's side); a degradation
// scales the photocurrent. (i_sc, i_shorted, i_shunt, i_hall are left 0: illuminate() solves them.)
Illumination panels(const Model& m, const Inputs& u, const FaultState& s, double t);

// The bus balance at state x: shunt fractions, the panels' bus-side currents, the battery, dx.
// memo: see BusSideMemo (nullptr: solve every time).
BusBalance bus_balance(const Model& m, const Illumination& l, const DiscreteState& d, const State& x,
                       BusSideMemo* memo);

}  // namespace ssr_plant::detail
