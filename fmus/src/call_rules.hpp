// The FMI 2.0 call-sequence rules (standard sections 3.2.3 and 4.2.4) as one table: for each entry
// point, the modes in which a host may call it. Checked at the top of every entry point.
#pragma once

#include <cstdint>
#include <string_view>

namespace fmu {

enum class Mode : std::uint32_t {
    instantiated = 1u << 0,
    initialization = 1u << 1,
    event = 1u << 2,            // Model Exchange
    continuous_time = 1u << 3,  // Model Exchange
    step_complete = 1u << 4,    // Co-Simulation
    step_failed = 1u << 5,
    step_canceled = 1u << 6,
    terminated = 1u << 7,
    error = 1u << 8,
    fatal = 1u << 9,
};

std::string_view to_string(Mode m);

enum class Call {
    set_debug_logging,
    setup_experiment,
    enter_initialization_mode,
    exit_initialization_mode,
    terminate,
    reset,
    get_values,
    set_values,
    get_fmu_state,
    set_fmu_state,
    free_fmu_state,
    serialize_fmu_state,
    directional_derivative,
    enter_event_mode,
    new_discrete_states,
    enter_continuous_time_mode,
    completed_integrator_step,
    set_time,
    set_continuous_states,
    get_derivatives,
    get_event_indicators,
    get_continuous_states,
    get_nominals,
    set_input_derivatives,
    get_output_derivatives,
    do_step,
    cancel_step,
    get_status,
};

std::string_view to_string(Call c);

constexpr std::uint32_t operator|(Mode a, Mode b) {
    return static_cast<std::uint32_t>(a) | static_cast<std::uint32_t>(b);
}
constexpr std::uint32_t operator|(std::uint32_t a, Mode b) {
    return a | static_cast<std::uint32_t>(b);
}

// Bit mask of the modes in which `call` is allowed.
std::uint32_t allowed_modes(Call call);

}  // namespace fmu
