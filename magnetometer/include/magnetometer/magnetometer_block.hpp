// The magnetometer as an FMU block: its variable table (the one source of the model description,
// the FMI getters/setters and the table-driven tests) and the event logic around the HMC2003 model.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <optional>

#include "fmu/block.hpp"
#include "fmu/fixed_string.hpp"
#include "magnetometer/faults.hpp"
#include "magnetometer/held_noise.hpp"
#include "magnetometer/hmc2003.hpp"
#include "magnetometer/spacecraft_field.hpp"

namespace magnetometer {

// Marks `noise` as not yet drawn; noise_index() never returns it (its range is ±max_noise_index).
inline constexpr std::int64_t no_noise_index = std::numeric_limits<std::int64_t>::min();

inline constexpr SpacecraftLayout layout_defaults = default_layout();

// One 3-vector of each face's string loop, face after face (+x, −x, +y, −y, +z, −z): the flat parameter
// arrays string_loop_center, string_loop_side_a and string_loop_side_b.
constexpr std::array<double, 3 * face_count> flat_strings(Vec3 CurrentLoop::*member) {
    std::array<double, 3 * face_count> out{};
    for (std::size_t k = 0; k < face_count; ++k)
        for (std::size_t i = 0; i < 3; ++i) out[3 * k + i] = (layout_defaults.string_loop[k].*member)[i];
    return out;
}

// Every variable of the block. Defaults are the HMC2003 datasheet's typical values where it gives
// one (Honeywell, "HMC2003 Three-axis magnetic sensor hybrid"); the others are marked as assumptions.
// Who pulses the set/reset strap (the `set_reset_source` choice).
enum class SetResetSource : std::int32_t { input = 1, timer = 2, none = 3 };

struct MagnetometerData {
    // inputs
    Vec3 mag_body{};                // T
    bool set_reset_command = true;  // the strap driver's last pulse (true: set, false: reset), source "input"
    // the plant's currents (ssr_plant's outputs of the same names), A: the spacecraft's own field
    std::array<double, face_count> i_string{};
    std::array<double, face_count> i_shunt{};
    double i_batt = 0.0;
    double i_load = 0.0;
    // parameters
    double sensitivity = 1.0 / tesla_per_gauss;  // V/T: datasheet 1 V/gauss
    double v_null = 2.5;                         // V: zero-field output and the reference pin
    double bridge_offset = 0.02;                 // V: assumed; the datasheet's null spread is 2.3–2.7 V
    // Who pulses the set/reset strap: input (the on-board computer, through set_reset_command, as in
    // flight: seed 000 fig. 10 drives the strap from MOSFETs), timer (the sensor alternates set and
    // reset by itself every set_reset_period: a stand-alone run) or none (set once at power-up).
    SetResetSource set_reset_source = SetResetSource::input;
    double set_reset_period = 1.0;               // s: source "timer" only; assumed, the seed says "occasionally"
    double cross_axis = 0.003;                   // 1: assumed 0.3 % cross-field pick-up
    Vec3 misalignment{};                         // rad
    double bandwidth = 1000.0;                   // Hz: datasheet 1 kHz
    double noise_rms = 40e-6 * tesla_per_gauss;  // T: datasheet resolution 40 µgauss
    double noise_sample_period = 0.01;           // s: noise held for this long (band-limits it to 50 Hz)
    std::int32_t noise_seed = 1;
    double temperature = 25.0;            // degC
    double sensitivity_tempco = -600e-6;  // 1/K: datasheet −600 ppm/°C
    double v_rail_low = 0.0;              // V
    double v_rail_high = 5.0;             // V
    // the spacecraft's own field (spacecraft_field.hpp): body axes, metres, A·m²; an assumed 3U layout
    bool read_spacecraft_field = true;  // false: mag_spacecraft is computed and shown, not read
    Vec3 sensor_position = layout_defaults.sensor_position;
    Vec3 dipole_moment = layout_defaults.dipole_moment;
    Vec3 dipole_position = layout_defaults.dipole_position;
    std::array<double, 3 * face_count> string_loop_center = flat_strings(&CurrentLoop::center);
    std::array<double, 3 * face_count> string_loop_side_a = flat_strings(&CurrentLoop::side_a);
    std::array<double, 3 * face_count> string_loop_side_b = flat_strings(&CurrentLoop::side_b);
    Vec3 shunt_loop_center = layout_defaults.shunt_loop.center;
    Vec3 shunt_loop_side_a = layout_defaults.shunt_loop.side_a;
    Vec3 shunt_loop_side_b = layout_defaults.shunt_loop.side_b;
    Vec3 battery_loop_center = layout_defaults.battery_loop.center;
    Vec3 battery_loop_side_a = layout_defaults.battery_loop.side_a;
    Vec3 battery_loop_side_b = layout_defaults.battery_loop.side_b;
    Vec3 load_loop_center = layout_defaults.load_loop.center;
    Vec3 load_loop_side_a = layout_defaults.load_loop.side_a;
    Vec3 load_loop_side_b = layout_defaults.load_loop.side_b;
    // injected faults (faults.hpp); the defaults inject none
    std::int32_t fault_stuck_axis = FaultParameters{}.stuck_axis;
    StuckMode fault_stuck_mode = FaultParameters{}.stuck_mode;
    double fault_stuck_onset = 0.0;
    double fault_stuck_end = 0.0;
    std::int32_t fault_spike_axis = FaultParameters{}.spike_axis;
    double fault_spike_rate = FaultParameters{}.spike_rate;
    double fault_spike_size = FaultParameters{}.spike_size;
    double fault_spike_duration = FaultParameters{}.spike_duration;
    std::int32_t fault_spike_seed = FaultParameters{}.spike_seed;
    double fault_spike_onset = 0.0;
    double fault_spike_end = 0.0;
    Vec3 fault_bias_jump = FaultParameters{}.bias_jump;
    double fault_bias_onset = 0.0;
    double fault_bias_end = 0.0;
    bool fault_strap_failed = FaultParameters{}.strap_failed;
    double fault_strap_onset = 0.0;
    double fault_strap_end = 0.0;
    // continuous states and derivatives
    Vec3 b_filt{};
    Vec3 der_b_filt{};
    // outputs
    Vec3 v_out{};
    Vec3 mag_spacecraft{};  // T, body axes: the dipole's and the currents' field at the sensor
    double v_ref = 2.5;
    bool set_polarity = true;  // true after a set pulse, false after a reset pulse
    // discrete state (locals)
    double next_set_reset = 0.0;
    double noise_start = 0.0;                   // s: start of hold interval 0 (the initialization time)
    std::int64_t noise_index = no_noise_index;  // hold interval whose samples `noise` holds (a cache)
    Vec3 noise{};                               // T
    FaultPhases fault_phase{};                  // pending, active or cleared, per fault (faults.hpp)
    double fault_stuck_value = 0.0;             // V, what the stuck axis reads (mode last: captured at the onset)
};

class MagnetometerBlock : public fmu::Block<MagnetometerBlock, MagnetometerData> {
public:
    static void declare(fmu::Table<MagnetometerData>& t);
    static fmu::ModelInfo describe();

    void initialize(double t) override;
    void evaluate(double t) override;
    fmu::EventUpdate event_update(double t, bool time_event_due) override;
    double next_time_event() const override;
    void validate() const override;
    void check_state() const override;
    // Builds the spacecraft's field per ampere at the sensor from the layout parameters.
    void configure() override;

private:
    void update_noise(double t);
    FaultParameters faults() const;
    // The faults' part of the output: the spike on its axis (V, 0 outside a pulse), the stuck axis.
    double spike_voltage(double t) const;
    void apply_stuck_axis();
    // The spacecraft's own field at the sensor, body axes (sets mag_spacecraft).
    Vec3 spacecraft_field();

    std::optional<SpacecraftField> spacecraft_;  // derived from the parameters by configure()
};

}  // namespace magnetometer
