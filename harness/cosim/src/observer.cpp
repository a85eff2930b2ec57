#include "observer.hpp"

#include "cosim_error.hpp"
#include "value_text.hpp"

namespace cosim {

CsvWriter::CsvWriter(const std::filesystem::path& file, const System& system, const std::vector<std::string>& columns)
    : out_(file) {
    if (!out_) throw CosimError("cannot write " + file.string());
    const auto& comps = system.components();
    if (columns.empty()) {
        for (std::size_t i = 0; i < comps.size(); ++i)
            for (const auto& v : comps[i].description().model_variables)
                if (v.causality == fmi_loader::Causality::output) columns_.push_back({i, &v});
    } else {
        for (const auto& name : columns) {
            const auto dot = name.find('.');
            if (dot == std::string::npos) throw CosimError("--columns expects component.variable, got '" + name + "'");
            const std::size_t i = system.component_index(name.substr(0, dot));
            const auto* v = comps[i].description().find_variable(name.substr(dot + 1));
            if (!v) throw CosimError("no variable '" + name.substr(dot + 1) + "' in component '" + comps[i].name + "'");
            columns_.push_back({i, v});
        }
    }
    out_ << "time";
    for (const auto& c : columns_) out_ << "," << comps[c.component].name << "." << c.variable->name;
    out_ << "\n";
}

void CsvWriter::sample(double t, System& system) {
    out_ << format_real(t);
    for (const auto& c : columns_) out_ << "," << system.components()[c.component].instance->get_as_text(*c.variable);
    out_ << "\n";
}

}  // namespace cosim
