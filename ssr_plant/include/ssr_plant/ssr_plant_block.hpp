// The power system as an FMU block: the variable table over the plant core (core/), and the
// mapping of the core's event-driven protocol onto the runtime's equations.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "fmu/block.hpp"
#include "fmu/fixed_string.hpp"
#include "ssr_plant/plant.hpp"

namespace ssr_plant {

// Every variable of the block; defaults are the core's (parameters.hpp says which are the seed's and
// which are assumed), except angular_response: the FMU defaults to the measured Kelly cosine of a real
// panel (seed 000 fig. 4); the seed-scenario systems select "cosine", the law eq. 5 assumes.
struct SsrPlantData {
    // inputs
    std::array<double, 3> sun_body{0.0, 0.0, 1.0};
    double irradiance = 1367.0;
    std::array<double, 6> albedo_face{};
    // parameters: selections
    fmu::FixedString<15> fidelity = "switching";
    fmu::FixedString<15> angular_response = "kelly";
    fmu::FixedString<15> modulation = "latched_natural";
    // panel datasheet
    double rated_irradiance = 1000.0;
    double panel_isc = 0.62;
    double panel_voc = 21.5;
    double panel_imp = 0.5714;
    double panel_vmp = 17.5;
    std::int32_t cells_in_series = 36;
    double panel_shunt_resistance = 2000.0;
    double cell_temperature = 298.15;
    // regulator and bus
    double or_diode_forward_voltage = 0.6;
    double or_diode_resistance = 0.05;
    double shunt_switch_resistance = 0.05;
    double pwm_frequency = 5000.0;
    double bus_capacitance = 1500e-6;
    double load_resistance = 90.0;
    double bus_voltage_reference = 15.0;
    double controller_gain = 300.0;
    // battery
    double battery_capacity = 7200.0;
    std::array<double, 11> battery_ocv{11.30, 11.51, 11.66, 11.81, 11.96, 12.10, 12.24, 12.37, 12.50, 12.62, 12.73};
    double battery_internal_resistance = 0.05;
    double charge_path_resistance = 5.0;
    double battery_diode_forward_voltage = 0.6;
    double battery_diode_resistance = 0.05;
    double soc_connect = 0.80;
    double soc_disconnect = 1.00;
    // continuous states and derivatives
    double v_cap = 15.0;
    double soc_state = 0.9;
    double der_v_cap = 0.0;
    double der_soc_state = 0.0;
    // outputs
    std::array<double, 3> i_sh{};
    std::array<double, 6> i_face_sh{};
    std::array<double, 6> i_sc{};
    std::array<double, 6> i_panel{};
    double v_bus = 15.0;
    double v_batt = 0.0;
    double i_batt = 0.0;
    double soc = 0.9;
    double duty = 0.0;
    bool gate = false;
    std::int32_t pwm_period = 0;
    double i_load = 0.0;
    // discrete state of the core (PWM period, S/H, charge switch)
    DiscreteState discrete{};
};

// The parameter fields of SsrPlantData are contiguous, from `fidelity` up to (not including) `v_cap`:
// the fitted model is keyed on these bytes (a test checks that every declared parameter lies inside).
// Equal bytes are equal values; unequal bytes (padding, a string's tail) only cost a refit.
inline constexpr std::size_t parameter_bytes_begin = offsetof(SsrPlantData, fidelity);
inline constexpr std::size_t parameter_bytes_end = offsetof(SsrPlantData, v_cap);

class SsrPlantBlock : public fmu::Block<SsrPlantBlock, SsrPlantData> {
public:
    static void declare(fmu::Table<SsrPlantData>& t);
    static fmu::ModelInfo describe();

    void initialize(double t) override;
    void evaluate(double t) override;
    // The bus balance alone (no Hall or short-circuit solves): what a solver needs between outputs.
    void evaluate_derivatives(double t) override;
    std::size_t event_indicator_count() const override { return indicator_count; }
    void event_indicators(double t, std::span<double> z) override;
    fmu::EventUpdate event_update(double t, bool time_event_due) override;
    double next_time_event() const override;
    void validate() const override;
    void check_state() const override;

private:
    // The fitted plant (panel fit ~0.2 ms) kept outside Data and rebuilt whenever the parameters
    // it was made from differ from the current ones (reset, FMU-state restore, tunable change).
    // const: a cache, refreshed from any call (next_time_event() too, after an FMU-state restore).
    const ssr_plant::Model& plant() const;
    // What the current inputs fix (panel photocurrents, short-circuit and Hall currents), checked and
    // recomputed only when the inputs or the model changed: inputs are constant over a step.
    const Illumination& illumination(const ssr_plant::Model& m) const;
    Inputs inputs() const;
    State state() const;
    bool gate_output() const;
    std::int32_t pwm_period_output() const;
    Parameters parameters() const;

    mutable std::optional<ssr_plant::Model> model_;
    mutable std::array<std::byte, parameter_bytes_end - parameter_bytes_begin> model_key_{};  // its parameter bytes
    mutable std::optional<Illumination> illumination_;
    mutable Inputs illumination_inputs_{};
    // The last bus-side panel solves (see BusSideMemo), emptied with every new illumination (and so
    // with every refit, which drops the illumination).
    mutable BusSideMemo bus_side_memo_;
};

}  // namespace ssr_plant
