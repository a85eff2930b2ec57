#include "fmi_loader/fmi3_library.hpp"

#include <dlfcn.h>

#include "fmi_loader/loader_error.hpp"
#include "resolve_symbol.hpp"

namespace fmi_loader {

std::filesystem::path Fmi3Library::binary_path(const std::filesystem::path& fmu_root,
                                               const std::string& model_identifier) {
    return fmu_root / "binaries" / "x86_64-linux" / (model_identifier + ".so");
}

Fmi3Library::Fmi3Library(const std::filesystem::path& shared_object, bool model_exchange, bool co_simulation)
    : path_(shared_object) {
    // RTLD_LOCAL: two FMUs exporting the same fmi3* names must not bind to each other.
    handle_ = dlopen(shared_object.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle_) {
        const char* why = dlerror();
        throw LoaderError(LoaderErrc::dl_open, "'" + shared_object.string() + "': " + (why ? why : "dlopen failed"));
    }
    std::vector<std::string> missing_required;
    auto& f = functions_;
    bool group = true;
#define FMI_LOADER_RESOLVE(name, required) \
    detail::resolve(handle_, #name, f.name, group && (required), missing_, missing_required);
    FMI_LOADER_FMI3_COMMON(FMI_LOADER_RESOLVE)
    group = model_exchange;
    FMI_LOADER_FMI3_MODEL_EXCHANGE(FMI_LOADER_RESOLVE)
    group = co_simulation;
    FMI_LOADER_FMI3_CO_SIMULATION(FMI_LOADER_RESOLVE)
#undef FMI_LOADER_RESOLVE

    if (!missing_required.empty()) {
        std::string list;
        for (const auto& name : missing_required) list += (list.empty() ? "" : ", ") + name;
        dlclose(handle_);
        throw LoaderError(LoaderErrc::missing_symbol, "'" + shared_object.string() + "' does not export: " + list);
    }
}

Fmi3Library::~Fmi3Library() {
    if (handle_) dlclose(handle_);
}

}  // namespace fmi_loader
