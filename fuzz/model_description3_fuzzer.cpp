// FMI 3.0 modelDescription.xml reader and what the master builds on it: any bytes give a description
// or a LoaderError, nothing else. Beyond the FMI 2.0 target (model_description_fuzzer.cpp), the 3.0
// parts: array sizes from <Dimension> and structural parameters (products, starts like "1e30"), the
// scalar view of the arrays' elements, and the master's check of features it does not run.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "engine/cosim_error.hpp"
#include "engine/fmi3_instance.hpp"
#include "fmi_loader/limits.hpp"
#include "fmi_loader/loader_error.hpp"
#include "fmi_loader/model_description.hpp"
#include "fmi_loader/scalar_view.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    // A lower element limit than the default million: the reader's limit is what is under test, and a
    // million copied elements per input would make the fuzzer slow, not find more.
    fmi_loader::Limits limits;
    limits.max_variables = 20'000;
    limits.max_event_indicators = 20'000;
    try {
        const auto md = fmi_loader::parse_model_description(std::string_view(reinterpret_cast<const char*>(data), size),
                                                            "<fuzz>", limits);
        if (!md.is_fmi3()) return 0;  // the FMI 2.0 target covers those
        std::size_t elements = 0;
        for (const auto& v : md.model_variables) {
            elements += md.element_count(v);
            (void)md.extents(v);
        }
        // Each element a variable of its own, as the master sees an FMI 3.0 FMU (bounded by max_variables).
        const auto view = fmi_loader::scalar_view(md, limits);
        if (view.description.model_variables.size() != elements) __builtin_trap();
        cosim::refuse_unsupported_fmi3(md, "fuzz");
    } catch (const fmi_loader::LoaderError&) {
    } catch (const cosim::CosimError&) {}
    return 0;
}
