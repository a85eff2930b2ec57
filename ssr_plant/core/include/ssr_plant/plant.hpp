// The whole power system (seed 000 §2–4, 001 §3–4) as an event-driven ODE for an external integrator:
// six panels (one per face), the Sequential Shunt Regulator with its PWM and P controller, bus capacitor,
// resistive load, battery with series diode and hysteresis charge switch, and the Hall transducers with
// sample/hold: one channel per face on its shunt current, and the per-axis differential (their difference).
//
// Protocol (FMI Model Exchange style), all functions pure:
//   model = make_model(parameters)                      (throws ParameterError)
//   d     = initialize(model, u, t0, x0)                 (discrete state at the start)
//   loop: integrate dx/dt = derivatives(model, u, d, t, x) up to next_time_event(model, d), watching
//         event_indicators(model, u, d, t, x) for sign changes; at a time or state event:
//         d = event_update(model, u, d, t, x).discrete   (continuous states never jump)
//   outputs(model, u, d, t, x) at any point.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <type_traits>

#include "ssr_plant/faults.hpp"
#include "ssr_plant/parameters.hpp"
#include "ssr_plant/pv_panel.hpp"

namespace ssr_plant {

inline constexpr std::size_t face_count = 6;  // +x, −x, +y, −y, +z, −z
inline constexpr std::size_t axis_count = 3;

// Continuous state vector layout.
inline constexpr std::size_t state_v_bus = 0;  // V, bus capacitor voltage (nominal 15)
inline constexpr std::size_t state_soc = 1;    // 1, battery state of charge (charge / capacity, nominal 1)
inline constexpr std::size_t state_count = 2;
using State = std::array<double, state_count>;

// Event indicators (state events). First: the hysteresis charge controller's distance to its next switch,
// by default on the battery's terminal voltage and charge current (ChargeControl::voltage):
//   disconnected: max(v_terminal − v_connect, EMF + Δ − v_bus)  (falls to 0 → connect for charging)
//   connected:    I_charge − charge_end_current in the charger's constant-voltage phase (falls to 0 at
//                 full charge → disconnect), I_charge below it (falls to 0 when the bus stops charging)
// or on the state of charge (ChargeControl::state_of_charge):
//   disconnected: soc − soc_connect      (falls to 0 → connect for charging)
//   connected:    soc_disconnect − soc   (falls to 0 at full charge → disconnect)
// Positive between events; after a switch it restarts well above 0 (no indicator stays at 0, so a
// battery resting at full charge does not leave a root function identically zero).
inline constexpr std::size_t indicator_charge_switch = 0;
// Second: the latched_natural modulator's comparator while the gate is on, D(v_bus) − (t − t_k)/T (the live
// controller output against the rising carrier); it falls to 0 at the pulse's trailing edge. A constant 1
// otherwise (gate off, regular modulation, averaged fidelity): no crossing.
inline constexpr std::size_t indicator_modulator = 1;
inline constexpr std::size_t indicator_count = 2;
using Indicators = std::array<double, indicator_count>;

inline constexpr double no_time_event = std::numeric_limits<double>::infinity();

struct Inputs {
    std::array<double, 3> sun_body = {0.0, 0.0, 1.0};  // sun direction in body axes (normalized here)
    double irradiance = 1367.0;                        // W/m² of direct sunlight, 0 in eclipse (seed)
    std::array<double, face_count> albedo_face = {};   // W/m² of Earth albedo reaching each face
    // K, each face's cell temperature; at the datasheet's cell_temperature (the default) a face is the fit
    // itself, elsewhere pv_panel.hpp's at_temperature() moves its curve.
    std::array<double, face_count> panel_temperature = {298.15, 298.15, 298.15, 298.15, 298.15, 298.15};
    bool operator==(const Inputs&) const = default;
};

// Everything that changes only at events. Trivially copyable.
struct DiscreteState {
    double period_origin = 0.0;              // s, start of PWM period 0 (the start time)
    std::int64_t period_index = 0;           // PWM period in progress: it starts at origin + index · T
    double duty = 0.0;                       // duty sampled at the start of this period (switching);
                                             // (averaged: the value at initialization, unused)
    bool gate = false;                       // shunt MOSFETs on (switching); averaged: duty > 0
    bool off_edge_pending = false;           // the gate turns off at origin + (index + duty) · T
    bool charge_connected = false;           // battery charge MOSFET on
    double next_event_time = no_time_event;  // s, next PWM edge (switching)
    // A, S/H value of each face's shunt current, updated when the gate opens. The per-axis S/H is their
    // difference (one hold instant for both, so i_sh = i_face_sh[+] − i_face_sh[−] exactly).
    std::array<double, face_count> held_face_current = {};
    FaultState faults;  // which injected faults are in effect (faults.hpp)
    friend bool operator==(const DiscreteState&, const DiscreteState&) = default;
};

struct Outputs {
    std::array<double, axis_count> i_sh = {};       // A, S/H of I(+axis) − I(−axis)
    std::array<double, face_count> i_face_sh = {};  // A, S/H of each face's shunt current (i_sh per face)
    std::array<double, face_count> i_sc = {};       // A, each panel's true short-circuit current (V = 0)
    std::array<double, face_count> i_panel = {};    // A, each panel's current into the bus (period
                                                    // average in averaged mode)
    // What a sensor slower than the PWM sees (the magnetometer's field of the currents), period averages in
    // both fidelities, so that they do not jump at the PWM edges:
    std::array<double, face_count> i_shunt = {};   // A, each panel's current through its shunt switch, D · I_short
                                                   // (switching: D sampled at the period's start)
    std::array<double, face_count> i_string = {};  // A, the current of each panel's cells: averaged fidelity
                                                   // (1 − D) I_bus + D I_short = i_panel + i_shunt; switching,
                                                   // whose bus-side current is not solved while the gate is on,
                                                   // I_short (the panel on the flat part of its curve)
    double v_bus = 0.0;                            // V
    double v_batt = 0.0;                           // V, battery terminal voltage
    double i_batt = 0.0;                           // A, into the battery (+ charging)
    double soc = 0.0;                              // 1
    double duty = 0.0;                             // 1, shunt duty cycle
    bool gate = false;                             // shunt MOSFETs on
    double i_load = 0.0;                           // A, through the load resistor
};

// Parameters plus what is derived from them once (the fitted panel circuit). Trivially copyable.
struct Model {
    Parameters parameters;
    DiodeModel diode;
    double pwm_period = 0.0;  // s
};

// The FMU runtime saves and restores a block's state as bytes.
static_assert(std::is_trivially_copyable_v<Parameters> && std::is_trivially_copyable_v<Model> &&
              std::is_trivially_copyable_v<DiscreteState> && std::is_trivially_copyable_v<Inputs> &&
              std::is_trivially_copyable_v<Outputs>);

// What the inputs alone fix, independent of the states and the discrete state: each face's
// photocurrent and true short-circuit current, and the Hall transducers' live currents of the shorted
// panels (per face, and per axis: their difference). Inputs are constant over a host's communication step, so a wrapper computes this
// once per input change instead of once per right-hand side (12 of the 18 panel solves of outputs()).
// Faults in effect change it (faults.hpp): an open string or a switch stuck off carries no shunt current.
struct Illumination {
    std::array<DiodeModel, face_count> diode = {};       // each face's panel at its temperature (and cell short)
    std::array<double, face_count> photocurrent = {};    // A, I_ph of each face
    std::array<bool, face_count> open = {};              // the face's string is open: no current at all
    std::array<bool, face_count> switch_stuck_on = {};   // the face's panel is shorted whatever the gate
    std::array<bool, face_count> switch_stuck_off = {};  // the face's panel feeds the bus whatever the gate
    std::array<double, face_count> i_sc = {};            // A, each panel's short-circuit current (V = 0)
    std::array<double, face_count> i_shorted = {};       // A, each panel's current when shorted through a switch
    std::array<double, face_count> i_shunt = {};         // A, each face's current through its switch when closed
    std::array<double, axis_count> i_hall = {};          // A, I(+axis) − I(−axis) of i_shunt
};

// derivatives() and outputs() in one pass (the bus-side panel solves shared).
struct Evaluation {
    State derivatives = {};
    Outputs outputs;
};

// The panels' currents into the bus with the shunts open at one bus voltage: the costly part of an
// evaluation (one Newton solve per lit face), a function of the model, the illumination and v_bus
// alone. An integrator asks for the same v_bus more than once (CVODE's difference-quotient Jacobian
// perturbs soc with v_bus unchanged; a restart evaluates its starting point for the root functions
// and again for the first step), so a caller may keep the last two solves here: evaluate() looks
// them up and stores what it solves. A hit returns the very values the solve would (the solve is
// pure), so results stay bit-identical. The caller empties it whenever the model or illumination
// changes.
struct BusSideMemo {
    struct Entry {
        bool valid = false;
        double v_bus = 0.0;
        std::array<double, face_count> current = {};
    };
    std::array<Entry, 2> entries = {};  // two: the Jacobian's v_bus column sits between base and soc column
    std::size_t next = 0;               // the entry the next solve replaces
    void clear() { *this = BusSideMemo{}; }
};

static_assert(std::is_trivially_copyable_v<Illumination> && std::is_trivially_copyable_v<Evaluation>);

// Validates the parameters and fits the panel circuit. Throws ParameterError with a clear message.
Model make_model(const Parameters& p);

// Throws std::invalid_argument for non-finite inputs, negative irradiance or albedo.
void check_inputs(const Inputs& u);

// Effective irradiance on each face: irradiance · f(β) + albedo (W/m²).
std::array<double, face_count> face_irradiance(const Model& m, const Inputs& u);

DiscreteState initialize(const Model& m, const Inputs& u, double t0, const State& x0);
State derivatives(const Model& m, const Inputs& u, const DiscreteState& d, double t, const State& x);
Outputs outputs(const Model& m, const Inputs& u, const DiscreteState& d, double t, const State& x);
Indicators event_indicators(const Model& m, const Inputs& u, const DiscreteState& d, double t, const State& x);
// PWM edges (switching) and the faults' onsets and ends; no_time_event if none.
double next_time_event(const Model& m, const DiscreteState& d);

// The same through a precomputed illumination (inputs checked by the caller): identical results.
// An illumination depends on the faults in effect and, while a degradation is, on the time.
Illumination illuminate(const Model& m, const Inputs& u, const FaultState& faults, double t);
Illumination illuminate(const Model& m, const Inputs& u);  // no fault in effect
Evaluation evaluate(const Model& m, const Illumination& l, const DiscreteState& d, double t, const State& x);
// The same, reusing and filling a memo of bus-side solves (see BusSideMemo): identical results.
Evaluation evaluate(const Model& m, const Illumination& l, const DiscreteState& d, double t, const State& x,
                    BusSideMemo& memo);

struct EventResult {
    DiscreteState discrete;
    bool changed = false;  // any discrete variable changed (for valuesOfContinuousStatesChanged = false,
                           // newDiscreteStatesNeeded = false: one call settles an event instant)
};
// Performs every discrete change due at t: PWM edges whose time has come (t >= edge − 1e-9 T), the
// controller sample at a period start, the S/H hold when the gate opens, the faults' onsets and ends, and
// the charge switch.
// Idempotent: a second call at the same t with the result changes nothing.
EventResult event_update(const Model& m, const Inputs& u, const DiscreteState& d, double t, const State& x);
EventResult event_update(const Model& m, const Illumination& l, const DiscreteState& d, double t, const State& x);

// The step between events of the switching plant (between_edges.cpp). Between two PWM edges the gate is fixed
// and the bus is C dv/dt = Σ (1 − σ_k) I_k(v) − v/R_L − I_batt(v, soc): linear in v except for the panels'
// diode law (while the shunts are open) and the battery network's kinks. Each step linearizes the right-hand
// side at its start in v and in t, f ≈ f0 + a (v − v0) + b (t − t0) (a from the panels' and the battery's
// exact slopes, b from the photocurrents at both ends: the inputs may move), and takes the exact solution
// of that linear equation, v(τ) = v0 + τ φ1(aτ) f0 + τ² φ2(aτ) b: exact for the linear circuit (gate on,
// panels dark). The slope at the step's end, f(t1, v1), measures what the linearization left out (it grows
// as (τ/h)²); its integral, 2 h φ3(ah) (f(t1, v1) − (f0 + a Δv + b h)), is added to v1 (third order) and its
// size is the error estimate, kept below 0.1 · rtol · max(1 V, |v|) by shorter steps.
// soc follows by the trapezoidal rule (dsoc/dt ≈ 1e-4 /s). Event indicators are watched at each step's end; a
// zero is located on the step's solution (Illinois) and the step ends there. Switching fidelity only
// (averaged: std::nullopt).
struct SpanResult {
    double t = 0.0;  // s, t_stop or the first indicator zero
    State x = {};
    bool state_event = false;
    int steps = 0;  // accepted steps
};
using InputsAt = std::function<Inputs(double)>;  // the inputs at time t (a host may interpolate them)
std::optional<SpanResult> advance_between_edges(const Model& m, const InputsAt& inputs_at, const DiscreteState& d,
                                                double t0, const State& x0, double t_stop, double rtol);

}  // namespace ssr_plant
