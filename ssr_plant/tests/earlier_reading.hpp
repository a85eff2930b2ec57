// What the older ssr_plant tests assume of the controller (shared by the core tests).
#pragma once

#include "ssr_plant/parameters.hpp"

// The hand bounds of these tests are derived for the regular modulator at 3 per volt (the model's earlier
// reading of the seed's "300" as 300 %/V) and a battery controlled on its state of charge, charged through
// the plain 5 Ω path; the seed's 300 per volt and the voltage-controlled, constant-voltage charge are
// tested on their own (SsrCorePlant.LatchedNatural…, SsrCoreBattery.Charge…, SsrFmuModulation.*).
inline ssr_plant::Parameters earlier_reading() {
    ssr_plant::Parameters p;
    p.controller_gain = 3.0;
    p.modulation = ssr_plant::Modulation::regular;
    p.battery.charge_control = ssr_plant::ChargeControl::state_of_charge;  // and the earlier battery
    p.battery.charge_voltage = 0.0;
    p.battery.charge_polarization = 0.0;
    return p;
}
