#include "fmi3_call_rules.hpp"

namespace fmu::fmi3 {

namespace {

constexpr std::uint32_t operator|(Mode a, Mode b) {
    return static_cast<std::uint32_t>(a) | static_cast<std::uint32_t>(b);
}
constexpr std::uint32_t operator|(std::uint32_t a, Mode b) {
    return a | static_cast<std::uint32_t>(b);
}
constexpr std::uint32_t bit(Mode m) {
    return static_cast<std::uint32_t>(m);
}

}  // namespace

std::string_view to_string(Mode m) {
    switch (m) {
        case Mode::instantiated:
            return "Instantiated";
        case Mode::configuration:
            return "Configuration Mode";
        case Mode::initialization:
            return "Initialization Mode";
        case Mode::event:
            return "Event Mode";
        case Mode::continuous_time:
            return "Continuous-Time Mode";
        case Mode::step:
            return "Step Mode";
        case Mode::reconfiguration:
            return "Reconfiguration Mode";
        case Mode::terminated:
            return "Terminated";
        case Mode::error:
            return "Error";
        case Mode::fatal:
            return "Fatal";
        case Mode::intermediate_update:
            return "Intermediate Update Mode (inside the intermediate-update callback)";
    }
    return "?";
}

std::string_view to_string(Call c) {
    switch (c) {
        case Call::set_debug_logging:
            return "fmi3SetDebugLogging";
        case Call::enter_initialization_mode:
            return "fmi3EnterInitializationMode";
        case Call::exit_initialization_mode:
            return "fmi3ExitInitializationMode";
        case Call::enter_event_mode:
            return "fmi3EnterEventMode";
        case Call::terminate:
            return "fmi3Terminate";
        case Call::reset:
            return "fmi3Reset";
        case Call::get_values:
            return "fmi3Get{Float64,Int32,Int64,Boolean,String,...}";
        case Call::set_values:
            return "fmi3Set{Float64,Int32,Int64,Boolean,String,...}";
        case Call::get_dependencies:
            return "fmi3Get(NumberOf)VariableDependencies";
        case Call::get_fmu_state:
            return "fmi3GetFMUState";
        case Call::set_fmu_state:
            return "fmi3SetFMUState";
        case Call::free_fmu_state:
            return "fmi3FreeFMUState";
        case Call::serialize_fmu_state:
            return "fmi3(De)SerializeFMUState";
        case Call::partial_derivative:
            return "fmi3Get{Directional,Adjoint}Derivative";
        case Call::enter_configuration_mode:
            return "fmi3EnterConfigurationMode";
        case Call::exit_configuration_mode:
            return "fmi3ExitConfigurationMode";
        case Call::clocks:
            return "fmi3{Get,Set}{Clock,Interval,Shift}";
        case Call::evaluate_discrete_states:
            return "fmi3EvaluateDiscreteStates";
        case Call::update_discrete_states:
            return "fmi3UpdateDiscreteStates";
        case Call::enter_continuous_time_mode:
            return "fmi3EnterContinuousTimeMode";
        case Call::completed_integrator_step:
            return "fmi3CompletedIntegratorStep";
        case Call::set_time:
            return "fmi3SetTime";
        case Call::set_continuous_states:
            return "fmi3SetContinuousStates";
        case Call::get_derivatives:
            return "fmi3GetContinuousStateDerivatives";
        case Call::get_event_indicators:
            return "fmi3GetEventIndicators";
        case Call::get_continuous_states:
            return "fmi3GetContinuousStates";
        case Call::get_nominals:
            return "fmi3GetNominalsOfContinuousStates";
        case Call::get_counts:
            return "fmi3GetNumberOf{EventIndicators,ContinuousStates}";
        case Call::enter_step_mode:
            return "fmi3EnterStepMode";
        case Call::get_output_derivatives:
            return "fmi3GetOutputDerivatives";
        case Call::do_step:
            return "fmi3DoStep";
        case Call::activate_model_partition:
            return "fmi3ActivateModelPartition";
    }
    return "?";
}

std::uint32_t allowed_modes(Call call) {
    using M = Mode;
    constexpr std::uint32_t any = M::instantiated | M::configuration | M::initialization | M::event |
                                  M::continuous_time | M::step | M::reconfiguration | M::terminated | M::error;
    constexpr std::uint32_t readable =
        M::initialization | M::event | M::continuous_time | M::step | M::terminated | M::error;
    switch (call) {
        case Call::set_debug_logging:
        case Call::reset:
        case Call::set_fmu_state:
        case Call::free_fmu_state:
        case Call::serialize_fmu_state:
        case Call::get_counts:
            return any;
        case Call::enter_initialization_mode:
            return bit(M::instantiated);
        case Call::exit_initialization_mode:
            return bit(M::initialization);
        // From Continuous-Time Mode (Model Exchange) or Step Mode (Co-Simulation with eventModeUsed; the
        // instance checks that flag).
        case Call::enter_event_mode:
            return M::continuous_time | M::step;
        case Call::terminate:
            return M::event | M::continuous_time | M::step;
        case Call::get_values:
        case Call::get_dependencies:
        case Call::partial_derivative:
            return readable;
        // Which variables may be set in which mode is checked per variable (the 2.0 instance's rule).
        case Call::set_values:
            return M::instantiated | M::configuration | M::initialization | M::event | M::continuous_time | M::step |
                   M::reconfiguration;
        // A state taken in the error mode could not be restored to continue.
        case Call::get_fmu_state:
            return any & ~bit(M::error);
        // Configuration Mode from Instantiated, Reconfiguration Mode from Event or Step Mode; the
        // instance refuses both: there is no structural parameter to configure.
        case Call::enter_configuration_mode:
            return M::instantiated | M::event | M::step;
        case Call::exit_configuration_mode:
            return M::configuration | M::reconfiguration;
        // No clocks and no Scheduled Execution: refused with a message in every mode they exist in.
        case Call::clocks:
            return M::initialization | M::event | M::step | M::continuous_time;
        case Call::evaluate_discrete_states:
            return M::initialization | M::event | M::continuous_time | M::step;
        case Call::activate_model_partition:
            return any;
        case Call::update_discrete_states:
        case Call::enter_continuous_time_mode:
        case Call::enter_step_mode:
            return bit(M::event);
        case Call::completed_integrator_step:
            return bit(M::continuous_time);
        case Call::set_time:
        case Call::set_continuous_states:
            return M::event | M::continuous_time;
        case Call::get_derivatives:
        case Call::get_event_indicators:
        case Call::get_continuous_states:
        case Call::get_nominals:
            return M::initialization | M::event | M::continuous_time | M::terminated | M::error;
        case Call::get_output_derivatives:
            return M::step | M::terminated | M::error;
        case Call::do_step:
            return bit(M::step);
    }
    return 0;
}

}  // namespace fmu::fmi3
