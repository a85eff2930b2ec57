// An FMU's shared library, dlopen'ed, with every FMI 2.0 function resolved into the typed pointers of
// fmi2FunctionTypes.h.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "fmi2/fmi2FunctionTypes.h"

namespace fmi_loader {

struct Fmi2Functions {
    // Common to both kinds (FMI 2.0.4 section 2.1).
    fmi2GetTypesPlatformTYPE* fmi2GetTypesPlatform = nullptr;
    fmi2GetVersionTYPE* fmi2GetVersion = nullptr;
    fmi2SetDebugLoggingTYPE* fmi2SetDebugLogging = nullptr;
    fmi2InstantiateTYPE* fmi2Instantiate = nullptr;
    fmi2FreeInstanceTYPE* fmi2FreeInstance = nullptr;
    fmi2SetupExperimentTYPE* fmi2SetupExperiment = nullptr;
    fmi2EnterInitializationModeTYPE* fmi2EnterInitializationMode = nullptr;
    fmi2ExitInitializationModeTYPE* fmi2ExitInitializationMode = nullptr;
    fmi2TerminateTYPE* fmi2Terminate = nullptr;
    fmi2ResetTYPE* fmi2Reset = nullptr;
    fmi2GetRealTYPE* fmi2GetReal = nullptr;
    fmi2GetIntegerTYPE* fmi2GetInteger = nullptr;
    fmi2GetBooleanTYPE* fmi2GetBoolean = nullptr;
    fmi2GetStringTYPE* fmi2GetString = nullptr;
    fmi2SetRealTYPE* fmi2SetReal = nullptr;
    fmi2SetIntegerTYPE* fmi2SetInteger = nullptr;
    fmi2SetBooleanTYPE* fmi2SetBoolean = nullptr;
    fmi2SetStringTYPE* fmi2SetString = nullptr;
    fmi2GetFMUstateTYPE* fmi2GetFMUstate = nullptr;
    fmi2SetFMUstateTYPE* fmi2SetFMUstate = nullptr;
    fmi2FreeFMUstateTYPE* fmi2FreeFMUstate = nullptr;
    fmi2SerializedFMUstateSizeTYPE* fmi2SerializedFMUstateSize = nullptr;
    fmi2SerializeFMUstateTYPE* fmi2SerializeFMUstate = nullptr;
    fmi2DeSerializeFMUstateTYPE* fmi2DeSerializeFMUstate = nullptr;
    fmi2GetDirectionalDerivativeTYPE* fmi2GetDirectionalDerivative = nullptr;
    // Model Exchange only (section 3.2).
    fmi2EnterEventModeTYPE* fmi2EnterEventMode = nullptr;
    fmi2NewDiscreteStatesTYPE* fmi2NewDiscreteStates = nullptr;
    fmi2EnterContinuousTimeModeTYPE* fmi2EnterContinuousTimeMode = nullptr;
    fmi2CompletedIntegratorStepTYPE* fmi2CompletedIntegratorStep = nullptr;
    fmi2SetTimeTYPE* fmi2SetTime = nullptr;
    fmi2SetContinuousStatesTYPE* fmi2SetContinuousStates = nullptr;
    fmi2GetDerivativesTYPE* fmi2GetDerivatives = nullptr;
    fmi2GetEventIndicatorsTYPE* fmi2GetEventIndicators = nullptr;
    fmi2GetContinuousStatesTYPE* fmi2GetContinuousStates = nullptr;
    fmi2GetNominalsOfContinuousStatesTYPE* fmi2GetNominalsOfContinuousStates = nullptr;
    // Co-Simulation only (section 4.2).
    fmi2SetRealInputDerivativesTYPE* fmi2SetRealInputDerivatives = nullptr;
    fmi2GetRealOutputDerivativesTYPE* fmi2GetRealOutputDerivatives = nullptr;
    fmi2DoStepTYPE* fmi2DoStep = nullptr;
    fmi2CancelStepTYPE* fmi2CancelStep = nullptr;
    fmi2GetStatusTYPE* fmi2GetStatus = nullptr;
    fmi2GetRealStatusTYPE* fmi2GetRealStatus = nullptr;
    fmi2GetIntegerStatusTYPE* fmi2GetIntegerStatus = nullptr;
    fmi2GetBooleanStatusTYPE* fmi2GetBooleanStatus = nullptr;
    fmi2GetStringStatusTYPE* fmi2GetStringStatus = nullptr;
};

class Fmi2Library {
public:
    // dlopen(RTLD_NOW | RTLD_LOCAL) `shared_object` and resolve the functions. The common ones are
    // always required (the standard makes every FMU export them, capability flags or not), the ME
    // ones when `model_exchange`, the CS ones when `co_simulation`. Throws LoaderError (dl_open, or
    // missing_symbol listing every missing required name). Optional names that are missing stay
    // null and are listed by missing_symbols().
    Fmi2Library(const std::filesystem::path& shared_object, bool model_exchange, bool co_simulation);
    ~Fmi2Library();
    Fmi2Library(const Fmi2Library&) = delete;
    Fmi2Library& operator=(const Fmi2Library&) = delete;

    const Fmi2Functions& functions() const noexcept { return functions_; }
    const Fmi2Functions* operator->() const noexcept { return &functions_; }
    const std::vector<std::string>& missing_symbols() const noexcept { return missing_; }
    const std::filesystem::path& path() const noexcept { return path_; }

    // binaries/linux64/<modelIdentifier>.so below an unpacked FMU (the platform tuple of section 2.3).
    static std::filesystem::path binary_path(const std::filesystem::path& fmu_root,
                                             const std::string& model_identifier);

private:
    std::filesystem::path path_;
    void* handle_ = nullptr;
    Fmi2Functions functions_;
    std::vector<std::string> missing_;
};

}  // namespace fmi_loader
