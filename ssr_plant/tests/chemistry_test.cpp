// The two battery chemistries against their published characteristics (values typed here from the
// sources, not from the code) and the charge efficiency in a charge–discharge cycle of the whole plant.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "ssr_plant/battery.hpp"
#include "ssr_plant/plant.hpp"
#include "test_integrator.hpp"

namespace {

using namespace ssr_plant;

// Trojan Battery Company, state of charge vs open-circuit voltage of a 12 V lead-acid battery at rest
// (the table in its battery user's guide): 100 % 12.73 V, 90 % 12.62, 80 % 12.50, 70 % 12.37, 60 % 12.24,
// 50 % 12.10, 40 % 11.96, 30 % 11.81, 20 % 11.66, 10 % 11.51.
TEST(SsrCoreChemistry, LeadAcidRestVoltageIsTrojansTable) {
    const BatteryParameters b = battery_preset(BatteryChemistry::lead_acid);
    struct Point {
        double soc, volts;
    };
    for (const Point& p :
         {Point{1.0, 12.73}, Point{0.9, 12.62}, Point{0.8, 12.50}, Point{0.7, 12.37}, Point{0.6, 12.24},
          Point{0.5, 12.10}, Point{0.4, 11.96}, Point{0.3, 11.81}, Point{0.2, 11.66}, Point{0.1, 11.51}})
        EXPECT_NEAR(open_circuit_voltage(b, p.soc), p.volts, 1e-9) << p.soc;
    // Linden's rule for a lead-acid cell, OCV = specific gravity + 0.84 V: Trojan's specific gravities 1.277
    // (100 %) and 1.172 (50 %) give 6 × 2.117 = 12.70 V and 6 × 2.012 = 12.07 V, within 0.04 V of the table.
    EXPECT_NEAR(open_circuit_voltage(b, 1.0), 6 * (1.277 + 0.84), 0.04);
    EXPECT_NEAR(open_circuit_voltage(b, 0.5), 6 * (1.172 + 0.84), 0.04);
}

// Chen & Rincón-Mora 2006, the TCL PL-383562 cell: V_oc(s) = −1.031 e^(−35 s) + 3.685 + 0.2156 s − 0.1178 s²
// + 0.3201 s³, evaluated by hand: s = 1: 3.685 + 0.2156 − 0.1178 + 0.3201 = 4.1029 V (e^(−35) ≈ 6e-16);
// s = 0.5: 3.685 + 0.1078 − 0.02945 + 0.0400125 − 1.031 e^(−17.5) = 3.8033625 V (the exponential 2.6e-8 V);
// s = 0: 3.685 − 1.031 = 2.654 V; s = 0.1: 3.685 + 0.02156 − 0.001178 + 0.0003201 − 1.031 e^(−3.5)
// (= 0.0311335) = 3.6745686 V. The pack is three cells in series.
TEST(SsrCoreChemistry, LithiumIonRestVoltageIsChenAndRinconMorasCellTimesThree) {
    const BatteryParameters b = battery_preset(BatteryChemistry::lithium_ion);
    struct Point {
        double soc, cell_volts;
    };
    for (const Point& p : {Point{1.0, 4.1029}, Point{0.5, 3.8033625}, Point{0.0, 2.654}, Point{0.1, 3.6745686}}) {
        EXPECT_NEAR(lithium_ion_cell_open_circuit_voltage(p.soc), p.cell_volts, 2e-7) << p.soc;
        EXPECT_NEAR(open_circuit_voltage(b, p.soc), 3 * p.cell_volts, 6e-7) << p.soc;
    }
    // Resistance: R_s + R_TS + R_TL at s = 1 by hand, 0.07446 + 0.04669 + 0.04984 (+ 0.1562 e^(−24.37) + …,
    // below 1e-10) = 0.17099 Ω for the 850 mAh cell; the 2 Ah pack of three: 3 × 0.17099 × 0.85 / 2.
    EXPECT_NEAR(lithium_ion_cell_resistance(1.0), 0.17099, 1e-9);
    EXPECT_NEAR(battery_resistance(b, 1.0), 3 * 0.17099 * 0.85 / 2.0, 1e-9);
}

// The charger's constant-voltage limit holds: 4.10 V per cell for lithium-ion (12.30 V), 2.40 V per cell for
// lead-acid (14.4 V), whatever the bus, once the battery is full enough for it to bind.
TEST(SsrCoreChemistry, ConstantVoltageLimitHolds) {
    struct Case {
        BatteryChemistry chemistry;
        double limit;
    };
    for (const Case& c : {Case{BatteryChemistry::lithium_ion, 12.30}, Case{BatteryChemistry::lead_acid, 14.4}}) {
        const BatteryParameters b = battery_preset(c.chemistry);
        EXPECT_NEAR(b.charge_voltage, c.limit, 1e-12);
        for (double soc = 0.0; soc <= 1.0; soc += 0.01)
            for (double v_bus : {13.0, 15.0, 16.0, 20.0})
                EXPECT_LE(battery_operating_point(b, soc, v_bus, true).terminal_voltage, c.limit + 1e-12)
                    << soc << " " << v_bus;
        // Near full the limit binds from a 15 V bus: the terminal sits exactly on it.
        EXPECT_NEAR(battery_operating_point(b, 0.985, 15.0, true).terminal_voltage, c.limit, 1e-12);
    }
}

// A charge–discharge cycle of the whole plant (averaged fidelity, a 0.25 C battery so that it runs in a second):
// sun from the start until the charger has disconnected at its end-of-charge current, then eclipse until the
// state of charge is back at its start. The charge taken out, ∫ −I dt, is the charge put in, ∫ I dt, times the
// chemistry's published charge efficiency: lead-acid 0.85 (~85 %), lithium-ion 0.99 (> 99 %), the values of
// the Battery Design reference on efficiency (batterydesign.net, "Efficiency").
void expect_cycle_returns(BatteryChemistry chemistry, double soc_start, double efficiency) {
    Parameters p;
    p.fidelity = Fidelity::averaged;
    p.battery = battery_preset(chemistry);
    p.battery.capacity = 0.25;
    const Model m = make_model(p);
    double t_dark = 1e9;  // the sun sets once the charger has disconnected
    auto u = [&](double t) {
        Inputs in;
        in.sun_body = {1 / std::sqrt(3.0), 1 / std::sqrt(3.0), 1 / std::sqrt(3.0)};
        in.irradiance = t < t_dark ? 1367.0 : 0.0;
        return in;
    };
    State x{15.0, soc_start};
    double q_in = 0.0, q_out = 0.0, t_prev = 0.0, i_prev = 0.0, soc_top = 0.0, soc_end = 0.0;
    double t_back = 0.0;
    bool was_connected = false, done = false;
    ssr_plant_test::simulate(m, u, x, 0.0, 1.5, 20e-6, 1e-4,
                             [&](double t, const State& xs, const DiscreteState& d, bool) {
                                 if (done) return;
                                 const double i = outputs(m, u(t), d, t, xs).i_batt;
                                 // trapezoid on each side of zero (the current changes sign only at events)
                                 const double dt = t - t_prev, mean = 0.5 * (i + i_prev);
                                 (mean > 0 ? q_in : q_out) += std::abs(mean) * dt;
                                 t_prev = t;
                                 i_prev = i;
                                 if (was_connected && !d.charge_connected && t_dark > t) t_dark = t;
                                 was_connected = d.charge_connected;
                                 soc_top = std::max(soc_top, xs[state_soc]);
                                 if (t > t_dark && xs[state_soc] <= soc_start) {
                                     done = true;
                                     soc_end = xs[state_soc];
                                     t_back = t;
                                 }
                             });
    ASSERT_TRUE(done) << "the cycle did not return to its start";
    // The sample that found soc back at its start is up to one output interval late: the charge drawn past
    // the start (soc_start − soc_end) × capacity is not part of the cycle.
    q_out -= (soc_start - soc_end) * p.battery.capacity;
    EXPECT_GT(soc_top, soc_start + 0.05);  // it did charge
    EXPECT_NEAR(q_out / q_in, efficiency, 2e-3) << "in " << q_in << " C, out " << q_out << " C";
    std::cout << "[charge cycle] from soc " << soc_start << " to " << soc_top << " and back at " << t_back << " s: in "
              << q_in << " C, out " << q_out << " C, ratio " << q_out / q_in << "\n";
}

TEST(SsrCoreChemistry, ChargeDischargeCycleReturnsLessThanPutInByTheEfficiency) {
    expect_cycle_returns(BatteryChemistry::lithium_ion, 0.90, 0.99);
    expect_cycle_returns(BatteryChemistry::lead_acid, 0.79, 0.85);
}

}  // namespace
