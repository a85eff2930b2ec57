// An FMI 3.0 FMU's shared library, dlopen'ed, with the FMI 3.0 functions resolved into the typed
// pointers of fmi3FunctionTypes.h (FMI 3.0.2).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "fmi3/fmi3FunctionTypes.h"

// The function names by group, each X(name, required): required ones must be exported by an FMU of
// that interface; the optional ones (FMU state, derivatives, clocks, configuration mode, dependency
// queries) stay null when absent and are checked by the user before a call that needs them.
// clang-format off
#define FMI_LOADER_FMI3_COMMON(X)                 \
    X(fmi3GetVersion, true)                       \
    X(fmi3SetDebugLogging, true)                  \
    X(fmi3FreeInstance, true)                     \
    X(fmi3EnterInitializationMode, true)          \
    X(fmi3ExitInitializationMode, true)           \
    X(fmi3EnterEventMode, true)                   \
    X(fmi3Terminate, true)                        \
    X(fmi3Reset, true)                            \
    X(fmi3GetFloat32, true)                       \
    X(fmi3GetFloat64, true)                       \
    X(fmi3GetInt8, true)                          \
    X(fmi3GetUInt8, true)                         \
    X(fmi3GetInt16, true)                         \
    X(fmi3GetUInt16, true)                        \
    X(fmi3GetInt32, true)                         \
    X(fmi3GetUInt32, true)                        \
    X(fmi3GetInt64, true)                         \
    X(fmi3GetUInt64, true)                        \
    X(fmi3GetBoolean, true)                       \
    X(fmi3GetString, true)                        \
    X(fmi3GetBinary, true)                        \
    X(fmi3SetFloat32, true)                       \
    X(fmi3SetFloat64, true)                       \
    X(fmi3SetInt8, true)                          \
    X(fmi3SetUInt8, true)                         \
    X(fmi3SetInt16, true)                         \
    X(fmi3SetUInt16, true)                        \
    X(fmi3SetInt32, true)                         \
    X(fmi3SetUInt32, true)                        \
    X(fmi3SetInt64, true)                         \
    X(fmi3SetUInt64, true)                        \
    X(fmi3SetBoolean, true)                       \
    X(fmi3SetString, true)                        \
    X(fmi3SetBinary, true)                        \
    X(fmi3UpdateDiscreteStates, true)             \
    X(fmi3GetClock, false)                        \
    X(fmi3SetClock, false)                        \
    X(fmi3GetNumberOfVariableDependencies, false) \
    X(fmi3GetVariableDependencies, false)         \
    X(fmi3GetFMUState, false)                     \
    X(fmi3SetFMUState, false)                     \
    X(fmi3FreeFMUState, false)                    \
    X(fmi3SerializedFMUStateSize, false)          \
    X(fmi3SerializeFMUState, false)               \
    X(fmi3DeserializeFMUState, false)             \
    X(fmi3GetDirectionalDerivative, false)        \
    X(fmi3GetAdjointDerivative, false)            \
    X(fmi3EnterConfigurationMode, false)          \
    X(fmi3ExitConfigurationMode, false)           \
    X(fmi3GetIntervalDecimal, false)              \
    X(fmi3GetIntervalFraction, false)             \
    X(fmi3GetShiftDecimal, false)                 \
    X(fmi3GetShiftFraction, false)                \
    X(fmi3SetIntervalDecimal, false)              \
    X(fmi3SetIntervalFraction, false)             \
    X(fmi3SetShiftDecimal, false)                 \
    X(fmi3SetShiftFraction, false)                \
    X(fmi3EvaluateDiscreteStates, false)
#define FMI_LOADER_FMI3_MODEL_EXCHANGE(X)      \
    X(fmi3InstantiateModelExchange, true)      \
    X(fmi3EnterContinuousTimeMode, true)       \
    X(fmi3CompletedIntegratorStep, true)       \
    X(fmi3SetTime, true)                       \
    X(fmi3SetContinuousStates, true)           \
    X(fmi3GetContinuousStateDerivatives, true) \
    X(fmi3GetEventIndicators, true)            \
    X(fmi3GetContinuousStates, true)           \
    X(fmi3GetNominalsOfContinuousStates, true) \
    X(fmi3GetNumberOfEventIndicators, true)    \
    X(fmi3GetNumberOfContinuousStates, true)
#define FMI_LOADER_FMI3_CO_SIMULATION(X) \
    X(fmi3InstantiateCoSimulation, true) \
    X(fmi3EnterStepMode, true)           \
    X(fmi3DoStep, true)                  \
    X(fmi3GetOutputDerivatives, false)
// clang-format on

namespace fmi_loader {

struct Fmi3Functions {
#define FMI_LOADER_FIELD(name, required) name##TYPE* name = nullptr;
    FMI_LOADER_FMI3_COMMON(FMI_LOADER_FIELD)
    FMI_LOADER_FMI3_MODEL_EXCHANGE(FMI_LOADER_FIELD)
    FMI_LOADER_FMI3_CO_SIMULATION(FMI_LOADER_FIELD)
#undef FMI_LOADER_FIELD
};

class Fmi3Library {
public:
    // dlopen(RTLD_NOW | RTLD_LOCAL) `shared_object` and resolve the functions: the required common
    // ones always, the required Model Exchange ones when `model_exchange`, the Co-Simulation ones when
    // `co_simulation`. Throws LoaderError (dl_open, or missing_symbol listing every missing required
    // name). Missing names that were not required stay null and are listed by missing_symbols().
    Fmi3Library(const std::filesystem::path& shared_object, bool model_exchange, bool co_simulation);
    ~Fmi3Library();
    Fmi3Library(const Fmi3Library&) = delete;
    Fmi3Library& operator=(const Fmi3Library&) = delete;

    const Fmi3Functions& functions() const noexcept { return functions_; }
    const Fmi3Functions* operator->() const noexcept { return &functions_; }
    const std::vector<std::string>& missing_symbols() const noexcept { return missing_; }
    const std::filesystem::path& path() const noexcept { return path_; }

    // binaries/x86_64-linux/<modelIdentifier>.so below an unpacked FMU (FMI 3.0.2 section 2.5.1.1).
    static std::filesystem::path binary_path(const std::filesystem::path& fmu_root,
                                             const std::string& model_identifier);

private:
    std::filesystem::path path_;
    void* handle_ = nullptr;
    Fmi3Functions functions_;
    std::vector<std::string> missing_;
};

}  // namespace fmi_loader
