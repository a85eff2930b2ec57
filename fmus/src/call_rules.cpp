#include "call_rules.hpp"

namespace fmu {

std::string_view to_string(Mode m) {
    switch (m) {
        case Mode::instantiated:
            return "Instantiated";
        case Mode::initialization:
            return "InitializationMode";
        case Mode::event:
            return "EventMode";
        case Mode::continuous_time:
            return "ContinuousTimeMode";
        case Mode::step_complete:
            return "StepComplete";
        case Mode::step_failed:
            return "StepFailed";
        case Mode::step_canceled:
            return "StepCanceled";
        case Mode::terminated:
            return "Terminated";
        case Mode::error:
            return "Error";
        case Mode::fatal:
            return "Fatal";
    }
    return "?";
}

std::string_view to_string(Call c) {
    switch (c) {
        case Call::set_debug_logging:
            return "fmi2SetDebugLogging";
        case Call::setup_experiment:
            return "fmi2SetupExperiment";
        case Call::enter_initialization_mode:
            return "fmi2EnterInitializationMode";
        case Call::exit_initialization_mode:
            return "fmi2ExitInitializationMode";
        case Call::terminate:
            return "fmi2Terminate";
        case Call::reset:
            return "fmi2Reset";
        case Call::get_values:
            return "fmi2Get{Real,Integer,Boolean,String}";
        case Call::set_values:
            return "fmi2Set{Real,Integer,Boolean,String}";
        case Call::get_fmu_state:
            return "fmi2GetFMUstate";
        case Call::set_fmu_state:
            return "fmi2SetFMUstate";
        case Call::free_fmu_state:
            return "fmi2FreeFMUstate";
        case Call::serialize_fmu_state:
            return "fmi2(De)SerializeFMUstate";
        case Call::directional_derivative:
            return "fmi2GetDirectionalDerivative";
        case Call::enter_event_mode:
            return "fmi2EnterEventMode";
        case Call::new_discrete_states:
            return "fmi2NewDiscreteStates";
        case Call::enter_continuous_time_mode:
            return "fmi2EnterContinuousTimeMode";
        case Call::completed_integrator_step:
            return "fmi2CompletedIntegratorStep";
        case Call::set_time:
            return "fmi2SetTime";
        case Call::set_continuous_states:
            return "fmi2SetContinuousStates";
        case Call::get_derivatives:
            return "fmi2GetDerivatives";
        case Call::get_event_indicators:
            return "fmi2GetEventIndicators";
        case Call::get_continuous_states:
            return "fmi2GetContinuousStates";
        case Call::get_nominals:
            return "fmi2GetNominalsOfContinuousStates";
        case Call::set_input_derivatives:
            return "fmi2SetRealInputDerivatives";
        case Call::get_output_derivatives:
            return "fmi2GetRealOutputDerivatives";
        case Call::do_step:
            return "fmi2DoStep";
        case Call::cancel_step:
            return "fmi2CancelStep";
        case Call::get_status:
            return "fmi2GetStatus";
    }
    return "?";
}

std::uint32_t allowed_modes(Call call) {
    using M = Mode;
    constexpr std::uint32_t any = M::instantiated | M::initialization | M::event | M::continuous_time |
                                  M::step_complete | M::step_failed | M::step_canceled | M::terminated | M::error;
    constexpr std::uint32_t readable = M::initialization | M::event | M::continuous_time | M::step_complete |
                                       M::step_failed | M::step_canceled | M::terminated | M::error;
    switch (call) {
        case Call::set_debug_logging:
            return any;
        case Call::setup_experiment:
            return static_cast<std::uint32_t>(M::instantiated);
        case Call::enter_initialization_mode:
            return static_cast<std::uint32_t>(M::instantiated);
        case Call::exit_initialization_mode:
            return static_cast<std::uint32_t>(M::initialization);
        case Call::terminate:
            return M::event | M::continuous_time | M::step_complete | M::step_failed;
        case Call::reset:
            return any;
        case Call::get_values:
            return readable;
        // Which variables may be set in which mode is checked per variable (Instance::check_settable).
        case Call::set_values:
            return M::instantiated | M::initialization | M::event | M::continuous_time | M::step_complete;
        // A state taken in the error mode could not be restored to continue (FMI 2.0 section 2.1.3).
        case Call::get_fmu_state:
            return any & ~static_cast<std::uint32_t>(M::error);
        case Call::set_fmu_state:
        case Call::free_fmu_state:
        case Call::serialize_fmu_state:
            return any;
        case Call::directional_derivative:
            return M::initialization | M::event | M::continuous_time | M::step_complete | M::step_failed |
                   M::step_canceled | M::terminated | M::error;
        case Call::enter_event_mode:
            return M::event | M::continuous_time;
        case Call::new_discrete_states:
            return static_cast<std::uint32_t>(M::event);
        case Call::enter_continuous_time_mode:
            return static_cast<std::uint32_t>(M::event);
        case Call::completed_integrator_step:
            return static_cast<std::uint32_t>(M::continuous_time);
        case Call::set_time:
            return M::event | M::continuous_time;
        case Call::set_continuous_states:
            return static_cast<std::uint32_t>(M::continuous_time);
        case Call::get_derivatives:
        case Call::get_event_indicators:
        case Call::get_continuous_states:
        case Call::get_nominals:
            return M::initialization | M::event | M::continuous_time | M::terminated | M::error;
        case Call::set_input_derivatives:
            return M::instantiated | M::initialization | M::step_complete;
        case Call::get_output_derivatives:
            return M::step_complete | M::step_failed | M::step_canceled | M::terminated | M::error;
        case Call::do_step:
            return static_cast<std::uint32_t>(M::step_complete);
        case Call::cancel_step:
            return 0;  // steps are synchronous: there is never a step in progress
        case Call::get_status:
            return M::step_complete | M::step_failed | M::step_canceled | M::terminated;
    }
    return 0;
}

}  // namespace fmu
