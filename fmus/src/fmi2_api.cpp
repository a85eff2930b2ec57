// The FMI 2.0 C API, implemented once for every block. Each entry point checks its handle, then runs
// its body inside one guard that enforces the call-sequence table and turns exceptions into an
// fmi2Status plus a message through the host's logger. Nothing thrown inside crosses this file.
// The error contract: fmu::Discard -> fmi2Discard, the instance stays in its mode; any other
// exception -> fmi2Error (fmi2Fatal for a non-standard one) and the instance enters the error mode.
#include <new>
#include <type_traits>

#include "fmi2/fmi2Functions.h"
#include "fmu/description.hpp"
#include "fmu/errors.hpp"
#include "instance.hpp"
#include "live_instances.hpp"

namespace {

using fmu::Call;
using fmu::Instance;
using fmu::Kind;

// The instances alive in this process. A handle the host passes in is used only if it is one of them,
// so a null, freed or foreign pointer gives fmi2Error instead of a crash.
fmu::LiveInstances& registry() {
    static fmu::LiveInstances r;
    return r;
}
bool is_live(const void* c) {
    return registry().contains(c);
}

const std::string& model_guid() {
    static const std::string guid = fmu::description_guid(*fmu::make_model());
    return guid;
}

template <class Body>
fmi2Status guarded(fmi2Component c, Call call, Body&& body) noexcept {
    if (!c || !is_live(c)) return fmi2Error;  // no instance, hence no logger to tell
    auto& self = *static_cast<Instance*>(c);
    try {
        if (self.logs_calls()) self.log_call(fmu::to_string(call));  // nothing built unless logAll is on
        self.require(call);
        if constexpr (std::is_void_v<decltype(body(self))>) {
            body(self);
            return fmi2OK;
        } else {
            return body(self);
        }
    } catch (const fmu::Discard& e) {
        self.log(fmi2Discard, "logStatusDiscard", e.what());
        return fmi2Discard;
    } catch (const std::bad_alloc&) {
        self.enter_error_mode();
        self.log(fmi2Error, "logStatusError", std::string(fmu::to_string(call)) + ": out of memory");
        return fmi2Error;
    } catch (const std::exception& e) {
        // FMI 2.0 section 2.1.3: after fmi2Error the simulation cannot continue with this instance
        // until the host restores a state it saved (fmi2SetFMUstate) or resets it; until then only
        // the calls call_rules.cpp allows in the error mode (reads for diagnosis, state restore,
        // reset, free, logging) are accepted. Values a host sets are checked before any is
        // written, so an instance never continues from a half-applied call either.
        self.enter_error_mode();
        self.log(fmi2Error, "logStatusError", e.what());
        return fmi2Error;
    } catch (...) {
        self.enter_error_mode();
        self.log(fmi2Fatal, "logStatusFatal", std::string(fmu::to_string(call)) + ": unknown exception");
        return fmi2Fatal;
    }
}

template <class T>
std::span<const T> span_of(const T* p, size_t n) {
    return p ? std::span<const T>(p, n) : std::span<const T>(static_cast<const T*>(nullptr), n);
}

}  // namespace

extern "C" {

const char* fmi2GetTypesPlatform(void) {
    return fmi2TypesPlatform;
}
const char* fmi2GetVersion(void) {
    return fmi2Version;
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID, fmi2String,
                              const fmi2CallbackFunctions* functions, fmi2Boolean, fmi2Boolean loggingOn) {
    if (!functions) return nullptr;
    auto refuse = [&](const std::string& why) -> fmi2Component {
        if (functions->logger)
            functions->logger(functions->componentEnvironment, instanceName ? instanceName : "", fmi2Error,
                              "logStatusError", "%s", why.c_str());
        return nullptr;
    };
    try {
        if (!instanceName || !*instanceName) return refuse("fmi2Instantiate: the instance name is empty");
        if (fmuType != fmi2ModelExchange && fmuType != fmi2CoSimulation)
            return refuse("fmi2Instantiate: unknown fmuType " + std::to_string(static_cast<int>(fmuType)));
        if (!fmuGUID || model_guid() != fmuGUID)
            return refuse(std::string("fmi2Instantiate: GUID ") + (fmuGUID ? fmuGUID : "(null)") +
                          " does not match this FMU's " + model_guid());
        auto* instance =
            new Instance(instanceName, fmuType == fmi2ModelExchange ? Kind::model_exchange : Kind::co_simulation,
                         *functions, loggingOn != fmi2False, fmu::make_model(), model_guid());
        registry().insert(instance);
        return instance;
    } catch (const std::exception& e) {
        return refuse(std::string("fmi2Instantiate: ") + e.what());
    } catch (...) {
        return refuse("fmi2Instantiate: unknown exception");
    }
}

void fmi2FreeInstance(fmi2Component c) {
    if (!c) return;
    if (!registry().erase(c)) return;
    delete static_cast<Instance*>(c);
}

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t nCategories,
                               const fmi2String categories[]) {
    return guarded(c, Call::set_debug_logging, [&](Instance& i) {
        if (nCategories > 0 && !categories) throw fmu::Error("fmi2SetDebugLogging: null category array");
        i.set_debug_logging(loggingOn != fmi2False, span_of(categories, nCategories));
    });
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined, fmi2Real tolerance, fmi2Real startTime,
                               fmi2Boolean stopTimeDefined, fmi2Real stopTime) {
    return guarded(c, Call::setup_experiment, [&](Instance& i) {
        i.setup_experiment(toleranceDefined != fmi2False, tolerance, startTime, stopTimeDefined != fmi2False, stopTime);
    });
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
    return guarded(c, Call::enter_initialization_mode, [](Instance& i) { i.enter_initialization_mode(); });
}
fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
    return guarded(c, Call::exit_initialization_mode, [](Instance& i) { i.exit_initialization_mode(); });
}
fmi2Status fmi2Terminate(fmi2Component c) {
    return guarded(c, Call::terminate, [](Instance& i) { i.terminate(); });
}
fmi2Status fmi2Reset(fmi2Component c) {
    return guarded(c, Call::reset, [](Instance& i) { i.reset(); });
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Real value[]) {
    return guarded(c, Call::get_values, [&](Instance& i) { i.get_real(span_of(vr, nvr), value); });
}
fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Integer value[]) {
    return guarded(c, Call::get_values, [&](Instance& i) { i.get_integer(span_of(vr, nvr), value); });
}
fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2Boolean value[]) {
    return guarded(c, Call::get_values, [&](Instance& i) { i.get_boolean(span_of(vr, nvr), value); });
}
fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, fmi2String value[]) {
    return guarded(c, Call::get_values, [&](Instance& i) { i.get_string(span_of(vr, nvr), value); });
}
fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Real value[]) {
    return guarded(c, Call::set_values, [&](Instance& i) { i.set_real(span_of(vr, nvr), value); });
}
fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Integer value[]) {
    return guarded(c, Call::set_values, [&](Instance& i) { i.set_integer(span_of(vr, nvr), value); });
}
fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2Boolean value[]) {
    return guarded(c, Call::set_values, [&](Instance& i) { i.set_boolean(span_of(vr, nvr), value); });
}
fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, const fmi2String value[]) {
    return guarded(c, Call::set_values, [&](Instance& i) { i.set_string(span_of(vr, nvr), value); });
}

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate* FMUstate) {
    return guarded(c, Call::get_fmu_state, [&](Instance& i) {
        if (!FMUstate) throw fmu::Error("fmi2GetFMUstate: null pointer");
        *FMUstate = i.get_state(static_cast<fmu::Snapshot*>(*FMUstate));
    });
}
fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate FMUstate) {
    return guarded(c, Call::set_fmu_state,
                   [&](Instance& i) { i.set_state(static_cast<const fmu::Snapshot*>(FMUstate)); });
}
fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate* FMUstate) {
    return guarded(c, Call::free_fmu_state, [&](Instance& i) {
        if (!FMUstate) throw fmu::Error("fmi2FreeFMUstate: null pointer");
        i.free_state(static_cast<fmu::Snapshot*>(*FMUstate));
        *FMUstate = nullptr;
    });
}
fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate FMUstate, size_t* size) {
    return guarded(c, Call::serialize_fmu_state, [&](Instance& i) {
        if (!size) throw fmu::Error("fmi2SerializedFMUstateSize: null size pointer");
        *size = i.serialized_size(static_cast<const fmu::Snapshot*>(FMUstate));
    });
}
fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate FMUstate, fmi2Byte serializedState[], size_t size) {
    return guarded(c, Call::serialize_fmu_state, [&](Instance& i) {
        if (!serializedState) throw fmu::Error("fmi2SerializeFMUstate: null buffer");
        const auto bytes = i.serialize(static_cast<const fmu::Snapshot*>(FMUstate));
        if (size < bytes.size())
            throw fmu::Error("fmi2SerializeFMUstate: buffer of " + std::to_string(size) + " bytes is smaller than " +
                             std::to_string(bytes.size()));
        std::copy(bytes.begin(), bytes.end(), serializedState);
    });
}
fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte serializedState[], size_t size,
                                   fmi2FMUstate* FMUstate) {
    return guarded(c, Call::serialize_fmu_state, [&](Instance& i) {
        if (!serializedState || !FMUstate) throw fmu::Error("fmi2DeSerializeFMUstate: null pointer");
        fmu::Snapshot* fresh = i.deserialize(span_of(serializedState, size));
        if (*FMUstate)
            i.free_state(static_cast<fmu::Snapshot*>(*FMUstate));  // the standard lets a host pass one to reuse
        *FMUstate = fresh;
    });
}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference[], size_t, const fmi2ValueReference[],
                                        size_t, const fmi2Real[], fmi2Real[]) {
    return guarded(c, Call::directional_derivative, [](Instance&) {
        throw fmu::Error("fmi2GetDirectionalDerivative: not provided (providesDirectionalDerivative=\"false\")");
    });
}

// Model Exchange
fmi2Status fmi2EnterEventMode(fmi2Component c) {
    return guarded(c, Call::enter_event_mode, [](Instance& i) {
        i.require_kind(Kind::model_exchange, Call::enter_event_mode);
        i.enter_event_mode();
    });
}
fmi2Status fmi2NewDiscreteStates(fmi2Component c, fmi2EventInfo* eventInfo) {
    return guarded(c, Call::new_discrete_states, [&](Instance& i) {
        i.require_kind(Kind::model_exchange, Call::new_discrete_states);
        if (!eventInfo) throw fmu::Error("fmi2NewDiscreteStates: null eventInfo");
        i.new_discrete_states(*eventInfo);
    });
}
fmi2Status fmi2EnterContinuousTimeMode(fmi2Component c) {
    return guarded(c, Call::enter_continuous_time_mode, [](Instance& i) {
        i.require_kind(Kind::model_exchange, Call::enter_continuous_time_mode);
        i.enter_continuous_time_mode();
    });
}
fmi2Status fmi2CompletedIntegratorStep(fmi2Component c, fmi2Boolean, fmi2Boolean* enterEventMode,
                                       fmi2Boolean* terminateSimulation) {
    return guarded(c, Call::completed_integrator_step, [&](Instance& i) {
        i.require_kind(Kind::model_exchange, Call::completed_integrator_step);
        i.completed_integrator_step(enterEventMode, terminateSimulation);
    });
}
fmi2Status fmi2SetTime(fmi2Component c, fmi2Real time) {
    return guarded(c, Call::set_time, [&](Instance& i) {
        i.require_kind(Kind::model_exchange, Call::set_time);
        i.set_time(time);
    });
}
fmi2Status fmi2SetContinuousStates(fmi2Component c, const fmi2Real x[], size_t nx) {
    return guarded(c, Call::set_continuous_states, [&](Instance& i) {
        i.require_kind(Kind::model_exchange, Call::set_continuous_states);
        i.set_continuous_states(span_of(x, nx));
    });
}
fmi2Status fmi2GetDerivatives(fmi2Component c, fmi2Real derivatives[], size_t nx) {
    return guarded(c, Call::get_derivatives, [&](Instance& i) {
        i.require_kind(Kind::model_exchange, Call::get_derivatives);
        i.get_derivatives({derivatives, nx});
    });
}
fmi2Status fmi2GetEventIndicators(fmi2Component c, fmi2Real eventIndicators[], size_t ni) {
    return guarded(c, Call::get_event_indicators, [&](Instance& i) {
        i.require_kind(Kind::model_exchange, Call::get_event_indicators);
        i.get_event_indicators({eventIndicators, ni});
    });
}
fmi2Status fmi2GetContinuousStates(fmi2Component c, fmi2Real x[], size_t nx) {
    return guarded(c, Call::get_continuous_states, [&](Instance& i) {
        i.require_kind(Kind::model_exchange, Call::get_continuous_states);
        i.get_continuous_states({x, nx});
    });
}
fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component c, fmi2Real x_nominal[], size_t nx) {
    return guarded(c, Call::get_nominals, [&](Instance& i) {
        i.require_kind(Kind::model_exchange, Call::get_nominals);
        i.get_nominals({x_nominal, nx});
    });
}

// Co-Simulation
fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                       const fmi2Integer order[], const fmi2Real value[]) {
    return guarded(c, Call::set_input_derivatives, [&](Instance& i) {
        i.require_kind(Kind::co_simulation, Call::set_input_derivatives);
        i.set_real_input_derivatives({vr, nvr}, order, value);
    });
}
fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference[], size_t, const fmi2Integer[],
                                        fmi2Real[]) {
    return guarded(c, Call::get_output_derivatives, [](Instance& i) {
        i.require_kind(Kind::co_simulation, Call::get_output_derivatives);
        throw fmu::Error("fmi2GetRealOutputDerivatives: not provided (maxOutputDerivativeOrder=\"0\")");
    });
}
fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint, fmi2Real communicationStepSize,
                      fmi2Boolean) {
    return guarded(c, Call::do_step, [&](Instance& i) {
        i.require_kind(Kind::co_simulation, Call::do_step);
        return i.do_step(currentCommunicationPoint, communicationStepSize);
    });
}
fmi2Status fmi2CancelStep(fmi2Component c) {
    return guarded(c, Call::cancel_step, [](Instance&) {});
}
fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status* value) {
    return guarded(c, Call::get_status, [&](Instance& i) {
        i.require_kind(Kind::co_simulation, Call::get_status);
        return i.get_status(s, value);
    });
}
fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real* value) {
    return guarded(c, Call::get_status, [&](Instance& i) {
        i.require_kind(Kind::co_simulation, Call::get_status);
        return i.get_real_status(s, value);
    });
}
fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind, fmi2Integer* value) {
    return guarded(c, Call::get_status, [&](Instance& i) -> fmi2Status {
        i.require_kind(Kind::co_simulation, Call::get_status);
        if (!value) throw fmu::Error("fmi2GetIntegerStatus: null output pointer");
        throw fmu::Discard("fmi2GetIntegerStatus: no integer status is defined by FMI 2.0");
    });
}
fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean* value) {
    return guarded(c, Call::get_status, [&](Instance& i) {
        i.require_kind(Kind::co_simulation, Call::get_status);
        return i.get_boolean_status(s, value);
    });
}
fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind, fmi2String* value) {
    return guarded(c, Call::get_status, [&](Instance& i) -> fmi2Status {
        i.require_kind(Kind::co_simulation, Call::get_status);
        if (!value) throw fmu::Error("fmi2GetStringStatus: null output pointer");
        throw fmu::Discard("fmi2GetStringStatus: only asynchronous steps have a string status");
    });
}

}  // extern "C"
