// What the older ssr_plant tests assume of the controller (shared by the core tests).
#pragma once

#include "ssr_plant/parameters.hpp"

// The hand bounds of these tests are derived for the regular modulator at 3 per volt (the model's earlier
// reading of the seed's "300" as 300 %/V); the seed's 300 per volt is tested in modulation_test.cpp.
inline ssr_plant::Parameters earlier_reading() {
    ssr_plant::Parameters p;
    p.controller_gain = 3.0;
    p.modulation = ssr_plant::Modulation::regular;
    return p;
}
