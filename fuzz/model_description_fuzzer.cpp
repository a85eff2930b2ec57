// modelDescription.xml reader: any bytes give a ModelDescription or a LoaderError, nothing else.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fmi_loader/loader_error.hpp"
#include "fmi_loader/model_description.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        const auto md =
            fmi_loader::parse_model_description(std::string_view(reinterpret_cast<const char*>(data), size), "<fuzz>");
        // What users of a description do with it: look variables up, read start values.
        for (const auto& v : md.model_variables) {
            (void)md.find_variable(v.name);
            (void)v.start_as_real();
            (void)v.start_as_boolean();
        }
        for (const auto* list : {&md.model_structure.outputs, &md.model_structure.derivatives})
            for (const auto& u : *list) (void)md.model_variables.at(u.index - 1);
    } catch (const fmi_loader::LoaderError&) {}
    return 0;
}
