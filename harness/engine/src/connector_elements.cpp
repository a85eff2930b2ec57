#include "connector_elements.hpp"

namespace cosim {

std::vector<const fmi_loader::ScalarVariable*> connector_elements(const fmi_loader::ModelDescription& md,
                                                                  const std::string& name) {
    if (const auto* v = md.find_variable(name)) return {v};
    std::vector<const fmi_loader::ScalarVariable*> out;
    if (!md.is_fmi3()) return out;  // FMI 2.0 has no arrays; "x[1]" there is only a name
    const std::string prefix = name + "[";
    for (const auto& v : md.model_variables)
        if (v.name.size() > prefix.size() && v.name.compare(0, prefix.size(), prefix) == 0 &&
            v.name.find('[', prefix.size()) == std::string::npos)
            out.push_back(&v);
    return out;
}

}  // namespace cosim
