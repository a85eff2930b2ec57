// dlsym into a typed slot, recording the name when it is missing: shared by the FMI 2.0 and 3.0
// libraries. Internal to the loader.
#pragma once

#include <dlfcn.h>

#include <string>
#include <vector>

namespace fmi_loader::detail {

template <class Fn>
void resolve(void* handle, const char* name, Fn*& slot, bool required, std::vector<std::string>& missing,
             std::vector<std::string>& missing_required) {
    dlerror();
    void* symbol = dlsym(handle, name);
    if (!symbol) {
        missing.emplace_back(name);
        if (required) missing_required.emplace_back(name);
        return;
    }
    // POSIX guarantees object-to-function pointer conversion for dlsym results.
    slot = reinterpret_cast<Fn*>(symbol);
}

}  // namespace fmi_loader::detail
