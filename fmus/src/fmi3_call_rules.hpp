// The FMI 3.0 call-sequence rules (standard sections 3.2 and 4.2, the state machines of Model
// Exchange and Co-Simulation) as one table: for each entry point, the states in which a host may call
// it. Checked at the top of every fmi3 entry point, as call_rules.hpp does for FMI 2.0.
#pragma once

#include <cstdint>
#include <string_view>

namespace fmu::fmi3 {

enum class Mode : std::uint32_t {
    instantiated = 1u << 0,
    configuration = 1u << 1,  // never entered: these FMUs have no structural parameters
    initialization = 1u << 2,
    event = 1u << 3,            // Model Exchange, and Co-Simulation with eventModeUsed
    continuous_time = 1u << 4,  // Model Exchange
    step = 1u << 5,             // Co-Simulation
    reconfiguration = 1u << 6,  // never entered, as configuration
    terminated = 1u << 7,
    error = 1u << 8,
    fatal = 1u << 9,
    // Co-Simulation, inside fmi3DoStep while the intermediate-update callback runs (standard section
    // 4.2.4): only the get/set of variables with intermediateUpdate="true" the callback's flags allow,
    // which none of these FMUs has, so every call is refused there (fmi3DoStep and fmi3EnterEventMode
    // above all: a step inside a step).
    intermediate_update = 1u << 10,
};

std::string_view to_string(Mode m);

enum class Call {
    set_debug_logging,
    enter_initialization_mode,
    exit_initialization_mode,
    enter_event_mode,
    terminate,
    reset,
    get_values,
    set_values,
    get_dependencies,
    get_fmu_state,
    set_fmu_state,
    free_fmu_state,
    serialize_fmu_state,
    partial_derivative,
    enter_configuration_mode,
    exit_configuration_mode,
    clocks,
    evaluate_discrete_states,
    update_discrete_states,
    enter_continuous_time_mode,
    completed_integrator_step,
    set_time,
    set_continuous_states,
    get_derivatives,
    get_event_indicators,
    get_continuous_states,
    get_nominals,
    get_counts,
    enter_step_mode,
    get_output_derivatives,
    do_step,
    activate_model_partition,
};

std::string_view to_string(Call c);

// Bit mask of the modes in which `call` is allowed.
std::uint32_t allowed_modes(Call call);

}  // namespace fmu::fmi3
