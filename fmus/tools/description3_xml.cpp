#include "description3_xml.hpp"

#include <algorithm>
#include <set>
#include <utility>
#include <vector>

#include "../src/instance.hpp"  // the log categories the runtime declares
#include "fmi/vocabulary.hpp"
#include "fmu/description.hpp"
#include "fmu/errors.hpp"
#include "fmu/fmi3_view.hpp"
#include "xml_writer.hpp"

namespace fmu {

namespace {

std::string join(const std::vector<std::string>& words) {
    std::string text;
    for (const auto& w : words) text += (text.empty() ? "" : " ") + w;
    return text;
}

// The FMI 3.0 value references of the variables the table's element indices belong to, each once, in
// increasing order; `also` adds one more (the independent variable).
std::string references_of(const Fmi3View& view, const std::vector<std::size_t>& indices,
                          std::optional<std::uint32_t> also) {
    std::set<std::uint32_t> refs;
    for (auto i : indices) refs.insert(view.owner(i).value_reference);
    if (also) refs.insert(*also);
    std::vector<std::string> words;
    for (auto r : refs) words.push_back(std::to_string(r));
    return join(words);
}

// The union of a property over an array's elements: FMI 3.0 states dependencies per variable.
std::optional<std::vector<std::size_t>> merged(const std::vector<Variable>& vars, const Fmi3Variable& v, bool initial) {
    std::vector<std::size_t> all;
    for (std::size_t i = v.first; i < v.first + v.count; ++i) {
        const auto& deps = initial ? vars[i].initial_dependencies : vars[i].dependencies;
        if (!deps) return std::nullopt;  // one element may depend on every known: so may the variable
        all.insert(all.end(), deps->begin(), deps->end());
    }
    return all;
}

void write_variable(Writer& w, const Fmi3View& view, const std::vector<Variable>& vars, const Fmi3Variable& fv,
                    std::span<const std::byte> defaults) {
    const Variable& v = vars[fv.first];
    const std::string element(fmi_vocabulary::spelling(fmi_vocabulary::types_fmi3, v.type));
    w.start(element.c_str());
    w.attribute("name", fv.array ? v.base_name : v.name);
    w.attribute("valueReference", std::to_string(fv.value_reference));
    w.attribute("description", v.description);
    w.attribute("causality", std::string(to_string(v.causality)));
    w.attribute("variability", std::string(to_string(v.variability)));
    if (v.initial != Initial::none) w.attribute("initial", std::string(to_string(v.initial)));
    if (v.type == ValueType::Enumeration) w.attribute("declaredType", v.declared_type);
    if (v.type == ValueType::Real && !v.unit.empty()) w.attribute("unit", v.unit);
    if (v.type == ValueType::Real || v.type == ValueType::Integer) {
        auto bound = [&](double x) {
            return v.type == ValueType::Real ? format_real(x) : std::to_string(static_cast<long long>(x));
        };
        if (v.min) w.attribute("min", bound(*v.min));
        if (v.max) w.attribute("max", bound(*v.max));
    }
    if (v.type == ValueType::Real && v.nominal) w.attribute("nominal", format_real(*v.nominal));
    std::vector<std::string> starts;
    if (v.has_start())
        for (std::size_t i = fv.first; i < fv.first + fv.count; ++i) starts.push_back(start_text(vars[i], defaults));
    // A String's start values are elements (FMI 3.0 section 2.4.7.6), the others' an attribute list.
    if (v.has_start() && v.type != ValueType::String) w.attribute("start", join(starts));
    if (v.derivative_of) w.attribute("derivative", std::to_string(view.owner(*v.derivative_of).value_reference));
    if (v.has_start() && v.type == ValueType::String)
        for (const auto& s : starts) {
            w.start("Start");
            w.attribute("value", s);
            w.end();
        }
    if (fv.array) {
        w.start("Dimension");
        w.attribute("start", std::to_string(fv.count));
        w.end();
    }
    w.end();
}

}  // namespace

std::string model_description3_xml(const Model& model) {
    const auto& info = model.info();
    const auto& vars = model.table().variables();
    const Fmi3View view(model.table(), model.event_indicator_count());
    auto defaults = model.clone();
    defaults->reset_to_defaults();
    const auto default_bytes = std::as_const(*defaults).bytes();
    for (const auto& v : view.variables())
        if (vars[v.first].base_name == "time" || vars[v.first].base_name == "event_indicators")
            throw Error("FMI 3.0: the name '" + vars[v.first].base_name +
                        "' is the FMI 3.0 description's own (independent variable, event indicators)");

    Writer w;
    w.start("fmiModelDescription");
    w.attribute("fmiVersion", "3.0");
    w.attribute("modelName", info.model_name);
    w.attribute("instantiationToken", description_guid(model));
    w.attribute("description", info.description);
    w.attribute("author", info.author);
    w.attribute("version", info.version);
    w.attribute("license", info.license);
    w.attribute("generationTool", "pv_attitude_fmi fmus runtime");
    w.attribute("variableNamingConvention", "structured");

    w.start("ModelExchange");
    w.attribute("modelIdentifier", info.model_identifier);
    w.attribute("needsCompletedIntegratorStep", "false");
    w.attribute("canGetAndSetFMUState", "true");
    w.attribute("canSerializeFMUState", "true");
    w.attribute("providesDirectionalDerivatives", "false");
    w.attribute("providesAdjointDerivatives", "false");
    w.end();
    w.start("CoSimulation");
    w.attribute("modelIdentifier", info.model_identifier);
    w.attribute("canGetAndSetFMUState", "true");
    w.attribute("canSerializeFMUState", "true");
    w.attribute("providesDirectionalDerivatives", "false");
    w.attribute("providesAdjointDerivatives", "false");
    w.attribute("canHandleVariableCommunicationStepSize", "true");
    w.attribute("maxOutputDerivativeOrder", "0");
    // Event mode and early return: a host that runs the events itself steps from event to event, the
    // FMU stopping at each (its time events, its located state events).
    w.attribute("hasEventMode", "true");
    w.attribute("mightReturnEarlyFromDoStep", "true");
    // With an intermediate-update callback the host is asked at each event whether the step should
    // end there; no variable is readable or writable in Intermediate Update Mode.
    w.attribute("providesIntermediateUpdate", "true");
    w.attribute("canReturnEarlyAfterIntermediateUpdate", "true");
    w.end();

    write_unit_definitions(w, vars, {"s"});

    bool any_choice = false;
    for (const auto& v : vars) any_choice = any_choice || v.type == ValueType::Enumeration;
    if (any_choice) {
        w.start("TypeDefinitions");
        for (const auto& v : vars) {
            if (v.type != ValueType::Enumeration) continue;
            w.start("EnumerationType");
            w.attribute("name", v.declared_type);
            write_items(w, v.items);
            w.end();
        }
        w.end();
    }

    write_log_categories(w, log_categories, log_category_descriptions);
    write_default_experiment(w, info.default_experiment);

    w.start("ModelVariables");
    w.start("Float64");
    w.attribute("name", "time");
    w.attribute("valueReference", std::to_string(view.time_reference()));
    w.attribute("description", "Simulation time");
    w.attribute("causality", "independent");
    w.attribute("variability", "continuous");
    w.attribute("unit", "s");
    w.end();
    for (const auto& fv : view.variables()) write_variable(w, view, vars, fv, default_bytes);
    if (view.event_indicator_count() > 0) {
        w.start("Float64");
        w.attribute("name", "event_indicators");
        w.attribute("valueReference", std::to_string(view.event_indicators_reference()));
        w.attribute("description", "The block's zero-crossing functions: an event where one changes sign");
        w.attribute("causality", "local");
        w.attribute("variability", "continuous");
        w.start("Dimension");
        w.attribute("start", std::to_string(view.event_indicator_count()));
        w.end();
        w.end();
    }
    w.end();

    // Per variable, in value-reference order: Output, ContinuousStateDerivative, InitialUnknown,
    // EventIndicator (the schema's order). An output or derivative may depend on time besides what
    // the table declares (the FMI 2.0 description had no time variable to name).
    w.start("ModelStructure");
    auto unknowns = [&](const char* element, auto&& selected, bool initial) {
        for (const auto& fv : view.variables()) {
            if (!selected(vars[fv.first])) continue;
            w.start(element);
            w.attribute("valueReference", std::to_string(fv.value_reference));
            if (const auto deps = merged(vars, fv, initial))
                w.attribute("dependencies",
                            references_of(view, *deps, initial ? std::nullopt : std::optional(view.time_reference())));
            w.end();
        }
    };
    unknowns(
        "Output", [](const Variable& v) { return v.causality == Causality::output; }, false);
    unknowns(
        "ContinuousStateDerivative", [](const Variable& v) { return v.is_derivative(); }, false);
    unknowns(
        "InitialUnknown", [](const Variable& v) { return is_initial_unknown(v); }, true);
    if (view.event_indicator_count() > 0) {
        w.start("EventIndicator");
        w.attribute("valueReference", std::to_string(view.event_indicators_reference()));
        w.end();
    }
    w.end();

    w.end();
    return w.finish();
}

}  // namespace fmu
