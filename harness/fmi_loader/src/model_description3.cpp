// The FMI 3.0 modelDescription.xml (FMI 3.0.2 standard, section 2.4; Model Exchange 3.4, Co-Simulation
// 4.4, Scheduled Execution 5.4) read into the loader's ModelDescription. Where FMI 3.0 names things by
// value reference (ModelStructure, derivative, Dimension), the model keeps FMI 2.0's 1-based indices
// into model_variables, so one set of users serves both versions.
#include <array>
#include <utility>

#include "description_reader.hpp"

namespace fmi_loader::detail {

namespace {

constexpr std::array<std::pair<const char*, Fmi3Type>, 15> type_elements{{
    {"Float32", Fmi3Type::float32},
    {"Float64", Fmi3Type::float64},
    {"Int8", Fmi3Type::int8},
    {"UInt8", Fmi3Type::uint8},
    {"Int16", Fmi3Type::int16},
    {"UInt16", Fmi3Type::uint16},
    {"Int32", Fmi3Type::int32},
    {"UInt32", Fmi3Type::uint32},
    {"Int64", Fmi3Type::int64},
    {"UInt64", Fmi3Type::uint64},
    {"Boolean", Fmi3Type::boolean},
    {"String", Fmi3Type::string},
    {"Binary", Fmi3Type::binary},
    {"Enumeration", Fmi3Type::enumeration},
    {"Clock", Fmi3Type::clock},
}};

// A variable element (<Float64 .../>) or, with suffix "Type", a TypeDefinitions element.
std::optional<Fmi3Type> fmi3_type_of(const xmlNode* n, std::string_view suffix = "") {
    if (n->type != XML_ELEMENT_NODE) return std::nullopt;
    const std::string_view name(reinterpret_cast<const char*>(n->name));
    for (const auto& [element, type] : type_elements) {
        const std::string_view e(element);
        if (name.size() == e.size() + suffix.size() && name.starts_with(e) && name.ends_with(suffix)) return type;
    }
    return std::nullopt;
}

bool is_float(Fmi3Type t) {
    return t == Fmi3Type::float32 || t == Fmi3Type::float64;
}

}  // namespace

ModelDescription Reader::read3(const xmlNode* root) const {
    fmi3_ = true;
    ModelDescription md;
    md.fmi_version = required(root, "fmiVersion");
    md.model_name = required(root, "modelName");
    md.guid = required(root, "instantiationToken");
    md.description = text(root, "description");
    md.author = text(root, "author");
    md.version = text(root, "version");
    md.generation_tool = text(root, "generationTool");
    md.variable_naming_convention = attr(root, "variableNamingConvention").value_or("flat");
    if (md.variable_naming_convention != "flat" && md.variable_naming_convention != "structured")
        invalid(root, "unknown variableNamingConvention '" + md.variable_naming_convention + "'");

    // Types first, variables next, the structure last: each refers to the ones before.
    for (const xmlNode* n = root->children; n; n = n->next) {
        if (is(n, "UnitDefinitions"))
            unit_definitions(n, md);
        else if (is(n, "TypeDefinitions"))
            type_definitions3(n, md);
        else if (is(n, "ModelExchange") || is(n, "CoSimulation") || is(n, "ScheduledExecution"))
            interfaces3(n, md);
        else if (is(n, "LogCategories")) {
            for (const xmlNode* c = n->children; c; c = c->next)
                if (is(c, "Category")) md.log_categories.push_back({required(c, "name"), text(c, "description")});
        } else if (is(n, "DefaultExperiment"))
            md.default_experiment =
                DefaultExperiment{real(n, "startTime"), real(n, "stopTime"), real(n, "tolerance"), real(n, "stepSize")};
    }
    for (const xmlNode* n = root->children; n; n = n->next) {
        if (!is(n, "ModelVariables")) continue;
        for (const xmlNode* c = n->children; c; c = c->next) {
            if (c->type != XML_ELEMENT_NODE) continue;
            const auto type = fmi3_type_of(c);
            if (!type)
                invalid(c, std::string("unknown variable element <") + reinterpret_cast<const char*>(c->name) + ">");
            add_variable(md, variable3(c, *type, md));
        }
    }
    if (!md.model_exchange && !md.co_simulation && !md.scheduled_execution)
        invalid(root, "none of <ModelExchange>, <CoSimulation>, <ScheduledExecution> is declared");
    check3(root, md);
    for (const xmlNode* n = root->children; n; n = n->next) {
        if (!is(n, "ModelStructure")) continue;
        auto& s = md.model_structure;
        s.outputs = unknowns3(n, "Output", md);
        s.derivatives = unknowns3(n, "ContinuousStateDerivative", md);
        s.clocked_states = unknowns3(n, "ClockedState", md);
        s.initial_unknowns = unknowns3(n, "InitialUnknown", md);
        s.event_indicators = unknowns3(n, "EventIndicator", md);
    }
    // FMI 3.0 has no numberOfEventIndicators: the EventIndicator elements are the list.
    std::size_t indicators = 0;
    for (const auto& u : md.model_structure.event_indicators)
        indicators += md.element_count(md.model_variables[u.index - 1]);
    if (indicators > limits_.max_event_indicators)
        throw LoaderError(LoaderErrc::limit, "'" + source_ + "': " + std::to_string(indicators) +
                                                 " event indicators, more than the limit of " +
                                                 std::to_string(limits_.max_event_indicators) +
                                                 " (max_event_indicators)");
    md.number_of_event_indicators = indicators;
    for (const auto& u : md.model_structure.derivatives)
        if (!md.model_variables[u.index - 1].derivative)
            invalid(root, "ContinuousStateDerivative '" + shorten(md.model_variables[u.index - 1].name) +
                              "' has no derivative attribute naming its state");
    return md;
}

void Reader::interfaces3(const xmlNode* n, ModelDescription& md) const {
    const std::string id = required(n, "modelIdentifier");
    check_model_identifier(n, id);
    if (is(n, "ScheduledExecution")) {
        md.scheduled_execution = ScheduledExecutionInfo{id};
        return;
    }
    // Attributes both interfaces have (fmi3InterfaceType.xsd); note FMI 3.0's spelling "FMUState".
    const bool needs_tool = boolean(n, "needsExecutionTool", false);
    const bool once = boolean(n, "canBeInstantiatedOnlyOncePerProcess", false);
    const bool get_set = boolean(n, "canGetAndSetFMUState", false);
    const bool serialize = boolean(n, "canSerializeFMUState", false);
    const bool directional = boolean(n, "providesDirectionalDerivatives", false);
    const bool evaluate = boolean(n, "providesEvaluateDiscreteStates", false);
    if (is(n, "ModelExchange")) {
        ModelExchangeInfo me;
        me.model_identifier = id;
        me.needs_execution_tool = needs_tool;
        me.completed_integrator_step_not_needed = !boolean(n, "needsCompletedIntegratorStep", false);
        me.can_be_instantiated_only_once_per_process = once;
        me.can_get_and_set_fmu_state = get_set;
        me.can_serialize_fmu_state = serialize;
        me.provides_directional_derivative = directional;
        me.provides_evaluate_discrete_states = evaluate;
        md.model_exchange = me;
        return;
    }
    CoSimulationInfo cs;
    cs.model_identifier = id;
    cs.needs_execution_tool = needs_tool;
    cs.can_be_instantiated_only_once_per_process = once;
    cs.can_get_and_set_fmu_state = get_set;
    cs.can_serialize_fmu_state = serialize;
    cs.provides_directional_derivative = directional;
    cs.provides_evaluate_discrete_states = evaluate;
    cs.can_handle_variable_communication_step_size = boolean(n, "canHandleVariableCommunicationStepSize", false);
    cs.fixed_internal_step_size = real(n, "fixedInternalStepSize");
    cs.max_output_derivative_order = static_cast<int>(integer(n, "maxOutputDerivativeOrder").value_or(0));
    cs.recommended_intermediate_input_smoothness =
        static_cast<int>(integer(n, "recommendedIntermediateInputSmoothness").value_or(0));
    cs.provides_intermediate_update = boolean(n, "providesIntermediateUpdate", false);
    cs.might_return_early_from_do_step = boolean(n, "mightReturnEarlyFromDoStep", false);
    cs.can_return_early_after_intermediate_update = boolean(n, "canReturnEarlyAfterIntermediateUpdate", false);
    cs.has_event_mode = boolean(n, "hasEventMode", false);
    md.co_simulation = cs;
}

void Reader::type_definitions3(const xmlNode* parent, ModelDescription& md) const {
    for (const xmlNode* n = parent->children; n; n = n->next) {
        const auto type = fmi3_type_of(n, "Type");
        if (!type) continue;
        SimpleType t;
        t.name = required(n, "name");
        t.description = text(n, "description");
        t.fmi3_type = *type;
        t.type = base_kind(*type);
        t.quantity = text(n, "quantity");
        t.unit = text(n, "unit");
        t.display_unit = text(n, "displayUnit");
        t.min = real(n, "min");
        t.max = real(n, "max");
        t.nominal = real(n, "nominal");
        for (const xmlNode* item = n->children; item; item = item->next) {
            if (!is(item, "Item")) continue;
            const auto value = integer(item, "value");
            if (!value) invalid(item, "Item lacks 'value'");
            t.items.push_back({required(item, "name"), *value, text(item, "description")});
        }
        md.type_definitions.push_back(std::move(t));
    }
}

ScalarVariable Reader::variable3(const xmlNode* n, Fmi3Type type, const ModelDescription& md) const {
    ScalarVariable v;
    v.name = required(n, "name");
    const auto vr = integer(n, "valueReference");
    if (!vr) invalid(n, "variable '" + shorten(v.name) + "' lacks 'valueReference'");
    if (*vr < 0 || *vr > 0xFFFFFFFFLL) invalid(n, "valueReference of '" + shorten(v.name) + "' out of range");
    v.value_reference = static_cast<std::uint32_t>(*vr);
    v.description = text(n, "description");
    v.fmi3_type = type;
    v.type = base_kind(type);
    v.causality = causality(n);
    // Section 2.4.7.4: parameters default to fixed, Float variables to continuous, the others to discrete.
    const bool parameter_like = v.causality == Causality::parameter || v.causality == Causality::calculated_parameter ||
                                v.causality == Causality::structural_parameter;
    if (attr(n, "variability"))
        v.variability = variability(n);
    else
        v.variability = parameter_like   ? Variability::fixed
                        : is_float(type) ? Variability::continuous
                                         : Variability::discrete;
    if (!is_valid_combination(v.causality, v.variability))
        invalid(n, "variable '" + shorten(v.name) + "': causality " + std::string(to_string(v.causality)) +
                       " with variability " + std::string(to_string(v.variability)) + " is not allowed");
    if (v.variability == Variability::continuous && !is_float(type))
        invalid(n, "variable '" + shorten(v.name) + "': only Float32 and Float64 may be continuous");
    v.can_handle_multiple_set_per_time_instant = boolean(n, "canHandleMultipleSetPerTimeInstant", true);
    v.intermediate_update = boolean(n, "intermediateUpdate", false);
    if (const auto p = integer(n, "previous")) v.previous = static_cast<std::uint32_t>(*p);
    if (const auto clocks = attr(n, "clocks"))
        for (const auto c : index_list(n, *clocks, 0)) v.clocks.push_back(static_cast<std::uint32_t>(c));
    const auto init = initial(n);
    v.initial_given = init.has_value();
    // The FMI 3.0 table gives inputs initial = exact (FMI 2.0: no initial).
    const Initial fallback =
        v.causality == Causality::input ? Initial::exact : default_initial(v.causality, v.variability);
    v.initial = init ? *init : fallback;

    v.declared_type = text(n, "declaredType");
    v.start = attr(n, "start");
    v.quantity = text(n, "quantity");
    v.unit = text(n, "unit");
    v.display_unit = text(n, "displayUnit");
    v.min = real(n, "min");
    v.max = real(n, "max");
    v.nominal = real(n, "nominal");
    v.relative_quantity = boolean(n, "relativeQuantity", false);
    v.reinit = boolean(n, "reinit", false);
    v.mime_type = attr(n, "mimeType").value_or(type == Fmi3Type::binary ? "application/octet-stream" : "");
    if (const auto size = integer(n, "maxSize")) {
        if (*size < 0) invalid(n, "maxSize of '" + shorten(v.name) + "' is negative");
        v.max_size = static_cast<std::uint64_t>(*size);
    }
    if (const auto d = integer(n, "derivative")) {
        if (*d < 0 || *d > 0xFFFFFFFFLL) invalid(n, "derivative of '" + shorten(v.name) + "' out of range");
        // Resolved to an index by check3 once every variable is known; the reference is kept meanwhile.
        v.derivative = static_cast<std::size_t>(*d);
    }
    for (const xmlNode* c = n->children; c; c = c->next) {
        if (is(c, "Dimension")) {
            Dimension d;
            if (const auto s = integer(c, "start")) {
                if (*s < 0) invalid(c, "Dimension start of '" + shorten(v.name) + "' is negative");
                d.start = static_cast<std::uint64_t>(*s);
            }
            if (const auto r = integer(c, "valueReference")) {
                if (*r < 0 || *r > 0xFFFFFFFFLL) invalid(c, "Dimension valueReference out of range");
                d.value_reference = static_cast<std::uint32_t>(*r);
            }
            if (d.start.has_value() == d.value_reference.has_value())
                invalid(c, "a Dimension of '" + shorten(v.name) + "' needs exactly one of start and valueReference");
            v.dimensions.push_back(d);
        } else if (is(c, "Start")) {
            if (type != Fmi3Type::string && type != Fmi3Type::binary)
                invalid(c, "<Start> elements belong to String and Binary variables, not '" + shorten(v.name) + "'");
            v.start_values.push_back(required(c, "value"));
        }
    }
    if (!v.start_values.empty()) v.start = v.start_values.front();
    if (!v.declared_type.empty()) {
        const SimpleType* t = md.find_type(v.declared_type);
        if (!t) invalid(n, "declaredType '" + v.declared_type + "' of '" + shorten(v.name) + "' is not defined");
        if (v.quantity.empty()) v.quantity = t->quantity;
        if (v.unit.empty()) v.unit = t->unit;
        if (v.display_unit.empty()) v.display_unit = t->display_unit;
        if (!v.min) v.min = t->min;
        if (!v.max) v.max = t->max;
        if (!v.nominal) v.nominal = t->nominal;
    } else if (type == Fmi3Type::enumeration) {
        invalid(n, "Enumeration '" + shorten(v.name) + "' lacks its declaredType");
    }
    return v;
}

std::size_t Reader::index_of_reference(const xmlNode* n, const ModelDescription& md, std::uint32_t vr) const {
    for (std::size_t i = 0; i < md.model_variables.size(); ++i)
        if (md.model_variables[i].value_reference == vr) return i + 1;
    invalid(n, "valueReference " + std::to_string(vr) + " names no variable");
}

std::vector<Unknown> Reader::unknowns3(const xmlNode* parent, const char* element, const ModelDescription& md) const {
    std::vector<Unknown> out;
    for (const xmlNode* u = parent->children; u; u = u->next) {
        if (!is(u, element)) continue;
        const auto vr = integer(u, "valueReference");
        if (!vr || *vr < 0 || *vr > 0xFFFFFFFFLL) invalid(u, std::string("<") + element + "> lacks a valueReference");
        Unknown unknown;
        unknown.index = index_of_reference(u, md, static_cast<std::uint32_t>(*vr));
        if (const auto deps = attr(u, "dependencies")) {
            std::vector<std::size_t> indices;
            for (const auto d : index_list(u, *deps, 0))
                indices.push_back(index_of_reference(u, md, static_cast<std::uint32_t>(d)));
            unknown.dependencies = std::move(indices);
        }
        if (const auto kinds = attr(u, "dependenciesKind")) {
            std::istringstream in(*kinds);
            std::string k;
            while (in >> k) {
                if (k != "dependent" && k != "constant" && k != "fixed" && k != "tunable" && k != "discrete")
                    invalid(u, "unknown dependenciesKind '" + shorten(k) + "'");
                unknown.dependencies_kind.push_back(k);
            }
        }
        out.push_back(std::move(unknown));
    }
    return out;
}

// Section 2.4.7: value references are unique across variables (aliases are <Alias> children, which
// this reader does not list), names are unique, Dimension references name a UInt64 structural
// parameter or constant, and `derivative` names a Float variable (turned here into its index).
void Reader::check3(const xmlNode* root, ModelDescription& md) const {
    std::map<std::string_view, std::size_t> names;
    std::map<std::uint32_t, std::size_t> references;
    for (std::size_t i = 0; i < md.model_variables.size(); ++i) {
        const auto& v = md.model_variables[i];
        if (const auto [it, fresh] = names.emplace(v.name, i); !fresh)
            invalid(root, "variable name '" + shorten(v.name) + "' is declared twice (variables " +
                              std::to_string(it->second + 1) + " and " + std::to_string(i + 1) + ")");
        if (const auto [it, fresh] = references.emplace(v.value_reference, i); !fresh)
            invalid(root, "variables '" + shorten(md.model_variables[it->second].name) + "' and '" + shorten(v.name) +
                              "' share valueReference " + std::to_string(v.value_reference) +
                              " (FMI 3.0 gives every variable its own)");
    }
    for (auto& v : md.model_variables) {
        // The array's size: every factor a whole UInt64, the product checked before it is taken, and no more
        // elements than a description may have variables (two sizes whose product wraps 64 bits, or a
        // start of "1e30", "abc" or "-5", would otherwise give an array of the wrong size).
        std::uint64_t elements = 1;
        for (const auto& d : v.dimensions) {
            std::uint64_t size = d.start.value_or(0);
            if (d.value_reference) {
                const auto it = references.find(*d.value_reference);
                const ScalarVariable* p = it == references.end() ? nullptr : &md.model_variables[it->second];
                if (!p || p->fmi3_type != Fmi3Type::uint64 ||
                    (p->causality != Causality::structural_parameter && p->variability != Variability::constant))
                    invalid(root, "a Dimension of '" + shorten(v.name) + "' refers to valueReference " +
                                      std::to_string(*d.value_reference) +
                                      ", which is not a UInt64 structural parameter or constant");
                const auto start = dimension_start(*p);
                if (!start)
                    invalid(root, "a Dimension of '" + shorten(v.name) + "' refers to '" + shorten(p->name) +
                                      "', whose start '" + shorten(p->start.value_or("")) +
                                      "' is not a whole number from 0 to 2^64 - 1 (a UInt64 array size)");
                size = *start;
            }
            if (size != 0 && elements > limits_.max_variables / size)
                throw LoaderError(LoaderErrc::limit,
                                  "'" + source_ + "': the array '" + shorten(v.name) + "' has more than the limit of " +
                                      std::to_string(limits_.max_variables) + " elements (max_variables)");
            elements *= size;
        }
        if (!v.derivative) continue;
        const auto it = references.find(static_cast<std::uint32_t>(*v.derivative));
        if (it == references.end() || !md.model_variables[it->second].fmi3_type ||
            !is_float(*md.model_variables[it->second].fmi3_type))
            invalid(root, "derivative of '" + shorten(v.name) + "' refers to valueReference " +
                              std::to_string(*v.derivative) + ", which is no Float variable");
        v.derivative = it->second + 1;
    }
}

}  // namespace fmi_loader::detail
