#include "ssr_plant/plant.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "plant_internals.hpp"
#include "ssr_plant/angular_response.hpp"
#include "ssr_plant/appendage_shadow.hpp"
#include "ssr_plant/battery.hpp"
#include "ssr_plant/shunt_regulator.hpp"

namespace ssr_plant {
namespace {

void require(bool ok, const char* what) {
    if (!ok) throw ParameterError(std::string("ssr_plant parameters: ") + what);
}

bool positive(double v) {
    return std::isfinite(v) && v > 0.0;
}
bool non_negative(double v) {
    return std::isfinite(v) && v >= 0.0;
}

// Time tolerance for "this PWM edge is due now": far below the PWM period, and at least the tolerance
// with which the FMU runtime finds a time event due (fmu::reached: 1e-12 relative, 1e-12 s below 1 s),
// so that an edge the runtime finds due is always taken. A host's t accumulated as a sum of steps lands
// within that of an edge (OMSimulator stepping by 0.1 ms: 2e-13 s below the edge at 1.9842 s).
double edge_tolerance(const Model& m, double t) {
    return 1e-9 * m.pwm_period + 2e-12 * std::max(1.0, std::abs(t));
}

// Pulses shorter than this are no pulse at all (no zero-length gate events).
double effective_duty(const Model& m, double duty) {
    constexpr double tiny = 1e-9;
    (void)m;
    if (duty < tiny) return 0.0;
    if (duty > 1.0 - tiny) return 1.0;
    return duty;
}

// The most PWM periods counted from the start: beyond, edges are closer than the edge tolerance in
// a double and an int64 count would overflow near 9.2e18 (1e11 periods of 200 us: 231 days).
constexpr double max_period_index = 1e11;

double period_start(const DiscreteState& d, const Model& m, std::int64_t k) {
    return d.period_origin + static_cast<double>(k) * m.pwm_period;
}

using FaceDiodes = std::array<DiodeModel, face_count>;

// Per face: the panel at the face's temperature (the fit itself at the datasheet's), with its shorted
// cells removed while a cell short is in effect.
FaceDiodes face_diodes(const Model& m, const Inputs& u, const FaultState& s) {
    const auto& p = m.parameters;
    FaceDiodes d;
    for (std::size_t k = 0; k < face_count; ++k) {
        d[k] = at_temperature(m.diode, p.panel, u.panel_temperature[k]);
        if (fault_on_face(p.faults, s, fault_cell_short, k))
            d[k] = with_cells_shorted(d[k], p.panel.cells_in_series, p.faults.shorted_cells);
    }
    return d;
}

// Direct sunlight on face k through the angular law (eq. 1 or the Kelly cosine), W/m².
double direct_irradiance(const Model& m, const Inputs& u, double norm, std::size_t k) {
    const auto& s = u.sun_body;
    const std::size_t axis = k / 2;
    const double sign = (k % 2 == 0) ? 1.0 : -1.0;  // faces +x, −x, +y, −y, +z, −z
    const double cos_beta = norm > 0.0 ? sign * s[axis] / norm : -1.0;
    return u.irradiance * angular_response(m.parameters.angular_response, cos_beta);
}

double sun_norm(const Inputs& u) {
    const auto& s = u.sun_body;
    return std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
}

}  // namespace

namespace detail {
Illumination panels(const Model& m, const Inputs& u, const FaultState& s, double t) {
    const auto& f = m.parameters.faults;
    Illumination l;
    l.diode = face_diodes(m, u, s);
    const double norm = sun_norm(u);
    for (std::size_t k = 0; k < face_count; ++k) {
        double g = direct_irradiance(m, u, norm, k);
        const bool shadow = fault_on_face(f, s, fault_shadow, k);
        const bool appendage = fault_on_face(f, s, fault_appendage, k);
        if (shadow || appendage) {
            double fraction = shadow ? f.shadow_fraction : 0.0;
            if (appendage && norm > 0.0) {
                const Vec3 sun = {u.sun_body[0] / norm, u.sun_body[1] / norm, u.sun_body[2] / norm};
                const Plate plate{f.appendage_center, f.appendage_side_a, f.appendage_side_b};
                fraction = std::max(fraction, appendage_shadow_fraction(plate, f.appendage_box, k, sun));
            }
            g *= 1.0 - fraction;
        }
        l.photocurrent[k] = photocurrent(l.diode[k], g + u.albedo_face[k]);
        if (fault_on_face(f, s, fault_degradation, k))
            l.photocurrent[k] *= degradation_factor(f.degradation_rate, f.degradation.onset, t);
        l.open[k] = fault_on_face(f, s, fault_string_open, k);
        const bool stuck = fault_on_face(f, s, fault_shunt_switch, k);
        l.switch_stuck_on[k] = stuck && f.switch_stuck == SwitchStuck::on;
        l.switch_stuck_off[k] = stuck && f.switch_stuck == SwitchStuck::off;
    }
    return l;
}
}  // namespace detail

namespace {
using detail::panels;

// Current each panel pushes through its OR diode into the bus when its shunt switch is off: the panel
// sits at v_bus + V_f + I R_or; a reverse-biased diode (panel below bus + V_f) passes nothing. A dark
// panel (I_ph = 0: every face turned away from the sun without albedo) is below any bus V >= 0: no solve.
// An open string passes nothing; a panel whose switch is stuck on never reaches the bus: no solve either.
std::array<double, face_count> bus_side_currents(const Model& m, const Illumination& l, double v_bus) {
    const auto& p = m.parameters;
    const double v_anode = v_bus + p.or_diode_forward_voltage;
    std::array<double, face_count> i{};
    for (std::size_t k = 0; k < face_count; ++k)
        if ((l.photocurrent[k] > 0.0 || v_anode < 0.0) && !l.open[k] && !l.switch_stuck_on[k])
            i[k] = std::max(0.0, panel_current(l.diode[k], l.photocurrent[k], v_anode, p.or_diode_resistance));
    return i;
}

// Fraction of the time the shunts are on: the gate itself (switching) or the duty (averaged, eq. 4).
double shunt_fraction(const Model& m, const DiscreteState& d, double v_bus) {
    if (m.parameters.fidelity == Fidelity::averaged) return controller_duty(m.parameters, v_bus);
    return d.gate ? 1.0 : 0.0;
}

// Face k's own shunt fraction: a switch stuck on shorts its panel all the time, one stuck off never.
double face_shunt_fraction(const Illumination& l, std::size_t k, double sigma) {
    if (l.switch_stuck_on[k]) return 1.0;
    if (l.switch_stuck_off[k]) return 0.0;
    return sigma;
}

bool any_switch_stuck(const Illumination& l) {
    for (std::size_t k = 0; k < face_count; ++k)
        if (l.switch_stuck_on[k] || l.switch_stuck_off[k]) return true;
    return false;
}

// Starts PWM period k at its start time: sample the controller, turn the gate on for the pulse. Regular
// modulation schedules the trailing edge at D·T; latched_natural leaves it to the comparator (a state event).
void start_period(const Model& m, DiscreteState& d, std::int64_t k, double v_bus) {
    d.period_index = k;
    d.duty = effective_duty(m, controller_duty(m.parameters, v_bus));
    d.gate = d.duty > 0.0;
    d.off_edge_pending = m.parameters.modulation == Modulation::regular && d.duty > 0.0 && d.duty < 1.0;
    d.next_event_time = d.off_edge_pending ? period_start(d, m, k) + d.duty * m.pwm_period : period_start(d, m, k + 1);
}

// The latched_natural comparator: live controller output minus the carrier of the period in progress.
double comparator(const Model& m, const DiscreteState& d, double t, double v_bus) {
    return controller_duty(m.parameters, v_bus) - (t - period_start(d, m, d.period_index)) / m.pwm_period;
}

bool comparator_armed(const Model& m, const DiscreteState& d) {
    return m.parameters.fidelity == Fidelity::switching && m.parameters.modulation == Modulation::latched_natural &&
           d.gate;
}

// The charge controller's distance to its next switch (positive between switches):
//   state_of_charge: disconnected soc − soc_connect; connected soc_disconnect − soc.
//   voltage: disconnected max(v_terminal − v_connect, EMF + Δ − v_bus): falls to 0 when the battery is
//            down to v_connect and the bus can charge it with twice charge_end_current (Δ = 2 I_end (R_path +
//            R_int + R_p)): no connecting in eclipse, and the connected indicator starts at +I_end, so the
//            two never chatter;
//            connected: in the charger's constant-voltage phase I_charge − charge_end_current (full: the
//            taper); below it, where the bus sets the current (weak sun), I_charge (disconnect when the bus no
//            longer charges at all). Ending the charge at I_end in weak sun too made the switch chatter at
//            every sunrise: connected, the panels' small surplus sank below I_end; disconnected, the bus rose
//            again (35 switchings in 0.5 s of penumbra in leo_orbit). Without a voltage limit: I − I_end.
double charge_switch_indicator(const Model& m, bool connected, const State& x) {
    const auto& b = m.parameters.battery;
    const double soc = x[state_soc], v_bus = x[state_v_bus];
    if (b.charge_control == ChargeControl::state_of_charge)
        return connected ? b.soc_disconnect - soc : soc - b.soc_connect;
    const BatteryPoint p = battery_operating_point(b, soc, v_bus, connected);
    if (connected)
        return b.charge_voltage > 0.0 && !charge_voltage_binds(b, soc, v_bus) ? p.current
                                                                              : p.current - b.charge_end_current;
    const double margin =
        2.0 * b.charge_end_current *
        (b.charge_path_resistance + battery_resistance(b, soc) + charge_polarization_resistance(b, soc));
    return std::max(p.terminal_voltage - b.v_connect, open_circuit_voltage(b, soc) + margin - v_bus);
}

void update_charge_switch(const Model& m, DiscreteState& d, const State& x) {
    if (charge_switch_indicator(m, d.charge_connected, x) > 0.0) return;
    d.charge_connected = !d.charge_connected;
}

// The bus-side currents at v through the caller's memo (if any): a hit is the earlier solve's result.
std::array<double, face_count> memoized_bus_side_currents(const Model& m, const Illumination& l, double v,
                                                          BusSideMemo* memo) {
    if (!memo) return bus_side_currents(m, l, v);
    for (const auto& e : memo->entries)
        if (e.valid && e.v_bus == v) return e.current;
    auto& e = memo->entries[memo->next];
    memo->next = (memo->next + 1) % memo->entries.size();
    e = {true, v, bus_side_currents(m, l, v)};
    return e.current;
}

}  // namespace

namespace detail {
BusBalance bus_balance(const Model& m, const Illumination& l, const DiscreteState& d, const State& x,
                       BusSideMemo* memo) {
    const auto& p = m.parameters;
    const double v = x[state_v_bus];
    BusBalance b;
    b.sigma = shunt_fraction(m, d, v);
    bool any_open_switch = false;
    for (std::size_t k = 0; k < face_count; ++k) {
        b.sigma_face[k] = face_shunt_fraction(l, k, b.sigma);
        any_open_switch = any_open_switch || b.sigma_face[k] < 1.0;
    }
    // With the shunts closed all period long (gate on, or D = 1) no panel feeds the bus: no solve.
    if (any_open_switch) b.i_pv = memoized_bus_side_currents(m, l, v, memo);
    double i_in = 0.0;
    if (!any_switch_stuck(l)) {
        for (double i : b.i_pv) i_in += i;
        i_in *= (1.0 - b.sigma);  // eq. 4: I_bus = (1 − D) I; σ ∈ {0, 1} when switching
    } else {
        for (std::size_t k = 0; k < face_count; ++k) i_in += (1.0 - b.sigma_face[k]) * b.i_pv[k];
    }
    b.batt = battery_operating_point(p.battery, x[state_soc], v, d.charge_connected);
    b.dx[state_v_bus] = (i_in - v / p.load_resistance - b.batt.current) / p.bus_capacitance;  // C dv/dt = Σ i
    // Charge balance: only charge_efficiency of a charging current is stored (battery.hpp).
    b.dx[state_soc] = stored_charge_rate(p.battery, b.batt.current) / p.battery.capacity;
    return b;
}
}  // namespace detail

namespace {
using detail::bus_balance;
using detail::BusBalance;

// What face k's Hall channel reads, its fault applied to the physical sample/hold value `physical`.
double measured_face_current(const Model& m, const DiscreteState& d, std::size_t k, double physical) {
    const auto& f = m.parameters.faults;
    if (!fault_on_face(f, d.faults, fault_hall, k)) return physical;
    return f.hall_mode == HallFault::stuck ? d.faults.hall_stuck_value : physical + f.hall_offset;
}

// derivatives and outputs in one pass; memo: see BusSideMemo (nullptr: solve every time).
Evaluation evaluation(const Model& m, const Illumination& l, const DiscreteState& d, const State& x,
                      BusSideMemo* memo) {
    const auto& p = m.parameters;
    const double v = x[state_v_bus];
    const BusBalance b = bus_balance(m, l, d, x, memo);
    Evaluation e;
    e.derivatives = b.dx;
    Outputs& y = e.outputs;
    y.i_sc = l.i_sc;
    for (std::size_t k = 0; k < face_count; ++k) y.i_panel[k] = (1.0 - b.sigma_face[k]) * b.i_pv[k];
    const bool averaged = p.fidelity == Fidelity::averaged;
    for (std::size_t k = 0; k < face_count; ++k) {
        // A switch stuck on carries the shorted current all the time; one stuck off nothing (l.i_shunt = 0).
        y.i_shunt[k] = l.switch_stuck_on[k] ? l.i_shunt[k] : (averaged ? b.sigma : d.duty) * l.i_shunt[k];
        // Switching: a panel whose switch is stuck off is on the bus all the time (solved, sigma_face = 0).
        y.i_string[k] = averaged ? y.i_panel[k] + y.i_shunt[k] : l.switch_stuck_off[k] ? b.i_pv[k] : l.i_shorted[k];
    }
    // Seed 001 §3: the S/H samples while the shunts are on and holds while they are off.
    // Averaged: no S/H, the live currents. The per-axis value is the difference of the per-face ones in
    // both branches, computed the same way, so i_sh[k] == i_face_sh[2k] − i_face_sh[2k+1] bit for bit.
    if (p.fidelity == Fidelity::averaged || d.gate) {
        y.i_face_sh = l.i_shunt;
        y.i_sh = l.i_hall;
    } else {
        y.i_face_sh = d.held_face_current;
        y.i_sh = differential_currents(d.held_face_current);
    }
    // A faulty Hall channel misreads its face (the per-axis values are formed from the face channels).
    if (d.faults.phase[fault_hall] == fault_active) {
        for (std::size_t k = 0; k < face_count; ++k) y.i_face_sh[k] = measured_face_current(m, d, k, y.i_face_sh[k]);
        y.i_sh = differential_currents(y.i_face_sh);
    }
    y.v_bus = v;
    y.v_batt = b.batt.terminal_voltage;
    y.i_batt = b.batt.current;
    y.soc = x[state_soc];
    y.duty = p.fidelity == Fidelity::averaged ? b.sigma : d.duty;
    y.gate = p.fidelity == Fidelity::averaged ? b.sigma > 0.0 : d.gate;
    y.i_load = v / p.load_resistance;
    return e;
}

}  // namespace

Model make_model(const Parameters& p) {
    require(p.fidelity == Fidelity::switching || p.fidelity == Fidelity::averaged, "fidelity must be 0 or 1");
    require(p.angular_response == AngularResponse::cosine || p.angular_response == AngularResponse::kelly,
            "angular_response must be 0 (cosine) or 1 (kelly)");
    require(non_negative(p.or_diode_forward_voltage) && non_negative(p.or_diode_resistance),
            "OR diode forward voltage and resistance must be >= 0");
    require(non_negative(p.shunt_switch_resistance), "shunt switch resistance must be >= 0");
    require(std::isfinite(p.panel.isc_temperature_coefficient) && std::isfinite(p.panel.voc_temperature_coefficient),
            "panel temperature coefficients must be finite");
    require(positive(p.pwm_frequency), "PWM frequency must be > 0");
    require(positive(p.bus_capacitance), "bus capacitance must be > 0");
    require(positive(p.load_resistance), "load resistance must be > 0");
    require(std::isfinite(p.bus_voltage_reference), "bus voltage reference must be finite");
    require(non_negative(p.controller_gain), "controller gain must be >= 0");
    const auto& b = p.battery;
    require(b.chemistry == BatteryChemistry::lead_acid || b.chemistry == BatteryChemistry::lithium_ion,
            "battery chemistry must be 0 (lead_acid) or 1 (lithium_ion)");
    require(positive(b.capacity), "battery capacity must be > 0");
    require(positive(b.charge_efficiency) && b.charge_efficiency <= 1.0,
            "battery charge efficiency must be within (0, 1]");
    require(positive(b.internal_resistance), "battery internal resistance must be > 0");
    require(positive(b.charge_path_resistance), "battery charge path resistance must be > 0");
    require(non_negative(b.diode_forward_voltage) && positive(b.diode_resistance),
            "battery diode: forward voltage >= 0 and resistance > 0");
    for (double v : b.open_circuit_voltage) require(positive(v), "battery open-circuit voltages must be > 0");
    require(std::isfinite(b.soc_connect) && std::isfinite(b.soc_disconnect) && b.soc_connect < b.soc_disconnect,
            "hysteresis needs soc_connect < soc_disconnect");
    require(positive(b.v_connect) && positive(b.charge_end_current), "v_connect and charge_end_current must be > 0");
    require(non_negative(b.charge_voltage) && non_negative(b.charge_polarization),
            "charge_voltage and charge_polarization must be >= 0");
    require(b.charge_voltage == 0.0 || b.charge_voltage > b.v_connect, "charge_voltage must exceed v_connect");
    check_faults(p.faults, p.panel.cells_in_series);
    Model m;
    m.parameters = p;
    m.diode = fit_diode_model(p.panel);
    m.pwm_period = 1.0 / p.pwm_frequency;
    return m;
}

void check_inputs(const Inputs& u) {
    for (double s : u.sun_body)
        if (!std::isfinite(s)) throw std::invalid_argument("ssr_plant inputs: sun_body must be finite");
    if (!std::isfinite(u.irradiance) || u.irradiance < 0.0)
        throw std::invalid_argument("ssr_plant inputs: irradiance must be finite and >= 0");
    for (double a : u.albedo_face)
        if (!std::isfinite(a) || a < 0.0)
            throw std::invalid_argument("ssr_plant inputs: albedo_face must be finite and >= 0");
    // 100–500 K: beyond, no silicon cell works (and the temperature coefficients mean nothing).
    for (double t : u.panel_temperature)
        if (!(t >= 100.0 && t <= 500.0))
            throw std::invalid_argument("ssr_plant inputs: panel_temperature must be within 100 ... 500 K");
}

std::array<double, face_count> face_irradiance(const Model& m, const Inputs& u) {
    const double norm = sun_norm(u);
    std::array<double, face_count> g{};
    // Direct sunlight through the angular law, plus the face's albedo.
    for (std::size_t k = 0; k < face_count; ++k) g[k] = direct_irradiance(m, u, norm, k) + u.albedo_face[k];
    return g;
}

Illumination illuminate(const Model& m, const Inputs& u, const FaultState& faults, double t) {
    Illumination l = panels(m, u, faults, t);
    const double r_switch = m.parameters.shunt_switch_resistance;
    for (std::size_t k = 0; k < face_count; ++k) {
        if (l.open[k]) continue;  // an open string: every current of the face is 0
        l.i_sc[k] = panel_current(l.diode[k], l.photocurrent[k], 0.0);
        // Through the closed shunt switch (R_DS(on)): what the Hall transducer sees while the gate is on.
        l.i_shorted[k] = panel_current(l.diode[k], l.photocurrent[k], 0.0, r_switch);
        l.i_shunt[k] = l.switch_stuck_off[k] ? 0.0 : l.i_shorted[k];
    }
    l.i_hall = differential_currents(l.i_shunt);
    return l;
}

Illumination illuminate(const Model& m, const Inputs& u) {
    return illuminate(m, u, FaultState{}, 0.0);
}

DiscreteState initialize(const Model& m, const Inputs& u, double t0, const State& x0) {
    DiscreteState d;
    d.period_origin = t0;
    d.charge_connected = charge_switch_indicator(m, false, x0) <= 0.0;
    advance_faults(m.parameters.faults, d.faults, t0);  // the faults whose onset is at or before the start
    // The S/H starts as if it had been tracking: it holds the live differential current.
    d.held_face_current = illuminate(m, u, d.faults, t0).i_shunt;
    // A Hall channel stuck from the start reads what it read then.
    const auto& hall = m.parameters.faults.hall;
    if (hall.face != no_fault_face) d.faults.hall_stuck_value = d.held_face_current[hall.face - 1];
    if (m.parameters.fidelity == Fidelity::switching) {
        start_period(m, d, 0, x0[state_v_bus]);
    } else {
        d.duty = controller_duty(m.parameters, x0[state_v_bus]);
        d.gate = d.duty > 0.0;
        d.next_event_time = no_time_event;
    }
    return d;
}

State derivatives(const Model& m, const Inputs& u, const DiscreteState& d, double t, const State& x) {
    return bus_balance(m, panels(m, u, d.faults, t), d, x, nullptr).dx;
}

Evaluation evaluate(const Model& m, const Illumination& l, const DiscreteState& d, double /*t*/, const State& x) {
    return evaluation(m, l, d, x, nullptr);
}

Evaluation evaluate(const Model& m, const Illumination& l, const DiscreteState& d, double /*t*/, const State& x,
                    BusSideMemo& memo) {
    return evaluation(m, l, d, x, &memo);
}

Outputs outputs(const Model& m, const Inputs& u, const DiscreteState& d, double t, const State& x) {
    return evaluate(m, illuminate(m, u, d.faults, t), d, t, x).outputs;
}

Indicators event_indicators(const Model& m, const Inputs&, const DiscreteState& d, double t, const State& x) {
    return {charge_switch_indicator(m, d.charge_connected, x),
            comparator_armed(m, d) ? comparator(m, d, t, x[state_v_bus]) : 1.0};
}

double next_time_event(const Model& m, const DiscreteState& d) {
    const double faults = next_fault_event(m.parameters.faults, d.faults);
    if (m.parameters.fidelity == Fidelity::averaged) return faults;
    return std::min(d.next_event_time, faults);
}

EventResult event_update(const Model& m, const Inputs& u, const DiscreteState& d, double t, const State& x) {
    return event_update(m, illuminate(m, u, d.faults, t), d, t, x);
}

EventResult event_update(const Model& m, const Illumination& l, const DiscreteState& d0, double t, const State& x) {
    DiscreteState d = d0;
    const auto& f = m.parameters.faults;
    const std::uint32_t started = advance_faults(f, d.faults, t);
    if ((started & (1u << fault_hall)) != 0u) {
        // A Hall channel sticking now keeps what it read just before: the tracked or the held value.
        const auto k = static_cast<std::size_t>(f.hall.face - 1);
        const bool tracking = m.parameters.fidelity == Fidelity::averaged || d0.gate;
        d.faults.hall_stuck_value = tracking ? l.i_shunt[k] : d0.held_face_current[k];
    }
    if (m.parameters.fidelity == Fidelity::switching) {
        // A host that stepped over whole periods (it should not) restarts in the period holding t
        // instead of walking every edge in between; a time too far for the count is refused.
        if (t >= d.next_event_time + m.pwm_period) {
            const double k = std::floor((t - d.period_origin) / m.pwm_period);
            if (!(k < max_period_index))
                throw std::invalid_argument("ssr_plant: t = " + std::to_string(t) +
                                            " s is more than 1e11 PWM periods "
                                            "after the start (the limit of the period count)");
            if (k > static_cast<double>(d.period_index)) {
                const bool gate_before = d.gate, off_edge_before = d.off_edge_pending;
                start_period(m, d, static_cast<std::int64_t>(k), x[state_v_bus]);
                // As walking the edges would have left it: the S/H holds at every trailing edge passed
                // (the pending one, and one per skipped period when the pulse has an off edge, the duty
                // being the same from the same bus voltage) and when the gate turns off.
                if (off_edge_before || d.off_edge_pending || (gate_before && !d.gate)) d.held_face_current = l.i_shunt;
            }
        }
        // A bounded loop: normally one edge is due.
        for (int guard = 0; guard < 1000000 && t >= d.next_event_time - edge_tolerance(m, t); ++guard) {
            if (d.off_edge_pending) {
                d.gate = false;  // trailing edge of the pulse
                d.off_edge_pending = false;
                d.next_event_time = period_start(d, m, d.period_index + 1);
                // The S/H holds what it tracked up to this instant.
                d.held_face_current = l.i_shunt;
            } else {
                const bool gate_before = d.gate;
                start_period(m, d, d.period_index + 1, x[state_v_bus]);  // controller sample (digital P)
                if (gate_before && !d.gate) d.held_face_current = l.i_shunt;
            }
        }
        // latched_natural: the comparator's trailing edge (the indicator reached 0; the tolerance is the
        // carrier's rise over the time tolerance of a PWM edge). Latched: off until the next period start.
        if (comparator_armed(m, d) && comparator(m, d, t, x[state_v_bus]) <= edge_tolerance(m, t) / m.pwm_period) {
            d.gate = false;
            d.held_face_current = l.i_shunt;  // the S/H holds what it tracked up to this instant
        }
    }
    update_charge_switch(m, d, x);
    return {d, !(d == d0)};
}

}  // namespace ssr_plant
