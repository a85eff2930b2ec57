#include "fmi_loader/fmi2_library.hpp"

#include <dlfcn.h>

#include "fmi_loader/loader_error.hpp"
#include "resolve_symbol.hpp"

namespace fmi_loader {

std::filesystem::path Fmi2Library::binary_path(const std::filesystem::path& fmu_root,
                                               const std::string& model_identifier) {
    return fmu_root / "binaries" / "linux64" / (model_identifier + ".so");
}

Fmi2Library::Fmi2Library(const std::filesystem::path& shared_object, bool model_exchange, bool co_simulation)
    : path_(shared_object) {
    // RTLD_LOCAL: two FMUs exporting the same fmi2* names must not bind to each other.
    handle_ = dlopen(shared_object.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle_) {
        const char* why = dlerror();
        throw LoaderError(LoaderErrc::dl_open, "'" + shared_object.string() + "': " + (why ? why : "dlopen failed"));
    }
    std::vector<std::string> missing_required;
    auto& f = functions_;
#define FMI_LOADER_RESOLVE(name, needed) detail::resolve(handle_, #name, f.name, needed, missing_, missing_required)
    const bool common = true;
    FMI_LOADER_RESOLVE(fmi2GetTypesPlatform, common);
    FMI_LOADER_RESOLVE(fmi2GetVersion, common);
    FMI_LOADER_RESOLVE(fmi2SetDebugLogging, common);
    FMI_LOADER_RESOLVE(fmi2Instantiate, common);
    FMI_LOADER_RESOLVE(fmi2FreeInstance, common);
    FMI_LOADER_RESOLVE(fmi2SetupExperiment, common);
    FMI_LOADER_RESOLVE(fmi2EnterInitializationMode, common);
    FMI_LOADER_RESOLVE(fmi2ExitInitializationMode, common);
    FMI_LOADER_RESOLVE(fmi2Terminate, common);
    FMI_LOADER_RESOLVE(fmi2Reset, common);
    FMI_LOADER_RESOLVE(fmi2GetReal, common);
    FMI_LOADER_RESOLVE(fmi2GetInteger, common);
    FMI_LOADER_RESOLVE(fmi2GetBoolean, common);
    FMI_LOADER_RESOLVE(fmi2GetString, common);
    FMI_LOADER_RESOLVE(fmi2SetReal, common);
    FMI_LOADER_RESOLVE(fmi2SetInteger, common);
    FMI_LOADER_RESOLVE(fmi2SetBoolean, common);
    FMI_LOADER_RESOLVE(fmi2SetString, common);
    FMI_LOADER_RESOLVE(fmi2GetFMUstate, common);
    FMI_LOADER_RESOLVE(fmi2SetFMUstate, common);
    FMI_LOADER_RESOLVE(fmi2FreeFMUstate, common);
    FMI_LOADER_RESOLVE(fmi2SerializedFMUstateSize, common);
    FMI_LOADER_RESOLVE(fmi2SerializeFMUstate, common);
    FMI_LOADER_RESOLVE(fmi2DeSerializeFMUstate, common);
    FMI_LOADER_RESOLVE(fmi2GetDirectionalDerivative, common);

    FMI_LOADER_RESOLVE(fmi2EnterEventMode, model_exchange);
    FMI_LOADER_RESOLVE(fmi2NewDiscreteStates, model_exchange);
    FMI_LOADER_RESOLVE(fmi2EnterContinuousTimeMode, model_exchange);
    FMI_LOADER_RESOLVE(fmi2CompletedIntegratorStep, model_exchange);
    FMI_LOADER_RESOLVE(fmi2SetTime, model_exchange);
    FMI_LOADER_RESOLVE(fmi2SetContinuousStates, model_exchange);
    FMI_LOADER_RESOLVE(fmi2GetDerivatives, model_exchange);
    FMI_LOADER_RESOLVE(fmi2GetEventIndicators, model_exchange);
    FMI_LOADER_RESOLVE(fmi2GetContinuousStates, model_exchange);
    FMI_LOADER_RESOLVE(fmi2GetNominalsOfContinuousStates, model_exchange);

    FMI_LOADER_RESOLVE(fmi2SetRealInputDerivatives, co_simulation);
    FMI_LOADER_RESOLVE(fmi2GetRealOutputDerivatives, co_simulation);
    FMI_LOADER_RESOLVE(fmi2DoStep, co_simulation);
    FMI_LOADER_RESOLVE(fmi2CancelStep, co_simulation);
    FMI_LOADER_RESOLVE(fmi2GetStatus, co_simulation);
    FMI_LOADER_RESOLVE(fmi2GetRealStatus, co_simulation);
    FMI_LOADER_RESOLVE(fmi2GetIntegerStatus, co_simulation);
    FMI_LOADER_RESOLVE(fmi2GetBooleanStatus, co_simulation);
    FMI_LOADER_RESOLVE(fmi2GetStringStatus, co_simulation);
#undef FMI_LOADER_RESOLVE

    if (!missing_required.empty()) {
        std::string list;
        for (const auto& name : missing_required) list += (list.empty() ? "" : ", ") + name;
        dlclose(handle_);
        throw LoaderError(LoaderErrc::missing_symbol, "'" + shared_object.string() + "' does not export: " + list);
    }
}

Fmi2Library::~Fmi2Library() {
    if (handle_) dlclose(handle_);
}

}  // namespace fmi_loader
