#include "ssr_plant/pv_panel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "reference_formulas.hpp"

namespace {

using namespace ssr_plant;

// The default datasheet numbers, typed here by hand (they are the assumptions documented in
// parameters.hpp): Isc 0.62 A, Voc 21.5 V, Imp 0.5714 A, Vmp 17.5 V, 36 cells, 10 Wp at 1000 W/m².
constexpr double isc = 0.62, voc = 21.5, imp = 0.5714, vmp = 17.5;

class SsrCorePanel : public ::testing::Test {
protected:
    DiodeModel m = fit_diode_model(PanelDatasheet{});
    double iph = photocurrent(m, 1000.0);
};

TEST_F(SsrCorePanel, FitIsPhysicallyPlausible) {
    // Silicon cells: ideality between 1 and 2; series resistance positive and well below the
    // MPP's V/I (30 Ω); saturation current tiny against Isc.
    EXPECT_GT(m.ideality, 1.0);
    EXPECT_LT(m.ideality, 2.0);
    EXPECT_GT(m.series_resistance, 0.0);
    EXPECT_LT(m.series_resistance, 3.0);
    EXPECT_GT(m.saturation_current, 0.0);
    EXPECT_LT(m.saturation_current, 1e-6 * isc);
    EXPECT_NEAR(iph, isc, 0.01 * isc);  // I_ph ≈ Isc (1 + R_s/R_sh)
}

TEST_F(SsrCorePanel, PassesThroughDatasheetPoints) {
    EXPECT_NEAR(panel_current(m, iph, 0.0), isc, 1e-9);
    EXPECT_NEAR(panel_current(m, iph, voc), 0.0, 1e-9);
    EXPECT_NEAR(panel_current(m, iph, vmp), imp, 1e-9);
}

TEST_F(SsrCorePanel, MaximumPowerIsTenWattsPeak) {
    // Independent search: golden section on P(V) = V I(V) over [0, Voc] (seed: 10 Wp at 1000 W/m²).
    double lo = 0.0, hi = voc;
    const double r = (std::sqrt(5.0) - 1.0) / 2.0;
    for (int i = 0; i < 100; ++i) {
        const double a = hi - r * (hi - lo), b = lo + r * (hi - lo);
        if (a * panel_current(m, iph, a) > b * panel_current(m, iph, b))
            hi = b;
        else
            lo = a;
    }
    const double v = 0.5 * (lo + hi);
    const double p = v * panel_current(m, iph, v);
    EXPECT_NEAR(p, 10.0, 0.1);        // within 1 % of 10 Wp
    EXPECT_NEAR(v, vmp, 0.01 * vmp);  // at the datasheet's Vmp
    // Coarse scan confirms no higher power elsewhere on the curve.
    for (int i = 0; i <= 2150; ++i) EXPECT_LE(0.01 * i * panel_current(m, iph, 0.01 * i), p + 1e-9);
}

TEST_F(SsrCorePanel, SolverAgreesWithLambertWClosedForm) {
    // Jain & Kapoor's explicit Lambert-W solution of eq. 2, over a wide range of voltages (reverse bias,
    // forward bias beyond Voc), irradiances (dark to 1.5 suns) and added series resistances.
    for (double g : {0.0, 1.0, 100.0, 1000.0, 1367.0, 1500.0}) {
        for (double extra : {0.0, 0.05, 1.0}) {
            const double ip = photocurrent(m, g);
            for (double v = -30.0; v <= 30.0; v += 0.25) {
                const double expected = ssr_plant_test::lambert_panel_current(
                    ip, m.saturation_current, m.ideality_voltage, m.series_resistance + extra, m.shunt_resistance, v);
                const double got = panel_current(m, ip, v, extra);
                ASSERT_TRUE(std::isfinite(got));
                EXPECT_NEAR(got, expected, 1e-9 * (1.0 + std::abs(expected)))
                    << "g=" << g << " v=" << v << " extra=" << extra;
            }
        }
    }
}

TEST_F(SsrCorePanel, SolverIsMonotoneAndNeverFails) {
    // Extreme but finite arguments: the bracket guarantees an answer.
    for (double v : {-1e4, -100.0, -1.0, 0.0, 15.6, 21.5, 25.0, 50.0, 1e3, 1e4}) {
        const double i = panel_current(m, iph, v, 0.0);
        EXPECT_TRUE(std::isfinite(i)) << v;
    }
    double prev = std::numeric_limits<double>::infinity();
    for (double v = -5.0; v <= 25.0; v += 0.01) {
        const double i = panel_current(m, iph, v);
        EXPECT_LT(i, prev) << v;  // dI/dV < 0 everywhere (eq. 2)
        prev = i;
    }
    // Dark panel at V = 0 gives no current; above zero it draws (diode + shunt) current.
    EXPECT_NEAR(panel_current(m, 0.0, 0.0), 0.0, 1e-15);
    EXPECT_LT(panel_current(m, 0.0, 15.6), 0.0);
}

TEST_F(SsrCorePanel, ShortCircuitCurrentScalesWithIrradiance) {
    // eq. 1's premise: Isc ∝ irradiance. At V = 0 the only non-linear term is the diode's
    // I_D (e^{Isc R_s / a} − 1): with I_D < 1e-6 Isc (FitIsPhysicallyPlausible) and Isc R_s / a ≲ 1
    // it is below 2e-6 Isc ≈ 1.2e-6 A at any of these irradiances.
    for (double g : {100.0, 500.0, 1367.0}) {
        EXPECT_NEAR(panel_current(m, photocurrent(m, g), 0.0), isc * g / 1000.0, 1.2e-6) << g;
    }
}

TEST(SsrCorePanelFit, RejectsInconsistentDatasheets) {
    PanelDatasheet s;
    s.max_power_current = 0.7;  // above Isc
    EXPECT_THROW(fit_diode_model(s), ParameterError);
    s = PanelDatasheet{};
    s.max_power_voltage = 22.0;  // above Voc
    EXPECT_THROW(fit_diode_model(s), ParameterError);
    s = PanelDatasheet{};
    s.max_power_current = 0.619;  // fill factor ≈ 0.81 at Vmp 17.5 with Rsh 500: too square for a diode
    s.max_power_voltage = 21.0;
    EXPECT_THROW(fit_diode_model(s), ParameterError);
    s = PanelDatasheet{};
    s.shunt_resistance = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(fit_diode_model(s), ParameterError);
}

// A panel away from the datasheet's 25 °C (at_temperature): the reference values below come from an
// independent Python script that takes the fit's five parameters as given (I_ph,rated 0.620417, I_0
// 8.0715e-9 A, a 1.185220 V, R_s 1.343961 Ω, R_sh 2000 Ω), applies the temperature rules of the header
// (I_ph (1 + 0.0005 ΔT), a T/T_ref, I_0 from the open circuit at 21.5 − 0.074 ΔT V) and solves eq. 2 for
// I by bisection, at 1367 W/m² and normal incidence.
TEST(SsrCorePvPanel, TemperatureMovesTheCurveAsItsCoefficientsSay) {
    const PanelDatasheet sheet;
    const DiodeModel ref = fit_diode_model(sheet);
    const DiodeModel same = at_temperature(ref, sheet, sheet.cell_temperature);
    EXPECT_EQ(same.saturation_current, ref.saturation_current);  // the fit itself, bit for bit
    EXPECT_EQ(same.ideality_voltage, ref.ideality_voltage);
    EXPECT_EQ(same.photocurrent_rated, ref.photocurrent_rated);

    const DiodeModel hot = at_temperature(ref, sheet, 333.15);  // 60 °C
    const double iph_hot = photocurrent(hot, 1367.0);
    EXPECT_NEAR(panel_current(hot, iph_hot, 0.0), 0.8623714143, 1e-8);
    EXPECT_NEAR(panel_current(hot, iph_hot, 15.6), 0.7457821443, 1e-8);  // near the bus: 0.865 of Isc
    // Isc +1.75 % (0.05 %/K over 35 K), Voc 21.5 − 0.074 · 35 = 18.91 V at the rated irradiance.
    EXPECT_NEAR(panel_current(hot, iph_hot, 0.0) / panel_current(ref, photocurrent(ref, 1367.0), 0.0), 1.0175, 2e-4);
    EXPECT_NEAR(panel_current(hot, photocurrent(hot, 1000.0), 18.91), 0.0, 1e-9);

    const DiodeModel cold = at_temperature(ref, sheet, 233.15);  // −40 °C
    const double iph_cold = photocurrent(cold, 1367.0);
    EXPECT_NEAR(panel_current(cold, iph_cold, 0.0), 0.8199949609, 1e-8);
    EXPECT_NEAR(panel_current(cold, iph_cold, 15.6), 0.8121819434, 1e-8);

    EXPECT_THROW(at_temperature(ref, sheet, 600.0), ParameterError);  // Voc would be gone: 21.5 − 0.074 · 302 < 0
}

}  // namespace
