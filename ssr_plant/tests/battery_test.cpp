#include "ssr_plant/battery.hpp"

#include <gtest/gtest.h>

namespace {

using namespace ssr_plant;

// Defaults typed by hand: OCV table 11.30 … 12.73 V, R_int 0.05 Ω, charge path 5 Ω, diode 0.6 V / 0.05 Ω;
// the tests of the plain network leave out the charge polarization and the charger's voltage limit.
BatteryParameters plain_network() {
    BatteryParameters p;
    p.charge_polarization = 0.0;
    p.charge_voltage = 0.0;
    return p;
}
const BatteryParameters b = plain_network();

TEST(SsrCoreBattery, OpenCircuitVoltageInterpolatesTheTable) {
    EXPECT_DOUBLE_EQ(open_circuit_voltage(b, 0.0), 11.30);
    EXPECT_DOUBLE_EQ(open_circuit_voltage(b, 1.0), 12.73);
    EXPECT_NEAR(open_circuit_voltage(b, 0.5), 12.10, 1e-12);
    EXPECT_NEAR(open_circuit_voltage(b, 0.85), 0.5 * (12.50 + 12.62), 1e-12);  // halfway 0.8…0.9
    EXPECT_DOUBLE_EQ(open_circuit_voltage(b, -0.2), 11.30);                    // held outside [0, 1]
    EXPECT_DOUBLE_EQ(open_circuit_voltage(b, 1.3), 12.73);
}

TEST(SsrCoreBattery, StandbyOnARegulatedBusDrawsNothing) {
    // Switch open, diode reverse-biased (12.73 − 15 < 0.6): no current, terminal = OCV.
    const auto pt = battery_operating_point(b, 1.0, 15.0, false);
    EXPECT_EQ(pt.current, 0.0);
    EXPECT_DOUBLE_EQ(pt.terminal_voltage, 12.73);
}

TEST(SsrCoreBattery, ChargingThroughTheSwitch) {
    // Hand: (15 − 12.10) / (5 + 0.05) = 0.574257… A into the battery.
    const auto pt = battery_operating_point(b, 0.5, 15.0, true);
    EXPECT_NEAR(pt.current, 2.90 / 5.05, 1e-12);
    EXPECT_NEAR(pt.terminal_voltage, 12.10 + 0.05 * 2.90 / 5.05, 1e-12);
}

TEST(SsrCoreBattery, DiodeCarriesTheLoadInEclipse) {
    // Switch open, bus at 11 V: diode conducts, hand: −(12.10 − 0.6 − 11) / (0.05 + 0.05) = −5 A.
    const auto pt = battery_operating_point(b, 0.5, 11.0, false);
    EXPECT_NEAR(pt.current, -5.0, 1e-12);
    // Both paths (switch closed as well): KCL at the terminal node by hand,
    // (vt − 12.10)/0.05 + (vt − 11)/5 + (vt − 11.6)/0.05 = 0 → vt = 476.2 / 40.2.
    const double vt = 476.2 / 40.2;
    const auto both = battery_operating_point(b, 0.5, 11.0, true);
    EXPECT_NEAR(both.terminal_voltage, vt, 1e-12);
    EXPECT_NEAR(both.current, (vt - 12.10) / 0.05, 1e-10);
}

TEST(SsrCoreBattery, ContinuousAtTheDiodeThreshold) {
    // The diode starts conducting at v_bus = OCV − V_f = 11.5 V: no jump in current there.
    const double v0 = 12.10 - 0.6;
    EXPECT_NEAR(battery_operating_point(b, 0.5, v0 + 1e-9, false).current, 0.0, 1e-7);
    EXPECT_NEAR(battery_operating_point(b, 0.5, v0 - 1e-9, false).current, 0.0, 1e-7);
}

TEST(SsrCoreBattery, ChargeCurrentTapersWithPolarizationAndStopsAtTheChargeVoltage) {
    // Independent script (Python, the same hand formulas written out, not this code): loop current
    // (15 − EMF)/(5 + 0.05 + R_p), R_p = 2.9 s/(1.01 − s), limited to (14.4 − EMF)/(0.05 + R_p):
    //   soc 0.5: 0.367408 A, terminal 13.163 V (2.19 V per cell); 0.8: 0.155302 A (14.22 V);
    //   0.85: 0.119046 A, the 14.4 V limit binds (2.40 V per cell at 85 % charge, the fitted point);
    //   0.95: 0.037527 A (limited).
    const BatteryParameters d{};  // the defaults: lead-acid, K = 2.9 Ω, 14.4 V
    struct Case {
        double soc, current;
        bool limited;
    };
    for (const Case& c : {Case{0.5, 0.367408, false}, Case{0.8, 0.155302, false}, Case{0.85, 0.119046, true},
                          Case{0.95, 0.037527, true}}) {
        const auto pt = battery_operating_point(d, c.soc, 15.0, true);
        EXPECT_NEAR(pt.current, c.current, 1e-6) << c.soc;
        if (c.limited)
            EXPECT_NEAR(pt.terminal_voltage, 14.4, 1e-12) << c.soc;
        else
            EXPECT_LT(pt.terminal_voltage, 14.4) << c.soc;
    }
    // The charge curve the issue names: a lead-acid cell near 2.2–2.3 V at half charge, 2.40 V at 80–90 %.
    const double per_cell_half = battery_operating_point(d, 0.5, 15.0, true).terminal_voltage / 6.0;
    EXPECT_GT(per_cell_half, 2.15);
    EXPECT_LT(per_cell_half, 2.3);
    EXPECT_LT(battery_operating_point(d, 0.79, 15.0, true).terminal_voltage, 14.4);
    EXPECT_NEAR(battery_operating_point(d, 0.9, 15.0, true).terminal_voltage, 14.4, 1e-12);
    // Discharging through the closed switch (bus below the EMF) sees no polarization: the plain network.
    EXPECT_NEAR(battery_operating_point(d, 0.5, 11.0, true).current,
                battery_operating_point(b, 0.5, 11.0, true).current, 1e-12);
    // Continuous where charging starts (bus = EMF).
    EXPECT_NEAR(battery_operating_point(d, 0.5, 12.10 + 1e-9, true).current, 0.0, 1e-9);
    EXPECT_NEAR(battery_operating_point(d, 0.5, 12.10 - 1e-9, true).current, 0.0, 1e-7);
}

}  // namespace
