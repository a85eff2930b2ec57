// The FMI 3.0 C API, implemented once for every block beside the FMI 2.0 one (fmi2_api.cpp), with
// the same contract: each entry point checks its handle, then runs its body inside one guard that
// enforces the FMI 3.0 call-sequence table (fmi3_call_rules.hpp) and turns exceptions into an
// fmi3Status plus a message through the host's logger. fmu::Discard -> fmi3Discard; any other
// exception -> fmi3Error (fmi3Fatal for a non-standard one) and the instance enters the error state,
// left only by fmi3SetFMUState, fmi3Reset or fmi3FreeInstance.
// Not offered, each refused with a message naming it: Scheduled Execution, clocks, Configuration and
// Reconfiguration Mode (no structural parameters), directional and adjoint derivatives, output
// derivatives, fmi3EvaluateDiscreteStates, variables accessed in Intermediate Update Mode (the
// intermediate-update callback is called at events only, to let the host request an early return; the
// instance is in Intermediate Update Mode while it runs, and the call-rule table refuses every call
// from there).
#include <new>
#include <type_traits>

#include "fmi3/fmi3Functions.h"
#include "fmi3_instance.hpp"
#include "fmu/description.hpp"
#include "fmu/errors.hpp"
#include "live_instances.hpp"

namespace {

using fmu::Kind;
using fmu::fmi3::Call;
using fmu::fmi3::Instance3;

fmu::LiveInstances& registry() {
    static fmu::LiveInstances r;
    return r;
}
bool is_live(const void* c) {
    return registry().contains(c);
}

const std::string& instantiation_token() {
    static const std::string token = fmu::description_guid(*fmu::make_model());
    return token;
}

template <class Body>
fmi3Status guarded(fmi3Instance c, Call call, Body&& body) noexcept {
    if (!c || !is_live(c)) return fmi3Error;  // no instance, hence no logger to tell
    auto& self = *static_cast<Instance3*>(c);
    try {
        if (self.logs_calls()) self.log_call(fmu::fmi3::to_string(call));
        self.require(call);
        if constexpr (std::is_void_v<decltype(body(self))>) {
            body(self);
            return fmi3OK;
        } else {
            return body(self);
        }
    } catch (const fmu::Discard& e) {
        self.log(fmi3Discard, "logStatusDiscard", e.what());
        return fmi3Discard;
    } catch (const std::bad_alloc&) {
        self.enter_error_mode();
        self.log(fmi3Error, "logStatusError", std::string(fmu::fmi3::to_string(call)) + ": out of memory");
        return fmi3Error;
    } catch (const std::exception& e) {
        self.enter_error_mode();
        self.log(fmi3Error, "logStatusError", e.what());
        return fmi3Error;
    } catch (...) {
        self.enter_error_mode();
        self.log(fmi3Fatal, "logStatusFatal", std::string(fmu::fmi3::to_string(call)) + ": unknown exception");
        return fmi3Fatal;
    }
}

template <class T>
std::span<T> span_of(T* p, size_t n) {
    return std::span<T>(p, p ? n : 0);
}
template <class T>
std::span<const T> cspan_of(const T* p, size_t n) {
    if (!p && n > 0) throw fmu::Error("null array with a non-zero length");
    return std::span<const T>(p, p ? n : 0);
}

fmi3Instance instantiate(fmi3String instanceName, fmi3String instantiationToken, Kind kind, fmu::fmi3::Options options,
                         fmi3Boolean loggingOn, fmi3InstanceEnvironment environment, fmi3LogMessageCallback logger) {
    const char* function =
        kind == Kind::model_exchange ? "fmi3InstantiateModelExchange" : "fmi3InstantiateCoSimulation";
    auto refuse = [&](const std::string& why) -> fmi3Instance {
        if (logger) logger(environment, fmi3Error, "logStatusError", (std::string(function) + ": " + why).c_str());
        return nullptr;
    };
    try {
        if (!instanceName || !*instanceName) return refuse("the instance name is empty");
        if (!instantiationToken || instantiation_token() != instantiationToken)
            return refuse(std::string("instantiation token ") + (instantiationToken ? instantiationToken : "(null)") +
                          " does not match this FMU's " + instantiation_token());
        auto* instance = new Instance3(instanceName, kind, options, environment, logger, loggingOn, fmu::make_model(),
                                       instantiation_token());
        registry().insert(instance);
        return instance;
    } catch (const std::exception& e) {
        return refuse(e.what());
    } catch (...) {
        return refuse("unknown exception");
    }
}

// Getters and setters of a type no variable of these FMUs has.
fmi3Status no_such_type(fmi3Instance c, Call call, const char* function, const fmi3ValueReference vr[], size_t nvr) {
    return guarded(c, call, [&](Instance3& i) { i.refuse_type(function, cspan_of(vr, nvr)); });
}

fmi3Status not_offered(fmi3Instance c, Call call, const char* what) {
    return guarded(c, call, [&](Instance3&) { throw fmu::Error(what); });
}

constexpr const char* no_clocks =
    "clocks are not supported: this FMU declares no Clock variable (its sampled updates are time events in Model "
    "Exchange and events in Co-Simulation's Event Mode)";

}  // namespace

extern "C" {

const char* fmi3GetVersion(void) {
    return fmi3Version;
}

fmi3Status fmi3SetDebugLogging(fmi3Instance c, fmi3Boolean loggingOn, size_t nCategories,
                               const fmi3String categories[]) {
    return guarded(c, Call::set_debug_logging, [&](Instance3& i) {
        if (nCategories > 0 && !categories) throw fmu::Error("fmi3SetDebugLogging: null category array");
        i.set_debug_logging(loggingOn, cspan_of(categories, nCategories));
    });
}

fmi3Instance fmi3InstantiateModelExchange(fmi3String instanceName, fmi3String instantiationToken, fmi3String,
                                          fmi3Boolean, fmi3Boolean loggingOn, fmi3InstanceEnvironment environment,
                                          fmi3LogMessageCallback logMessage) {
    return instantiate(instanceName, instantiationToken, Kind::model_exchange, {}, loggingOn, environment, logMessage);
}

fmi3Instance fmi3InstantiateCoSimulation(fmi3String instanceName, fmi3String instantiationToken, fmi3String,
                                         fmi3Boolean, fmi3Boolean loggingOn, fmi3Boolean eventModeUsed,
                                         fmi3Boolean earlyReturnAllowed, const fmi3ValueReference[], size_t,
                                         fmi3InstanceEnvironment environment, fmi3LogMessageCallback logMessage,
                                         fmi3IntermediateUpdateCallback intermediateUpdate) {
    return instantiate(instanceName, instantiationToken, Kind::co_simulation,
                       {eventModeUsed, earlyReturnAllowed, intermediateUpdate}, loggingOn, environment, logMessage);
}

fmi3Instance fmi3InstantiateScheduledExecution(fmi3String instanceName, fmi3String, fmi3String, fmi3Boolean,
                                               fmi3Boolean, fmi3InstanceEnvironment environment,
                                               fmi3LogMessageCallback logMessage, fmi3ClockUpdateCallback,
                                               fmi3LockPreemptionCallback, fmi3UnlockPreemptionCallback) {
    if (logMessage)
        logMessage(environment, fmi3Error, "logStatusError",
                   (std::string("fmi3InstantiateScheduledExecution (") + (instanceName ? instanceName : "") +
                    "): Scheduled Execution is not supported by this FMU (it offers Model Exchange and Co-Simulation)")
                       .c_str());
    return nullptr;
}

void fmi3FreeInstance(fmi3Instance c) {
    if (!c) return;
    if (!registry().contains(c)) return;
    // From inside the intermediate-update callback the step that called it is still on the stack:
    // freeing the instance under it is refused (the host frees it after fmi3DoStep returns).
    if (static_cast<Instance3*>(c)->in_intermediate_update()) {
        static_cast<Instance3*>(c)->log(fmi3Error, "logStatusError",
                                        "fmi3FreeInstance is not allowed in Intermediate Update Mode (from inside "
                                        "the intermediate-update callback): call it after fmi3DoStep returns");
        return;
    }
    if (!registry().erase(c)) return;
    delete static_cast<Instance3*>(c);
}

fmi3Status fmi3EnterInitializationMode(fmi3Instance c, fmi3Boolean toleranceDefined, fmi3Float64 tolerance,
                                       fmi3Float64 startTime, fmi3Boolean stopTimeDefined, fmi3Float64 stopTime) {
    return guarded(c, Call::enter_initialization_mode, [&](Instance3& i) {
        i.enter_initialization_mode(toleranceDefined, tolerance, startTime, stopTimeDefined, stopTime);
    });
}
fmi3Status fmi3ExitInitializationMode(fmi3Instance c) {
    return guarded(c, Call::exit_initialization_mode, [](Instance3& i) { i.exit_initialization_mode(); });
}
fmi3Status fmi3EnterEventMode(fmi3Instance c) {
    return guarded(c, Call::enter_event_mode, [](Instance3& i) { i.enter_event_mode(); });
}
fmi3Status fmi3Terminate(fmi3Instance c) {
    return guarded(c, Call::terminate, [](Instance3& i) { i.terminate(); });
}
fmi3Status fmi3Reset(fmi3Instance c) {
    return guarded(c, Call::reset, [](Instance3& i) { i.reset(); });
}

// Getters and setters: nValues counts array elements.
fmi3Status fmi3GetFloat64(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr, fmi3Float64 values[],
                          size_t nValues) {
    return guarded(c, Call::get_values,
                   [&](Instance3& i) { i.get_float64(cspan_of(vr, nvr), span_of(values, nValues)); });
}
fmi3Status fmi3GetInt32(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr, fmi3Int32 values[], size_t nValues) {
    return guarded(c, Call::get_values,
                   [&](Instance3& i) { i.get_int32(cspan_of(vr, nvr), span_of(values, nValues)); });
}
fmi3Status fmi3GetInt64(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr, fmi3Int64 values[], size_t nValues) {
    return guarded(c, Call::get_values,
                   [&](Instance3& i) { i.get_int64(cspan_of(vr, nvr), span_of(values, nValues)); });
}
fmi3Status fmi3GetBoolean(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr, fmi3Boolean values[],
                          size_t nValues) {
    return guarded(c, Call::get_values,
                   [&](Instance3& i) { i.get_boolean(cspan_of(vr, nvr), span_of(values, nValues)); });
}
fmi3Status fmi3GetString(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr, fmi3String values[],
                         size_t nValues) {
    return guarded(c, Call::get_values,
                   [&](Instance3& i) { i.get_string(cspan_of(vr, nvr), span_of(values, nValues)); });
}
fmi3Status fmi3SetFloat64(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr, const fmi3Float64 values[],
                          size_t nValues) {
    return guarded(c, Call::set_values,
                   [&](Instance3& i) { i.set_float64(cspan_of(vr, nvr), cspan_of(values, nValues)); });
}
fmi3Status fmi3SetInt32(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr, const fmi3Int32 values[],
                        size_t nValues) {
    return guarded(c, Call::set_values,
                   [&](Instance3& i) { i.set_int32(cspan_of(vr, nvr), cspan_of(values, nValues)); });
}
fmi3Status fmi3SetInt64(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr, const fmi3Int64 values[],
                        size_t nValues) {
    return guarded(c, Call::set_values,
                   [&](Instance3& i) { i.set_int64(cspan_of(vr, nvr), cspan_of(values, nValues)); });
}
fmi3Status fmi3SetBoolean(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr, const fmi3Boolean values[],
                          size_t nValues) {
    return guarded(c, Call::set_values,
                   [&](Instance3& i) { i.set_boolean(cspan_of(vr, nvr), cspan_of(values, nValues)); });
}
fmi3Status fmi3SetString(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr, const fmi3String values[],
                         size_t nValues) {
    return guarded(c, Call::set_values,
                   [&](Instance3& i) { i.set_string(cspan_of(vr, nvr), cspan_of(values, nValues)); });
}

#define PVATT_NO_SUCH_TYPE(Name, T)                                                                          \
    fmi3Status fmi3Get##Name(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr, T[], size_t) {       \
        return no_such_type(c, Call::get_values, "fmi3Get" #Name, vr, nvr);                                  \
    }                                                                                                        \
    fmi3Status fmi3Set##Name(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr, const T[], size_t) { \
        return no_such_type(c, Call::set_values, "fmi3Set" #Name, vr, nvr);                                  \
    }
PVATT_NO_SUCH_TYPE(Float32, fmi3Float32)
PVATT_NO_SUCH_TYPE(Int8, fmi3Int8)
PVATT_NO_SUCH_TYPE(UInt8, fmi3UInt8)
PVATT_NO_SUCH_TYPE(Int16, fmi3Int16)
PVATT_NO_SUCH_TYPE(UInt16, fmi3UInt16)
PVATT_NO_SUCH_TYPE(UInt32, fmi3UInt32)
PVATT_NO_SUCH_TYPE(UInt64, fmi3UInt64)
#undef PVATT_NO_SUCH_TYPE

fmi3Status fmi3GetBinary(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr, size_t[], fmi3Binary[], size_t) {
    return no_such_type(c, Call::get_values, "fmi3GetBinary", vr, nvr);
}
fmi3Status fmi3SetBinary(fmi3Instance c, const fmi3ValueReference vr[], size_t nvr, const size_t[], const fmi3Binary[],
                         size_t) {
    return no_such_type(c, Call::set_values, "fmi3SetBinary", vr, nvr);
}

fmi3Status fmi3GetClock(fmi3Instance c, const fmi3ValueReference[], size_t, fmi3Clock[]) {
    return not_offered(c, Call::clocks, no_clocks);
}
fmi3Status fmi3SetClock(fmi3Instance c, const fmi3ValueReference[], size_t, const fmi3Clock[]) {
    return not_offered(c, Call::clocks, no_clocks);
}
fmi3Status fmi3GetIntervalDecimal(fmi3Instance c, const fmi3ValueReference[], size_t, fmi3Float64[],
                                  fmi3IntervalQualifier[]) {
    return not_offered(c, Call::clocks, no_clocks);
}
fmi3Status fmi3GetIntervalFraction(fmi3Instance c, const fmi3ValueReference[], size_t, fmi3UInt64[], fmi3UInt64[],
                                   fmi3IntervalQualifier[]) {
    return not_offered(c, Call::clocks, no_clocks);
}
fmi3Status fmi3GetShiftDecimal(fmi3Instance c, const fmi3ValueReference[], size_t, fmi3Float64[]) {
    return not_offered(c, Call::clocks, no_clocks);
}
fmi3Status fmi3GetShiftFraction(fmi3Instance c, const fmi3ValueReference[], size_t, fmi3UInt64[], fmi3UInt64[]) {
    return not_offered(c, Call::clocks, no_clocks);
}
fmi3Status fmi3SetIntervalDecimal(fmi3Instance c, const fmi3ValueReference[], size_t, const fmi3Float64[]) {
    return not_offered(c, Call::clocks, no_clocks);
}
fmi3Status fmi3SetIntervalFraction(fmi3Instance c, const fmi3ValueReference[], size_t, const fmi3UInt64[],
                                   const fmi3UInt64[]) {
    return not_offered(c, Call::clocks, no_clocks);
}
fmi3Status fmi3SetShiftDecimal(fmi3Instance c, const fmi3ValueReference[], size_t, const fmi3Float64[]) {
    return not_offered(c, Call::clocks, no_clocks);
}
fmi3Status fmi3SetShiftFraction(fmi3Instance c, const fmi3ValueReference[], size_t, const fmi3UInt64[],
                                const fmi3UInt64[]) {
    return not_offered(c, Call::clocks, no_clocks);
}

fmi3Status fmi3GetNumberOfVariableDependencies(fmi3Instance c, fmi3ValueReference, size_t*) {
    return not_offered(c, Call::get_dependencies,
                       "fmi3GetNumberOfVariableDependencies: not provided; the dependencies are in the model "
                       "description's ModelStructure");
}
fmi3Status fmi3GetVariableDependencies(fmi3Instance c, fmi3ValueReference, size_t[], fmi3ValueReference[], size_t[],
                                       fmi3DependencyKind[], size_t) {
    return not_offered(c, Call::get_dependencies,
                       "fmi3GetVariableDependencies: not provided; the dependencies are in the model description's "
                       "ModelStructure");
}

fmi3Status fmi3GetFMUState(fmi3Instance c, fmi3FMUState* FMUState) {
    return guarded(c, Call::get_fmu_state, [&](Instance3& i) {
        if (!FMUState) throw fmu::Error("fmi3GetFMUState: null pointer");
        *FMUState = i.get_state(static_cast<fmu::Snapshot*>(*FMUState));
    });
}
fmi3Status fmi3SetFMUState(fmi3Instance c, fmi3FMUState FMUState) {
    return guarded(c, Call::set_fmu_state,
                   [&](Instance3& i) { i.set_state(static_cast<const fmu::Snapshot*>(FMUState)); });
}
fmi3Status fmi3FreeFMUState(fmi3Instance c, fmi3FMUState* FMUState) {
    return guarded(c, Call::free_fmu_state, [&](Instance3& i) {
        if (!FMUState) throw fmu::Error("fmi3FreeFMUState: null pointer");
        i.free_state(static_cast<fmu::Snapshot*>(*FMUState));
        *FMUState = nullptr;
    });
}
fmi3Status fmi3SerializedFMUStateSize(fmi3Instance c, fmi3FMUState FMUState, size_t* size) {
    return guarded(c, Call::serialize_fmu_state, [&](Instance3& i) {
        if (!size) throw fmu::Error("fmi3SerializedFMUStateSize: null size pointer");
        *size = i.serialized_size(static_cast<const fmu::Snapshot*>(FMUState));
    });
}
fmi3Status fmi3SerializeFMUState(fmi3Instance c, fmi3FMUState FMUState, fmi3Byte serializedState[], size_t size) {
    return guarded(c, Call::serialize_fmu_state, [&](Instance3& i) {
        if (!serializedState) throw fmu::Error("fmi3SerializeFMUState: null buffer");
        const auto bytes = i.serialize(static_cast<const fmu::Snapshot*>(FMUState));
        if (size < bytes.size())
            throw fmu::Error("fmi3SerializeFMUState: buffer of " + std::to_string(size) + " bytes is smaller than " +
                             std::to_string(bytes.size()));
        std::copy(bytes.begin(), bytes.end(), reinterpret_cast<char*>(serializedState));
    });
}
fmi3Status fmi3DeserializeFMUState(fmi3Instance c, const fmi3Byte serializedState[], size_t size,
                                   fmi3FMUState* FMUState) {
    return guarded(c, Call::serialize_fmu_state, [&](Instance3& i) {
        if (!serializedState || !FMUState) throw fmu::Error("fmi3DeserializeFMUState: null pointer");
        fmu::Snapshot* fresh = i.deserialize(cspan_of(serializedState, size));
        if (*FMUState) i.free_state(static_cast<fmu::Snapshot*>(*FMUState));
        *FMUState = fresh;
    });
}

fmi3Status fmi3GetDirectionalDerivative(fmi3Instance c, const fmi3ValueReference[], size_t, const fmi3ValueReference[],
                                        size_t, const fmi3Float64[], size_t, fmi3Float64[], size_t) {
    return not_offered(c, Call::partial_derivative,
                       "fmi3GetDirectionalDerivative: not provided (providesDirectionalDerivatives=\"false\")");
}
fmi3Status fmi3GetAdjointDerivative(fmi3Instance c, const fmi3ValueReference[], size_t, const fmi3ValueReference[],
                                    size_t, const fmi3Float64[], size_t, fmi3Float64[], size_t) {
    return not_offered(c, Call::partial_derivative,
                       "fmi3GetAdjointDerivative: not provided (providesAdjointDerivatives=\"false\")");
}

fmi3Status fmi3EnterConfigurationMode(fmi3Instance c) {
    return not_offered(c, Call::enter_configuration_mode,
                       "fmi3EnterConfigurationMode: this FMU has no structural parameters, so neither Configuration "
                       "nor Reconfiguration Mode");
}
fmi3Status fmi3ExitConfigurationMode(fmi3Instance c) {
    return guarded(c, Call::exit_configuration_mode, [](Instance3&) {});  // never reached: the mode never begins
}

fmi3Status fmi3EvaluateDiscreteStates(fmi3Instance c) {
    return not_offered(c, Call::evaluate_discrete_states,
                       "fmi3EvaluateDiscreteStates: not provided (providesEvaluateDiscreteStates=\"false\")");
}

fmi3Status fmi3UpdateDiscreteStates(fmi3Instance c, fmi3Boolean* discreteStatesNeedUpdate,
                                    fmi3Boolean* terminateSimulation, fmi3Boolean* nominalsOfContinuousStatesChanged,
                                    fmi3Boolean* valuesOfContinuousStatesChanged, fmi3Boolean* nextEventTimeDefined,
                                    fmi3Float64* nextEventTime) {
    return guarded(c, Call::update_discrete_states, [&](Instance3& i) {
        if (!discreteStatesNeedUpdate || !terminateSimulation || !nominalsOfContinuousStatesChanged ||
            !valuesOfContinuousStatesChanged || !nextEventTimeDefined || !nextEventTime)
            throw fmu::Error("fmi3UpdateDiscreteStates: null output pointer");
        const auto u = i.update_discrete_states();
        *discreteStatesNeedUpdate = u.again;
        *terminateSimulation = u.terminate;
        *nominalsOfContinuousStatesChanged = false;
        *valuesOfContinuousStatesChanged = u.states_changed;
        *nextEventTimeDefined = u.next_defined;
        *nextEventTime = u.next_time;
    });
}

// Model Exchange
fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance c) {
    return guarded(c, Call::enter_continuous_time_mode, [](Instance3& i) {
        i.require_kind(Kind::model_exchange, Call::enter_continuous_time_mode);
        i.enter_continuous_time_mode();
    });
}
fmi3Status fmi3CompletedIntegratorStep(fmi3Instance c, fmi3Boolean, fmi3Boolean* enterEventMode,
                                       fmi3Boolean* terminateSimulation) {
    return guarded(c, Call::completed_integrator_step, [&](Instance3& i) {
        i.require_kind(Kind::model_exchange, Call::completed_integrator_step);
        if (!enterEventMode || !terminateSimulation)
            throw fmu::Error("fmi3CompletedIntegratorStep: null output pointer");
        *enterEventMode = false;  // no step events: every event is a time or state event
        *terminateSimulation = false;
    });
}
fmi3Status fmi3SetTime(fmi3Instance c, fmi3Float64 time) {
    return guarded(c, Call::set_time, [&](Instance3& i) {
        i.require_kind(Kind::model_exchange, Call::set_time);
        i.set_time(time);
    });
}
fmi3Status fmi3SetContinuousStates(fmi3Instance c, const fmi3Float64 x[], size_t nx) {
    return guarded(c, Call::set_continuous_states, [&](Instance3& i) {
        i.require_kind(Kind::model_exchange, Call::set_continuous_states);
        i.inner().set_continuous_states(cspan_of(x, nx));
    });
}
fmi3Status fmi3GetContinuousStateDerivatives(fmi3Instance c, fmi3Float64 derivatives[], size_t nx) {
    return guarded(c, Call::get_derivatives, [&](Instance3& i) {
        i.require_kind(Kind::model_exchange, Call::get_derivatives);
        i.inner().get_derivatives(span_of(derivatives, nx));
    });
}
fmi3Status fmi3GetEventIndicators(fmi3Instance c, fmi3Float64 eventIndicators[], size_t ni) {
    return guarded(c, Call::get_event_indicators, [&](Instance3& i) {
        i.require_kind(Kind::model_exchange, Call::get_event_indicators);
        i.inner().get_event_indicators(span_of(eventIndicators, ni));
    });
}
fmi3Status fmi3GetContinuousStates(fmi3Instance c, fmi3Float64 x[], size_t nx) {
    return guarded(c, Call::get_continuous_states, [&](Instance3& i) {
        i.require_kind(Kind::model_exchange, Call::get_continuous_states);
        i.inner().get_continuous_states(span_of(x, nx));
    });
}
fmi3Status fmi3GetNominalsOfContinuousStates(fmi3Instance c, fmi3Float64 nominals[], size_t nx) {
    return guarded(c, Call::get_nominals, [&](Instance3& i) {
        i.require_kind(Kind::model_exchange, Call::get_nominals);
        i.inner().get_nominals(span_of(nominals, nx));
    });
}
fmi3Status fmi3GetNumberOfEventIndicators(fmi3Instance c, size_t* n) {
    return guarded(c, Call::get_counts, [&](Instance3& i) {
        if (!n) throw fmu::Error("fmi3GetNumberOfEventIndicators: null pointer");
        *n = i.event_indicator_count();
    });
}
fmi3Status fmi3GetNumberOfContinuousStates(fmi3Instance c, size_t* n) {
    return guarded(c, Call::get_counts, [&](Instance3& i) {
        if (!n) throw fmu::Error("fmi3GetNumberOfContinuousStates: null pointer");
        *n = i.state_count();
    });
}

// Co-Simulation
fmi3Status fmi3EnterStepMode(fmi3Instance c) {
    return guarded(c, Call::enter_step_mode, [](Instance3& i) {
        i.require_kind(Kind::co_simulation, Call::enter_step_mode);
        i.enter_step_mode();
    });
}
fmi3Status fmi3GetOutputDerivatives(fmi3Instance c, const fmi3ValueReference[], size_t, const fmi3Int32[],
                                    fmi3Float64[], size_t) {
    return guarded(c, Call::get_output_derivatives, [](Instance3& i) {
        i.require_kind(Kind::co_simulation, Call::get_output_derivatives);
        throw fmu::Error("fmi3GetOutputDerivatives: not provided (maxOutputDerivativeOrder=\"0\")");
    });
}
fmi3Status fmi3DoStep(fmi3Instance c, fmi3Float64 currentCommunicationPoint, fmi3Float64 communicationStepSize,
                      fmi3Boolean, fmi3Boolean* eventHandlingNeeded, fmi3Boolean* terminateSimulation,
                      fmi3Boolean* earlyReturn, fmi3Float64* lastSuccessfulTime) {
    return guarded(c, Call::do_step, [&](Instance3& i) {
        i.require_kind(Kind::co_simulation, Call::do_step);
        if (!eventHandlingNeeded || !terminateSimulation || !earlyReturn || !lastSuccessfulTime)
            throw fmu::Error("fmi3DoStep: null output pointer");
        const auto r = i.do_step(currentCommunicationPoint, communicationStepSize);
        *eventHandlingNeeded = r.event_handling_needed;
        *terminateSimulation = r.terminate;
        *earlyReturn = r.early_return;
        *lastSuccessfulTime = r.last_successful_time;
        return r.status;
    });
}

// Scheduled Execution
fmi3Status fmi3ActivateModelPartition(fmi3Instance c, fmi3ValueReference, fmi3Float64) {
    return not_offered(c, Call::activate_model_partition,
                       "fmi3ActivateModelPartition: Scheduled Execution is not supported by this FMU");
}

}  // extern "C"
