#include "description_xml.hpp"

#include <memory>
#include <set>
#include <utility>

#include "../src/instance.hpp"  // the log categories the runtime declares
#include "fmu/description.hpp"
#include "fmu/errors.hpp"
#include "fmu/units.hpp"
#include "xml_writer.hpp"

namespace fmu {

namespace {

// with_dependencies: Outputs and Derivatives (Variable::dependencies), else InitialUnknowns
// (Variable::initial_dependencies); either only where declared.
void write_unknowns(Writer& w, const char* element, const std::vector<std::size_t>& indices,
                    const std::vector<Variable>& vars, bool with_dependencies) {
    if (indices.empty()) return;
    w.start(element);
    for (auto i : indices) {
        w.start("Unknown");
        w.attribute("index", static_cast<int>(i + 1));
        const auto& deps = with_dependencies ? vars[i].dependencies : vars[i].initial_dependencies;
        if (deps) {
            std::string list;
            for (auto d : *deps) list += (list.empty() ? "" : " ") + std::to_string(d + 1);
            w.attribute("dependencies", list);
        }
        w.end();
    }
    w.end();
}

}  // namespace

std::string model_description_xml(const Model& model) {
    const auto& info = model.info();
    const auto& vars = model.table().variables();
    auto defaults = model.clone();
    defaults->reset_to_defaults();
    const auto default_bytes = std::as_const(*defaults).bytes();

    Writer w;
    w.start("fmiModelDescription");
    w.attribute("fmiVersion", "2.0");
    w.attribute("modelName", info.model_name);
    w.attribute("guid", description_guid(model));
    w.attribute("description", info.description);
    w.attribute("author", info.author);
    w.attribute("version", info.version);
    w.attribute("license", info.license);
    w.attribute("generationTool", "pv_attitude_fmi fmus runtime");
    w.attribute("variableNamingConvention", "structured");
    w.attribute("numberOfEventIndicators", static_cast<int>(model.event_indicator_count()));

    w.start("ModelExchange");
    w.attribute("modelIdentifier", info.model_identifier);
    w.attribute("completedIntegratorStepNotNeeded", "true");
    w.attribute("canNotUseMemoryManagementFunctions", "true");
    w.attribute("canGetAndSetFMUstate", "true");
    w.attribute("canSerializeFMUstate", "true");
    w.attribute("providesDirectionalDerivative", "false");
    w.end();
    w.start("CoSimulation");
    w.attribute("modelIdentifier", info.model_identifier);
    w.attribute("canHandleVariableCommunicationStepSize", "true");
    w.attribute("canInterpolateInputs", "true");  // linearly: fmi2SetRealInputDerivatives of order 1
    w.attribute("maxOutputDerivativeOrder", "0");
    w.attribute("canRunAsynchronuously", "false");  // the standard's spelling
    w.attribute("canNotUseMemoryManagementFunctions", "true");
    w.attribute("canGetAndSetFMUstate", "true");
    w.attribute("canSerializeFMUstate", "true");
    w.attribute("providesDirectionalDerivative", "false");
    w.end();

    write_unit_definitions(w, vars);

    // Each choice's items, as a type its Enumeration variable declares (FMI 2.0 section 2.2.3).
    bool any_choice = false;
    for (const auto& v : vars) any_choice = any_choice || v.type == ValueType::Enumeration;
    if (any_choice) {
        w.start("TypeDefinitions");
        for (const auto& v : vars) {
            if (v.type != ValueType::Enumeration) continue;
            w.start("SimpleType");
            w.attribute("name", v.declared_type);
            w.start("Enumeration");
            write_items(w, v.items);
            w.end();
            w.end();
        }
        w.end();
    }

    write_log_categories(w, log_categories, log_category_descriptions);
    write_default_experiment(w, info.default_experiment);

    w.start("ModelVariables");
    for (std::size_t i = 0; i < vars.size(); ++i) {
        const auto& v = vars[i];
        w.start("ScalarVariable");
        w.attribute("name", v.name);
        w.attribute("valueReference", std::to_string(v.value_reference));
        w.attribute("description", v.description);
        w.attribute("causality", std::string(to_string(v.causality)));
        w.attribute("variability", std::string(to_string(v.variability)));
        if (v.initial != Initial::none) w.attribute("initial", std::string(to_string(v.initial)));
        w.start(std::string(to_string(v.type)).c_str());
        if (v.type == ValueType::Enumeration) w.attribute("declaredType", v.declared_type);
        if (v.type == ValueType::Real && !v.unit.empty()) w.attribute("unit", v.unit);
        if (v.has_start()) w.attribute("start", start_text(v, default_bytes));
        if (v.type == ValueType::Real || v.type == ValueType::Integer) {
            auto bound = [&](double x) {
                return v.type == ValueType::Real ? format_real(x) : std::to_string(static_cast<long long>(x));
            };
            if (v.min) w.attribute("min", bound(*v.min));
            if (v.max) w.attribute("max", bound(*v.max));
        }
        if (v.type == ValueType::Real && v.nominal) w.attribute("nominal", format_real(*v.nominal));
        if (v.derivative_of) w.attribute("derivative", static_cast<int>(*v.derivative_of + 1));
        w.end();
        w.end();
    }
    w.end();

    std::vector<std::size_t> outputs, initial_unknowns;
    for (std::size_t i = 0; i < vars.size(); ++i) {
        const auto& v = vars[i];
        if (v.causality == Causality::output) outputs.push_back(i);
        if (is_initial_unknown(v)) initial_unknowns.push_back(i);  // in index order
    }
    w.start("ModelStructure");
    write_unknowns(w, "Outputs", outputs, vars, true);
    write_unknowns(w, "Derivatives", model.table().derivatives(), vars, true);
    write_unknowns(w, "InitialUnknowns", initial_unknowns, vars, false);
    w.end();

    w.end();
    return w.finish();
}

}  // namespace fmu
