// The injected faults of the power system (faults.hpp) against their physics: each expected value is a
// datasheet point, a hand derivation in the comment or the independent Lambert-W solution of eq. 2.
#include "ssr_plant/faults.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "reference_formulas.hpp"
#include "ssr_plant/appendage_shadow.hpp"
#include "ssr_plant/plant.hpp"

namespace {

using namespace ssr_plant;

Parameters averaged_plant() {
    Parameters p;
    p.fidelity = Fidelity::averaged;
    return p;
}

// The sun along +x at the datasheet's rated irradiance (1000 W/m²): face +x (index 0) at its ratings.
Inputs sun_on_plus_x() {
    Inputs u;
    u.sun_body = {1.0, 0.0, 0.0};
    u.irradiance = 1000.0;
    return u;
}

// A discrete state with the faults of p in effect from t = 0, after initialization at t0 = 0.
DiscreteState started(const Model& m, const Inputs& u, double v_bus = 15.0) {
    return initialize(m, u, 0.0, {v_bus, 0.9});
}

TEST(SsrFaults, CellShortScalesTheVoltageOfTheDatasheetPoints) {
    // Hand derivation (faults.hpp): per cell nothing changes, so with N' = N − n cells the string's curve is
    // I'(V N'/N) = I(V): the datasheet's Isc, (Vmp, Imp) and Voc move to (0, Isc), (Vmp N'/N, Imp), (Voc N'/N, 0).
    const PanelDatasheet sheet;
    const DiodeModel healthy = fit_diode_model(sheet);
    for (int shorted : {1, 6, 12, 35}) {
        const DiodeModel s = with_cells_shorted(healthy, sheet.cells_in_series, shorted);
        const double scale = (36.0 - shorted) / 36.0;
        const double iph = healthy.photocurrent_rated;
        EXPECT_NEAR(panel_current(s, iph, 0.0), sheet.short_circuit_current, 1e-9) << shorted;
        EXPECT_NEAR(panel_current(s, iph, sheet.max_power_voltage * scale), sheet.max_power_current, 1e-9) << shorted;
        EXPECT_NEAR(panel_current(s, iph, sheet.open_circuit_voltage * scale), 0.0, 1e-9) << shorted;
    }
    EXPECT_THROW(with_cells_shorted(healthy, 36, 0), ParameterError);
    EXPECT_THROW(with_cells_shorted(healthy, 36, 36), ParameterError);
}

TEST(SsrFaults, CellShortBelowTheBusStopsTheFaceFeedingItButNotItsShunt) {
    // 12 of 36 cells shorted: Voc' = 21.5 · 24/36 = 14.33 V, below the bus (15 V) plus the OR diode
    // (0.6 V): the face's OR diode is reverse-biased, it gives the bus nothing. Shorted through its switch it
    // still drives its short-circuit current (Lambert-W with the scaled string and R_DS(on) in series).
    Parameters p = averaged_plant();
    const Inputs u = sun_on_plus_x();
    const Model healthy = make_model(p);
    p.faults.cell_short = {1, 0.0, 0.0};
    p.faults.shorted_cells = 12;
    const Model faulty = make_model(p);
    const State x = {15.0, 0.9};
    const Outputs yh = outputs(healthy, u, started(healthy, u), 0.0, x);
    const Outputs yf = outputs(faulty, u, started(faulty, u), 0.0, x);
    EXPECT_GT(yh.i_panel[0], 0.5);  // healthy: near Isc at 15.6 V, below Vmp = 17.5 V
    EXPECT_EQ(yf.i_panel[0], 0.0);
    const double f = 24.0 / 36.0;
    const DiodeModel& d = healthy.diode;
    const double expected = ssr_plant_test::lambert_panel_current(
        d.photocurrent_rated, d.saturation_current, d.ideality_voltage * f,
        d.series_resistance * f + p.shunt_switch_resistance, d.shunt_resistance * f, 0.0);
    EXPECT_NEAR(yf.i_face_sh[0], expected, 1e-9);
    // The other faces are untouched.
    for (std::size_t k = 1; k < face_count; ++k) EXPECT_EQ(yf.i_panel[k], yh.i_panel[k]) << k;
}

TEST(SsrFaults, OpenStringCarriesNoCurrentAndTheBusLosesItsShare) {
    Parameters p = averaged_plant();
    const Inputs u = sun_on_plus_x();
    const Model healthy = make_model(p);
    p.faults.string_open = {1, 0.0, 0.0};
    const Model faulty = make_model(p);
    const State x = {15.0, 0.9};  // duty 0: every panel on the bus
    const DiscreteState dh = started(healthy, u), df = started(faulty, u);
    const Outputs yh = outputs(healthy, u, dh, 0.0, x);
    const Outputs yf = outputs(faulty, u, df, 0.0, x);
    EXPECT_EQ(yf.i_panel[0], 0.0);
    EXPECT_EQ(yf.i_sc[0], 0.0);
    EXPECT_EQ(yf.i_face_sh[0], 0.0);
    EXPECT_EQ(yf.i_string[0], 0.0);
    EXPECT_EQ(yf.i_shunt[0], 0.0);
    EXPECT_EQ(yf.i_sh[0], -yh.i_face_sh[1]);  // the axis' difference loses its + face
    // Kirchhoff at the bus: C dv/dt falls by exactly the face's healthy current into it.
    const State dxh = derivatives(healthy, u, dh, 0.0, x), dxf = derivatives(faulty, u, df, 0.0, x);
    EXPECT_NEAR((dxh[state_v_bus] - dxf[state_v_bus]) * p.bus_capacitance, yh.i_panel[0], 1e-12);
}

TEST(SsrFaults, DegradationLosesItsRatePerYearOfTheShortCircuitCurrent) {
    // I_sc = I_ph / (1 + R_s/R_sh) up to the diode's I_0 (e^{I R_s / a} − 1) ~ 1e-8 A: proportional to the
    // photocurrent, so I_sc(t) / I_sc(0) = 1 − rate (t − onset) / year to 1e-7.
    Parameters p = averaged_plant();
    const Inputs u = sun_on_plus_x();
    p.faults.degradation = {7, 1000.0, 0.0};
    p.faults.degradation_rate = 0.04;
    const Model m = make_model(p);
    const Model healthy = make_model(averaged_plant());
    const double i0 = illuminate(healthy, u).i_sc[0];
    DiscreteState d = initialize(m, u, 0.0, {15.0, 0.9});
    EXPECT_EQ(next_time_event(m, d), 1000.0);
    EXPECT_EQ(illuminate(m, u, d.faults, 999.0).i_sc[0], i0);  // before the onset
    d = event_update(m, u, d, 1000.0, {15.0, 0.9}).discrete;
    const double half_year = 0.5 * 365.25 * 86400.0;
    for (std::size_t k : {0u, 2u}) {
        Inputs uk = u;
        uk.sun_body = k == 0 ? std::array<double, 3>{1, 0, 0} : std::array<double, 3>{0, 1, 0};
        const double ik = illuminate(healthy, uk).i_sc[k];
        EXPECT_NEAR(illuminate(m, uk, d.faults, 1000.0 + half_year).i_sc[k] / ik, 0.98, 1e-7) << k;
    }
    // After 25 years at 4 %: nothing left, not a negative current.
    EXPECT_EQ(illuminate(m, u, d.faults, 1000.0 + 30 * 365.25 * 86400.0).i_sc[0], 0.0);
}

TEST(SsrFaults, ShadowTakesItsFractionOfTheDirectSunNotOfTheAlbedo) {
    // I_sc ∝ I_ph ∝ effective irradiance (to 1e-7): with 30 % of the face shadowed, 1000 W/m² of sun and
    // 100 W/m² of albedo, I_sc falls to (0.7 · 1000 + 100) / 1100.
    Parameters p = averaged_plant();
    Inputs u = sun_on_plus_x();
    u.albedo_face[0] = 100.0;
    const Model healthy = make_model(p);
    p.faults.shadow = {1, 0.0, 0.0};
    p.faults.shadow_fraction = 0.3;
    const Model faulty = make_model(p);
    const double ratio = illuminate(faulty, u, started(faulty, u).faults, 0.0).i_sc[0] / illuminate(healthy, u).i_sc[0];
    EXPECT_NEAR(ratio, 800.0 / 1100.0, 1e-7);
}

TEST(SsrFaults, ShuntSwitchStuckOnShortsItsPanelStuckOffFeedsTheBus) {
    const Inputs u = sun_on_plus_x();
    Parameters p = averaged_plant();
    p.faults.shunt_switch = {1, 0.0, 0.0};
    p.faults.switch_stuck = SwitchStuck::on;
    const Model on = make_model(p);
    // Duty 0 (v_bus = v_ref): the healthy switches are open, the stuck one shorts +x all the time.
    const State low = {15.0, 0.9};
    const Outputs y_on = outputs(on, u, started(on, u), 0.0, low);
    EXPECT_EQ(y_on.duty, 0.0);
    EXPECT_EQ(y_on.i_panel[0], 0.0);
    EXPECT_NEAR(y_on.i_shunt[0], y_on.i_face_sh[0], 1e-15);
    EXPECT_NEAR(y_on.i_shunt[0], 0.62, 0.01);  // the datasheet's Isc through R_DS(on)
    p.faults.switch_stuck = SwitchStuck::off;
    const Model off = make_model(p);
    // Duty 1 (v_bus 10 mV above the reference at 300 /V): every healthy panel shorted; +x still feeds the
    // bus at 15.01 + 0.6 V, below Vmp = 17.5 V: between the datasheet's Imp and Isc.
    const State high = {15.01, 0.9};
    const DiscreteState d_off = started(off, u, 15.01);
    const Outputs y_off = outputs(off, u, d_off, 0.0, high);
    EXPECT_EQ(y_off.duty, 1.0);
    EXPECT_GT(y_off.i_panel[0], 0.5714);
    EXPECT_LT(y_off.i_panel[0], 0.62);
    EXPECT_EQ(y_off.i_face_sh[0], 0.0);  // nothing flows through the switch its Hall channel is on
    EXPECT_EQ(y_off.i_shunt[0], 0.0);
    // The bus gets it: C dv/dt = I_pv − v/R − I_batt, with I_pv from +x alone.
    const State dx = derivatives(off, u, d_off, 0.0, high);
    EXPECT_NEAR(dx[state_v_bus] * p.bus_capacitance, y_off.i_panel[0] - y_off.i_load - y_off.i_batt, 1e-12);
}

TEST(SsrFaults, HallOffsetAndStuckChangeTheMeasurementNotTheCurrent) {
    Parameters p = averaged_plant();
    Inputs u = sun_on_plus_x();
    const Model healthy = make_model(p);
    p.faults.hall = {1, 5.0, 0.0};
    p.faults.hall_mode = HallFault::offset;
    p.faults.hall_offset = 0.05;
    const Model offset = make_model(p);
    const State x = {15.0, 0.9};
    DiscreteState d = started(offset, u);
    EXPECT_EQ(next_time_event(offset, d), 5.0);
    d = event_update(offset, u, d, 5.0, x).discrete;
    const Outputs yh = outputs(healthy, u, started(healthy, u), 5.0, x);
    const Outputs yo = outputs(offset, u, d, 5.0, x);
    EXPECT_EQ(yo.i_face_sh[0], yh.i_face_sh[0] + 0.05);
    EXPECT_EQ(yo.i_sh[0], yo.i_face_sh[0] - yo.i_face_sh[1]);
    EXPECT_EQ(yo.i_sc[0], yh.i_sc[0]);  // the physical current is untouched
    EXPECT_EQ(yo.i_string[0], yh.i_string[0]);

    p.faults.hall_mode = HallFault::stuck;
    const Model stuck = make_model(p);
    d = event_update(stuck, u, started(stuck, u), 5.0, x).discrete;
    const double at_onset = yh.i_face_sh[0];
    EXPECT_EQ(d.faults.hall_stuck_value, at_onset);
    u.sun_body = {0.6, 0.8, 0.0};  // the sun moves on: cos β = 0.6 on +x, the current falls by 40 %
    const Outputs ys = outputs(stuck, u, d, 6.0, x);
    EXPECT_EQ(ys.i_face_sh[0], at_onset);
    EXPECT_NEAR(ys.i_sc[0], 0.6 * yh.i_sc[0], 1e-7);
}

TEST(SsrFaults, OnsetsAndEndsAreTimeEventsAndAFaultClears) {
    Parameters p = averaged_plant();
    const Inputs u = sun_on_plus_x();
    p.faults.string_open = {1, 2.0, 3.0};
    p.faults.shadow = {3, 2.5, 0.0};
    p.faults.shadow_fraction = 0.5;
    const Model m = make_model(p);
    const State x = {15.0, 0.9};
    DiscreteState d = started(m, u);
    EXPECT_EQ(next_time_event(m, d), 2.0);  // averaged fidelity: the faults' events alone
    d = event_update(m, u, d, 2.0, x).discrete;
    EXPECT_EQ(outputs(m, u, d, 2.0, x).i_sc[0], 0.0);
    EXPECT_EQ(next_time_event(m, d), 2.5);
    d = event_update(m, u, d, 2.5, x).discrete;
    EXPECT_EQ(next_time_event(m, d), 3.0);
    d = event_update(m, u, d, 3.0, x).discrete;
    EXPECT_GT(outputs(m, u, d, 3.0, x).i_sc[0], 0.6);  // the string closed again
    EXPECT_EQ(next_time_event(m, d), no_time_event);
    // A second update at the same instant changes nothing.
    EXPECT_FALSE(event_update(m, u, d, 3.0, x).changed);
    // Switching fidelity: the earlier of the PWM edge and the fault's onset.
    p.fidelity = Fidelity::switching;
    p.faults.string_open = {1, 1e-5, 0.0};
    const Model s = make_model(p);
    EXPECT_EQ(next_time_event(s, started(s, u)), 1e-5);
}

TEST(SsrFaults, RejectsFaultParametersOutOfRange) {
    const auto rejects = [](auto change) {
        Parameters p;
        change(p.faults);
        EXPECT_THROW(make_model(p), ParameterError);
    };
    rejects([](FaultParameters& f) { f.string_open.face = 7; });
    rejects([](FaultParameters& f) { f.degradation.face = 8; });
    rejects([](FaultParameters& f) { f.shadow = {2, 5.0, 4.0}; });  // ends before it starts
    rejects([](FaultParameters& f) { f.shorted_cells = 36; });
    rejects([](FaultParameters& f) { f.degradation_rate = -0.1; });
    rejects([](FaultParameters& f) { f.shadow_fraction = 1.5; });
    rejects([](FaultParameters& f) { f.hall.onset = std::nan(""); });
    Parameters ok;
    ok.faults.degradation.face = 7;
    EXPECT_NO_THROW(make_model(ok));
}

// The appendage's shadow by hand: a 0.1 × 0.1 × 0.34 m box, face +x at x = 0.05 spanning y ±0.05, z ±0.17
// (0.034 m²).
constexpr Vec3 box_3u = {0.1, 0.1, 0.34};

TEST(SsrFaults, AppendageShadowOfAPlateAgainstHandGeometry) {
    const double r = 1.0 / std::sqrt(2.0);
    // Sun normal to +x, a plate parallel to the face covering y in [0, 0.05], all of z: half the face.
    const Plate half{{0.2, 0.025, 0.0}, {0.0, 0.05, 0.0}, {0.0, 0.0, 0.34}};
    EXPECT_NEAR(appendage_shadow_fraction(half, box_3u, 0, {1.0, 0.0, 0.0}), 0.5, 1e-12);
    // Sun at 45° in the x–z plane, a 0.1 m square plate 0.1 m in front of the face (x = 0.15, z ±0.05): the
    // shadow slides by 0.1 m along −z to z in [−0.15, −0.05], all on the face: 0.01 / 0.034.
    const Plate square{{0.15, 0.0, 0.0}, {0.0, 0.1, 0.0}, {0.0, 0.0, 0.1}};
    EXPECT_NEAR(appendage_shadow_fraction(square, box_3u, 0, {r, 0.0, r}), 0.01 / 0.034, 1e-12);
    // The same plate at z in [−0.12, −0.02]: the shadow at z in [−0.22, −0.12] is cut at the edge −0.17.
    const Plate low{{0.15, 0.0, -0.07}, {0.0, 0.1, 0.0}, {0.0, 0.0, 0.1}};
    EXPECT_NEAR(appendage_shadow_fraction(low, box_3u, 0, {r, 0.0, r}), 0.005 / 0.034, 1e-12);
    // A fin standing on the face (the x–y plane at z = 0, x in [0, 0.1], y ±0.05): only its half in front of
    // the face casts, x in [0.05, 0.1] → z' = −(x − 0.05) in [−0.05, 0]: 0.005 / 0.034.
    const Plate fin{{0.05, 0.0, 0.0}, {0.1, 0.0, 0.0}, {0.0, 0.1, 0.0}};
    EXPECT_NEAR(appendage_shadow_fraction(fin, box_3u, 0, {r, 0.0, r}), 0.005 / 0.034, 1e-12);
    // Nothing: the plate behind the face's plane, the sun behind the face, the plate's shadow off the face,
    // a plate seen edge-on, another face.
    const Plate behind{{0.0, 0.0, 0.0}, {0.0, 0.1, 0.0}, {0.0, 0.0, 0.1}};
    EXPECT_EQ(appendage_shadow_fraction(behind, box_3u, 0, {1.0, 0.0, 0.0}), 0.0);
    EXPECT_EQ(appendage_shadow_fraction(half, box_3u, 0, {-1.0, 0.0, 0.0}), 0.0);
    const Plate aside{{0.2, 0.3, 0.0}, {0.0, 0.1, 0.0}, {0.0, 0.0, 0.1}};
    EXPECT_EQ(appendage_shadow_fraction(aside, box_3u, 0, {1.0, 0.0, 0.0}), 0.0);
    const Plate edge_on{{0.2, 0.0, 0.0}, {0.1, 0.0, 0.0}, {0.0, 0.0, 0.1}};
    EXPECT_NEAR(appendage_shadow_fraction(edge_on, box_3u, 0, {1.0, 0.0, 0.0}), 0.0, 1e-15);
    // Face −z (index 5) at z = −0.17, a plate below it covering x ≥ 0, sun along −z: half of 0.1 × 0.1.
    const Plate under{{0.025, 0.0, -0.3}, {0.05, 0.0, 0.0}, {0.0, 0.1, 0.0}};
    EXPECT_NEAR(appendage_shadow_fraction(under, box_3u, 5, {0.0, 0.0, -1.0}), 0.5, 1e-12);
}

TEST(SsrFaults, AppendageShadowCutsTheDirectPhotocurrentFromItsDeployment) {
    // Sun normal to +x, the half-face plate deployed at 100 s: I_sc of +x halves (∝ irradiance, to 1e-7).
    Parameters p = averaged_plant();
    const Inputs u = sun_on_plus_x();
    p.faults.appendage = {1, 100.0, 0.0};
    p.faults.appendage_center = {0.2, 0.025, 0.0};
    p.faults.appendage_side_a = {0.0, 0.05, 0.0};
    p.faults.appendage_side_b = {0.0, 0.0, 0.34};
    const Model m = make_model(p);
    const double healthy = illuminate(make_model(averaged_plant()), u).i_sc[0];
    DiscreteState d = started(m, u);
    EXPECT_EQ(illuminate(m, u, d.faults, 50.0).i_sc[0], healthy);
    EXPECT_EQ(next_time_event(m, d), 100.0);
    d = event_update(m, u, d, 100.0, {15.0, 0.9}).discrete;
    EXPECT_NEAR(illuminate(m, u, d.faults, 100.0).i_sc[0] / healthy, 0.5, 1e-7);
}

}  // namespace
