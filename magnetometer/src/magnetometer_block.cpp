#include "magnetometer/magnetometer_block.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "fmu/errors.hpp"
#include "fmu/instant_clock.hpp"
#include "fmu/state_check.hpp"

namespace magnetometer {

namespace {

// The injected faults (faults.hpp): physical effects from an onset to an end, both time events.
void declare_faults(fmu::Table<MagnetometerData>& t) {
    using D = MagnetometerData;
    const auto onset = [&](const char* name, double D::*field, const char* what) {
        t.parameter(name, field, "s", std::string("Simulation time at which ") + what + " (a time event)");
    };
    const auto end = [&](const char* name, double D::*field, const char* what) {
        t.parameter(name, field, "s",
                    std::string("Simulation time at which ") + what + " clears (a time event); 0 = never");
    };
    t.parameter("fault_stuck_axis", &D::fault_stuck_axis, "",
                "Axis whose output is stuck (fault_stuck_mode); 0 = no fault, 1 ... 3 = X, Y, Z")
        .range(0, 3);
    t.choice("fault_stuck_mode", &D::fault_stuck_mode,
             {{"last", StuckMode::last}, {"rail_low", StuckMode::rail_low}, {"rail_high", StuckMode::rail_high}},
             "Where the stuck axis stays: last (the voltage it had at the onset: a latched amplifier or ADC "
             "channel), rail_low or rail_high (an open bridge arm drives its amplifier to a supply rail)");
    onset("fault_stuck_onset", &D::fault_stuck_onset, "the axis sticks");
    end("fault_stuck_end", &D::fault_stuck_end, "the stuck axis");
    t.parameter("fault_spike_axis", &D::fault_spike_axis, "",
                "Axis whose output carries interference spikes; 0 = no fault, 1 ... 3 = X, Y, Z")
        .range(0, 3);
    t.parameter("fault_spike_rate", &D::fault_spike_rate, "Hz",
                "Mean rate of the spikes (a Poisson process, at most one per fault_spike_duration)")
        .range(0.0, 1e6);
    t.parameter("fault_spike_size", &D::fault_spike_size, "V",
                "Height of a spike at the output, either sign at random (1 V = 1 gauss = 100 uT at the "
                "datasheet's sensitivity); clamped at the rails")
        .range(-5.0, 5.0);
    t.parameter("fault_spike_duration", &D::fault_spike_duration, "s",
                "Length of a spike (and of the slots the spikes are drawn in, counted from the onset)")
        .min(1e-6);
    t.parameter("fault_spike_seed", &D::fault_spike_seed, "",
                "Seed of the spikes' generator: the same seed gives the same spikes");
    onset("fault_spike_onset", &D::fault_spike_onset, "the spikes start");
    end("fault_spike_end", &D::fault_spike_end, "the spikes");
    t.parameter("fault_bias_jump", &D::fault_bias_jump, "T",
                "A field that appears at the sensor, body axes (a part magnetised nearby): read like the Earth's "
                "field, so it flips with set/reset and is not removed by it; all zero = no fault")
        .range(-1e-3, 1e-3);
    onset("fault_bias_onset", &D::fault_bias_onset, "the bias field appears");
    end("fault_bias_end", &D::fault_bias_end, "the bias field");
    t.parameter("fault_strap_failed", &D::fault_strap_failed, "",
                "The set/reset strap fails (open strap or driver): from the onset the pulses no longer flip the "
                "film, the polarity stays at its value then");
    onset("fault_strap_onset", &D::fault_strap_onset, "the strap fails");
    end("fault_strap_end", &D::fault_strap_end, "the strap failure");
}

}  // namespace

void MagnetometerBlock::declare(fmu::Table<MagnetometerData>& t) {
    using D = MagnetometerData;
    t.input("mag_body", &D::mag_body, "T", "Magnetic flux density at the sensor, body axes");
    t.input("set_reset_command", &D::set_reset_command, "",
            "Last set/reset strap pulse commanded by the on-board computer: true = set, false = reset "
            "(set_reset_source = input; a change is a pulse)");
    t.input("i_string", &D::i_string, "A",
            "Each face's cell current, PWM-period average (ssr_plant i_string; +x, -x, +y, -y, +z, -z): its string "
            "loop");
    t.input("i_shunt", &D::i_shunt, "A",
            "Each face's shunt-switch current, PWM-period average (ssr_plant i_shunt): their sum runs around the "
            "shunt loop");
    t.input("i_batt", &D::i_batt, "A", "Battery current, positive charging (ssr_plant i_batt): the battery loop");
    t.input("i_load", &D::i_load, "A", "Load current (ssr_plant i_load): the load loop");

    t.parameter("sensitivity", &D::sensitivity, "V/T", "Sensitivity at 25 degC (datasheet: 1 V/gauss = 1e4 V/T)")
        .min(1e-3);
    t.parameter("v_null", &D::v_null, "V", "Zero-field output voltage, also the reference pin (datasheet: 2.5 V)")
        .range(0.0, 5.0);
    t.parameter("bridge_offset", &D::bridge_offset, "V",
                "Bridge and amplifier offset referred to the output; unchanged by set/reset pulses (the pulses "
                "flip the field term)")
        .range(-1.0, 1.0);
    t.choice("set_reset_source", &D::set_reset_source,
             {{"input", SetResetSource::input}, {"timer", SetResetSource::timer}, {"none", SetResetSource::none}},
             "Who pulses the set/reset strap: input (set_reset_command, the on-board computer), timer (the "
             "sensor alternates set and reset every set_reset_period by itself) or none (set at power-up only)");
    t.parameter("set_reset_period", &D::set_reset_period, "s",
                "Time between set/reset pulses when set_reset_source = timer")
        .min(1e-4)
        .applies_when("set_reset_source", {"timer"});
    t.parameter("cross_axis", &D::cross_axis, "1",
                "Cross-axis sensitivity: fraction of each transverse field seen by an axis")
        .range(-0.1, 0.1);
    t.parameter("misalignment", &D::misalignment, "rad",
                "Small rotation of the sensor axes relative to the body axes, about x, y, z")
        .range(-0.1, 0.1);
    t.parameter("bandwidth", &D::bandwidth, "Hz", "Sensor bandwidth, a first-order low-pass (datasheet: 1 kHz)")
        .range(1e-3, 1e6);
    t.parameter("noise_rms", &D::noise_rms, "T",
                "RMS output noise, field-equivalent (datasheet resolution 40 ugauss = 4 nT); 0 disables it")
        .range(0.0, 1e-3);
    t.parameter("noise_sample_period", &D::noise_sample_period, "s",
                "Noise is a new Gaussian sample every period, held in between (band-limits it); the samples are "
                "counted from the start time, not scheduled as time events")
        .min(1e-5);
    t.parameter("noise_seed", &D::noise_seed, "", "Seed of the noise generator: the same seed gives the same run");
    t.parameter("temperature", &D::temperature, "degC", "Sensor temperature").range(-55.0, 125.0).tunable();
    t.parameter("sensitivity_tempco", &D::sensitivity_tempco, "1/K",
                "Relative change of sensitivity per kelvin (datasheet: -600 ppm/degC)")
        .range(-0.01, 0.01);
    t.parameter("v_rail_low", &D::v_rail_low, "V", "Lower saturation rail of the outputs");
    t.parameter("v_rail_high", &D::v_rail_high, "V", "Upper saturation rail of the outputs (5 V supply)");
    // The spacecraft's own field (spacecraft_field.hpp). Defaults: an assumed 3U layout (README).
    t.parameter("read_spacecraft_field", &D::read_spacecraft_field, "",
                "The sensor reads the spacecraft's own field (mag_spacecraft) on top of mag_body; false: a sensor "
                "calibrated against it (mag_spacecraft is still computed and output)");
    t.parameter("sensor_position", &D::sensor_position, "m", "Position of the sensor, body axes (from the box centre)");
    t.parameter("dipole_moment", &D::dipole_moment, "A.m2", "Residual magnetic dipole of the spacecraft, body axes")
        .range(-100.0, 100.0);
    t.parameter("dipole_position", &D::dipole_position, "m", "Position of the residual dipole, body axes");
    t.parameter("string_loop_center", &D::string_loop_center, "m",
                "Centre of each face's cell-string loop, 3 elements per face (+x, -x, +y, -y, +z, -z)");
    t.parameter("string_loop_side_a", &D::string_loop_side_a, "m",
                "First side of each face's string loop, 3 elements per face: the current runs along side_a, then "
                "side_b; side_a x side_b is the loop's normal times its area (zero sides: no loop)");
    t.parameter("string_loop_side_b", &D::string_loop_side_b, "m",
                "Second side of each face's string loop, 3 elements per face");
    t.parameter("shunt_loop_center", &D::shunt_loop_center, "m",
                "Centre of the shunt switches' current loop (carries the sum of i_shunt)");
    t.parameter("shunt_loop_side_a", &D::shunt_loop_side_a, "m", "First side of the shunt loop");
    t.parameter("shunt_loop_side_b", &D::shunt_loop_side_b, "m", "Second side of the shunt loop");
    t.parameter("battery_loop_center", &D::battery_loop_center, "m",
                "Centre of the battery's current loop (carries i_batt)");
    t.parameter("battery_loop_side_a", &D::battery_loop_side_a, "m", "First side of the battery loop");
    t.parameter("battery_loop_side_b", &D::battery_loop_side_b, "m", "Second side of the battery loop");
    t.parameter("load_loop_center", &D::load_loop_center, "m", "Centre of the load's current loop (carries i_load)");
    t.parameter("load_loop_side_a", &D::load_loop_side_a, "m", "First side of the load loop");
    t.parameter("load_loop_side_b", &D::load_loop_side_b, "m", "Second side of the load loop");

    declare_faults(t);

    t.state("b_filt", &D::b_filt, &D::der_b_filt, "T", "Field after the sensor's bandwidth filter, sensor axes")
        .nominal(1e-4)
        .calculated_start()
        .derivative_depends_elementwise({"b_filt"})
        .derivative_depends_on({"mag_body"});

    t.output("v_out", &D::v_out, "V", "Output voltages X, Y, Z (0-5 V, v_ref at zero field)")
        .depends_elementwise({"b_filt"})
        .depends_on({"set_reset_command", "i_string", "i_shunt", "i_batt", "i_load"});
    t.output("mag_spacecraft", &D::mag_spacecraft, "T",
             "The spacecraft's own field at the sensor, body axes: residual dipole and the plant's currents (read "
             "by the sensor on top of mag_body)")
        .depends_on({"i_string", "i_shunt", "i_batt", "i_load"});
    t.output("v_ref", &D::v_ref, "V", "Zero-field reference voltage (+2.5 V pin)").depends_on({});
    t.output("set_polarity", &D::set_polarity, "", "True after a set pulse, false after a reset pulse")
        .depends_on({"set_reset_command"});
}

fmu::ModelInfo MagnetometerBlock::describe() {
    fmu::ModelInfo info;
    info.model_identifier = "magnetometer";
    info.model_name = "magnetometer";
    info.description = "Honeywell HMC2003 three-axis magnetoresistive magnetometer and its output circuit";
    info.documentation_html =
        "<p>The HMC2003 hybrid of seed paper 000 section 5 (fig. 10): three magnetoresistive bridges with "
        "amplifiers giving 0-5 V outputs, 1 V/gauss, +2.5 V at zero field, and a +2.5 V reference pin for the "
        "ADC. Signal chain per axis: the body-frame field is mixed by the cross-axis and misalignment matrix "
        "M = C&middot;(I &minus; [&theta;&times;]), filtered by the sensor bandwidth (first order, continuous "
        "states <code>b_filt</code>), scaled by the temperature-dependent sensitivity "
        "S(T) = S<sub>0</sub>(1 + k<sub>T</sub>(T &minus; 25 &deg;C)) with the sign of the last set/reset pulse "
        "(a pulse re-magnetises the permalloy and reverses the field term; the bridge offset stays, so half the "
        "difference of a set and a reset reading is the field without it), shifted by the offset. The pulses "
        "come from the on-board computer through <code>set_reset_command</code> "
        "(<code>set_reset_source</code> = input, the default), from the sensor's own timer (time events every "
        "<code>set_reset_period</code>), or not at all (none), plus seeded Gaussian noise held for "
        "<code>noise_sample_period</code> (a counter-based generator keyed by the seed, the hold interval "
        "and the axis, so the noise needs no time events and an FMU state reproduces it), and clamped to the rails.</p>"
        "<p>The sensor reads the spacecraft's own field on top of <code>mag_body</code>: a residual dipole "
        "(<code>dipole_moment</code> at <code>dipole_position</code>, the exact point-dipole field) and the "
        "currents of the power system, each run around a rectangular loop of straight wires (Biot-Savart, closed "
        "form per segment): each face's cell string (<code>i_string</code>), the shunt "
        "switches' path (the sum of <code>i_shunt</code>), the battery (<code>i_batt</code>) and the load "
        "(<code>i_load</code>). Positions in metres, body axes, from the box centre; the defaults are an assumed "
        "3U layout with no dipole. The currents are PWM-period averages, and their field joins after the bandwidth "
        "filter (it changes on the plant's time scale). <code>mag_spacecraft</code> shows that field at the "
        "sensor; <code>read_spacecraft_field</code> = false leaves it out of the reading.</p>"
        "<p>Defaults are the datasheet's typical values; <code>bridge_offset</code>, <code>cross_axis</code> and "
        "<code>set_reset_period</code> are assumptions to be replaced by a calibration of the flight unit. "
        "Linearity error, hysteresis and the set/reset pulse's own transient are not modelled.</p>"
        "<p>Faults (parameters <code>fault_...</code>, each from its onset to its end, both time events): an axis "
        "stuck at its last value or at a rail, seeded interference spikes on an axis' output, a bias field "
        "appearing at the sensor, a failed set/reset strap (no flip). See the block's README.</p>";
    info.default_experiment = {.start_time = 0.0, .stop_time = 5.0, .tolerance = 1e-6, .step_size = 1e-3};
    return info;
}

void MagnetometerBlock::configure() {
    const auto& d = data();
    SpacecraftLayout l;
    l.sensor_position = d.sensor_position;
    l.dipole_moment = d.dipole_moment;
    l.dipole_position = d.dipole_position;
    for (std::size_t k = 0; k < face_count; ++k) {
        for (std::size_t i = 0; i < 3; ++i) {
            l.string_loop[k].center[i] = d.string_loop_center[3 * k + i];
            l.string_loop[k].side_a[i] = d.string_loop_side_a[3 * k + i];
            l.string_loop[k].side_b[i] = d.string_loop_side_b[3 * k + i];
        }
    }
    l.shunt_loop = {d.shunt_loop_center, d.shunt_loop_side_a, d.shunt_loop_side_b};
    l.battery_loop = {d.battery_loop_center, d.battery_loop_side_a, d.battery_loop_side_b};
    l.load_loop = {d.load_loop_center, d.load_loop_side_a, d.load_loop_side_b};
    spacecraft_.reset();
    try {
        spacecraft_.emplace(l);
    } catch (const std::invalid_argument& e) {
        throw fmu::Error(std::string("magnetometer: ") + e.what());
    }
}

Vec3 MagnetometerBlock::spacecraft_field() {
    auto& d = data();
    if (!spacecraft_) throw fmu::Error("magnetometer: used before configure()");  // the runtime configures first
    d.mag_spacecraft =
        spacecraft_->at_sensor({.string = d.i_string, .shunt = d.i_shunt, .battery = d.i_batt, .load = d.i_load});
    return d.mag_spacecraft;
}

void MagnetometerBlock::validate() const {
    const auto& d = data();
    if (!(d.v_rail_low < d.v_rail_high)) throw fmu::Error("v_rail_low must be below v_rail_high");
    if (d.v_null < d.v_rail_low || d.v_null > d.v_rail_high) throw fmu::Error("v_null must lie between the rails");
    try {
        check_faults(faults());
    } catch (const std::invalid_argument& e) {
        throw fmu::Error(e.what());
    }
}

FaultParameters MagnetometerBlock::faults() const {
    const auto& d = data();
    FaultParameters f;
    f.stuck_axis = d.fault_stuck_axis;
    f.stuck_mode = d.fault_stuck_mode;
    f.stuck = {d.fault_stuck_onset, d.fault_stuck_end};
    f.spike_axis = d.fault_spike_axis;
    f.spike_rate = d.fault_spike_rate;
    f.spike_size = d.fault_spike_size;
    f.spike_duration = d.fault_spike_duration;
    f.spike_seed = d.fault_spike_seed;
    f.spikes = {d.fault_spike_onset, d.fault_spike_end};
    f.bias_jump = d.fault_bias_jump;
    f.bias = {d.fault_bias_onset, d.fault_bias_end};
    f.strap_failed = d.fault_strap_failed;
    f.strap = {d.fault_strap_onset, d.fault_strap_end};
    return f;
}

// Slots of fault_spike_duration counted from the onset, like the noise's hold intervals: no time events.
double MagnetometerBlock::spike_voltage(double t) const {
    const auto& d = data();
    if (d.fault_phase[fault_spikes] != fault_active) return 0.0;
    return spike_in_slot(faults(), noise_index(t, d.fault_spike_onset, d.fault_spike_duration, "fault_spike_onset",
                                               "fault_spike_duration"));
}

void MagnetometerBlock::apply_stuck_axis() {
    auto& d = data();
    if (d.fault_phase[fault_stuck] != fault_active) return;
    const double stuck = d.fault_stuck_mode == StuckMode::last       ? d.fault_stuck_value
                         : d.fault_stuck_mode == StuckMode::rail_low ? d.v_rail_low
                                                                     : d.v_rail_high;
    d.v_out[static_cast<std::size_t>(d.fault_stuck_axis - 1)] = stuck;
}

// The fields outside the table of a state restored from bytes (issue 14 case 8).
void MagnetometerBlock::check_state() const {
    const auto& d = data();
    fmu::require_bool(d.set_polarity, "set_polarity");
    for (const double n : d.noise) fmu::require_finite(n, "noise");
    if (std::isnan(d.next_set_reset) || !std::isfinite(d.noise_start))
        throw fmu::Error("restored FMU state: an event time is NaN");
    if (d.noise_index < 0 && d.noise_index != no_noise_index)
        throw fmu::Error("restored FMU state: the noise hold interval is negative");
    for (const std::int32_t phase : d.fault_phase)
        fmu::require_range(phase, fault_pending, fault_cleared, "fault_phase");
    fmu::require_finite(d.fault_stuck_value, "fault_stuck_value");
    // An active stuck axis indexes the outputs by fault_stuck_axis: bytes saying it is active with no
    // axis (0) or one out of 1 ... 3 are no state this block could have reached (found by fuzz_state).
    if (d.fault_phase[fault_stuck] == fault_active && (d.fault_stuck_axis < 1 || d.fault_stuck_axis > 3))
        throw fmu::Error("restored FMU state: a stuck axis is active with fault_stuck_axis " +
                         std::to_string(d.fault_stuck_axis) + " (not 1 ... 3)");
}

// The noise enters the outputs only (after the filter), never a derivative: a new sample is a jump of
// v_out alone, which needs no event, so the hold intervals are counted from the time, not scheduled.
void MagnetometerBlock::update_noise(double t) {
    auto& d = data();
    if (!(d.noise_rms > 0.0)) {
        d.noise = {};
        return;
    }
    const std::int64_t k = noise_index(t, d.noise_start, d.noise_sample_period, "the noise's start time");
    if (k == d.noise_index) return;
    const auto seed = static_cast<std::uint64_t>(static_cast<std::uint32_t>(d.noise_seed));
    for (int axis = 0; axis < 3; ++axis) d.noise[axis] = d.noise_rms * held_normal(seed, k, axis);
    d.noise_index = k;
}

void MagnetometerBlock::initialize(double t) {
    auto& d = data();
    // The sensor has been powered long before the simulation starts: its filter is in steady state.
    d.b_filt = multiply(sensor_matrix(d.cross_axis, d.misalignment), d.mag_body);
    d.set_polarity = true;  // the first pulse at power-up is a set pulse
    d.next_set_reset = d.set_reset_source == SetResetSource::timer ? t + d.set_reset_period : fmu::no_time_event;
    d.noise_start = t;
    d.noise_index = no_noise_index;  // interval 0 is drawn by the first evaluate
    // Faults whose onset is at or before the start. An axis stuck at its last value from the start reads
    // what the sensor reads then with the other faults.
    const FaultParameters f = faults();
    FaultPhases phases{};
    advance_faults(f, phases, t);
    d.fault_phase = phases;
    d.fault_stuck_value = 0.0;
    if (phases[fault_stuck] == fault_active && f.stuck_mode == StuckMode::last) {
        d.fault_phase[fault_stuck] = fault_pending;
        evaluate(t);
        d.fault_stuck_value = d.v_out[static_cast<std::size_t>(d.fault_stuck_axis - 1)];
        d.fault_phase = phases;
    }
}

void MagnetometerBlock::evaluate(double t) {
    auto& d = data();
    update_noise(t);
    const Mat3 m = sensor_matrix(d.cross_axis, d.misalignment);
    d.der_b_filt = filter_derivative(multiply(m, d.mag_body), d.b_filt, d.bandwidth);
    // The spacecraft's own field joins after the bandwidth filter, as the noise does: the plant's currents
    // reach the sensor as a Co-Simulation component's steps (1 ms in the seed systems), and through the
    // filter every step would be an input discontinuity, an integrator restart (README: what it costs).
    const Vec3 field_of_spacecraft = spacecraft_field();
    const Vec3 own = d.read_spacecraft_field ? multiply(m, field_of_spacecraft) : Vec3{};
    const OutputStage stage{.sensitivity = sensitivity_at(d.sensitivity, d.sensitivity_tempco, d.temperature),
                            .v_null = d.v_null,
                            .offset = d.bridge_offset,
                            .v_low = d.v_rail_low,
                            .v_high = d.v_rail_high};
    // A failed strap no longer flips the film: the polarity stays what it was at the failure.
    const bool strap_works = d.fault_phase[fault_strap] != fault_active;
    if (d.set_reset_source == SetResetSource::input && strap_works) d.set_polarity = d.set_reset_command;
    const double polarity = d.set_polarity ? 1.0 : -1.0;
    if (d.fault_phase == FaultPhases{}) {
        for (int i = 0; i < 3; ++i) d.v_out[i] = output_voltage(stage, d.b_filt[i] + own[i], d.noise[i], polarity);
    } else {
        // A bias field is a field at the sensor (through M, flipped by set/reset); a spike is a voltage at
        // the amplifier's output (not flipped, clamped at the rails); a stuck axis overrides its output.
        const Vec3 bias = d.fault_phase[fault_bias] == fault_active ? multiply(m, d.fault_bias_jump) : Vec3{};
        const double spike = spike_voltage(t);
        for (std::size_t i = 0; i < 3; ++i) {
            OutputStage axis_stage = stage;
            if (static_cast<std::int32_t>(i) + 1 == d.fault_spike_axis) axis_stage.offset += spike;
            d.v_out[i] = output_voltage(axis_stage, d.b_filt[i] + own[i] + bias[i], d.noise[i], polarity);
        }
        apply_stuck_axis();
    }
    d.v_ref = std::clamp(d.v_null, d.v_rail_low, d.v_rail_high);
}

fmu::EventUpdate MagnetometerBlock::event_update(double t, bool time_event_due) {
    auto& d = data();
    if (!time_event_due) return {};
    // Fault onsets and ends. The outputs were evaluated for the instant before the update (the runtime's
    // contract): an axis sticking at its last value keeps that reading.
    const std::uint32_t started = advance_faults(faults(), d.fault_phase, t);
    if ((started & (1u << fault_stuck)) != 0u)
        d.fault_stuck_value = d.v_out[static_cast<std::size_t>(d.fault_stuck_axis - 1)];
    const bool strap_works = d.fault_phase[fault_strap] != fault_active;
    // A host that stepped over instants gets them counted at once (and a time too far for the count
    // refused), not one per call: next_instant_index is the number of instants reached.
    if (fmu::reached(t, d.next_set_reset)) {
        const auto pulses = fmu::next_instant_index(t, d.next_set_reset, d.set_reset_period, 1, "set/reset pulses");
        // pulses alternate set, reset, set, ... (a failed strap's pulses flip nothing)
        if (pulses % 2 == 1 && strap_works) d.set_polarity = !d.set_polarity;
        d.next_set_reset += static_cast<double>(pulses) * d.set_reset_period;
    }
    return {};
}

double MagnetometerBlock::next_time_event() const {
    return std::min(data().next_set_reset, next_fault_event(faults(), data().fault_phase));
}

}  // namespace magnetometer

FMU_BLOCK(magnetometer::MagnetometerBlock)
