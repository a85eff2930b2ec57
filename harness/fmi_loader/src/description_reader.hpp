// The modelDescription.xml reader shared by the FMI 2.0 (model_description.cpp) and FMI 3.0
// (model_description3.cpp) schemas: attribute access with the loader's error messages, and each
// version's elements. Internal to the loader.
#pragma once

#include <libxml/tree.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "fmi/vocabulary.hpp"
#include "fmi_loader/loader_error.hpp"
#include "fmi_loader/model_description.hpp"

namespace fmi_loader::detail {

class Reader {
public:
    Reader(std::string source, const Limits& limits) : source_(std::move(source)), limits_(limits) {}

    [[noreturn]] void invalid(const xmlNode* node, const std::string& cause) const {
        const long line = node ? static_cast<long>(xmlGetLineNo(node)) : 0;
        throw LoaderError(LoaderErrc::xml_invalid, "'" + source_ + "' line " + std::to_string(line) + ": " + cause);
    }

    static bool is(const xmlNode* n, const char* name) {
        return n->type == XML_ELEMENT_NODE && xmlStrcmp(n->name, reinterpret_cast<const xmlChar*>(name)) == 0;
    }

    static std::optional<std::string> attr(const xmlNode* n, const char* name) {
        xmlChar* value = xmlGetNoNsProp(n, reinterpret_cast<const xmlChar*>(name));
        if (!value) return std::nullopt;
        std::string text(reinterpret_cast<const char*>(value));
        xmlFree(value);
        return text;
    }

    std::string required(const xmlNode* n, const char* name) const {
        auto v = attr(n, name);
        if (!v)
            invalid(n, std::string("<") + reinterpret_cast<const char*>(n->name) + "> lacks required attribute '" +
                           name + "'");
        return *v;
    }

    std::string text(const xmlNode* n, const char* name) const { return attr(n, name).value_or(""); }

    std::optional<double> real(const xmlNode* n, const char* name) const {
        auto v = attr(n, name);
        if (!v) return std::nullopt;
        return parse_real(n, name, *v);
    }

    // "1e999" is a number, only too large for a double: say so rather than "not a number".
    double parse_real(const xmlNode* n, const char* name, const std::string& v) const {
        char* end = nullptr;
        errno = 0;
        const double value = std::strtod(v.c_str(), &end);
        if (v.empty() || *end != '\0')
            invalid(n, std::string("attribute '") + name + "' is not a number: '" + shorten(v) + "'");
        if (errno == ERANGE && std::abs(value) > 1.0)
            invalid(n, std::string("attribute '") + name + "': " + shorten(v) + " is out of range of a double");
        return value;  // an underflow to 0 or a subnormal is that value, as the standard's xs:double has it
    }

    std::optional<long long> integer(const xmlNode* n, const char* name) const {
        auto v = attr(n, name);
        if (!v) return std::nullopt;
        char* end = nullptr;
        errno = 0;
        const long long value = std::strtoll(v->c_str(), &end, 10);
        if (v->empty() || *end != '\0')
            invalid(n, std::string("attribute '") + name + "' is not an integer: '" + shorten(*v) + "'");
        if (errno == ERANGE) invalid(n, std::string("attribute '") + name + "': " + shorten(*v) + " is out of range");
        return value;
    }

    // Values quoted in messages are cut: a 50 MB attribute must not become a 50 MB message.
    static std::string shorten(const std::string& v) {
        constexpr std::size_t keep = 64;
        return v.size() <= keep ? v : v.substr(0, keep) + "... (" + std::to_string(v.size()) + " characters)";
    }

    std::size_t index(const xmlNode* n, const char* name) const {
        const auto v = integer(n, name);
        if (!v) invalid(n, std::string("lacks required attribute '") + name + "'");
        if (*v < 1) invalid(n, std::string("attribute '") + name + "' must be >= 1");
        return static_cast<std::size_t>(*v);
    }

    bool boolean(const xmlNode* n, const char* name, bool fallback) const {
        auto v = attr(n, name);
        if (!v) return fallback;
        if (*v == "true" || *v == "1") return true;
        if (*v == "false" || *v == "0") return false;
        invalid(n, std::string("attribute '") + name + "' is not a boolean: '" + *v + "'");
    }

    Causality causality(const xmlNode* n) const {
        const auto v = attr(n, "causality");
        if (!v) return Causality::local;  // default, section 2.2.7
        if (const auto c = fmi_vocabulary::parse<Causality>(fmi_vocabulary::causalities, *v)) return *c;
        if (*v == "structuralParameter" && fmi3_) return Causality::structural_parameter;
        invalid(n, "unknown causality '" + *v + "'");
    }

    Variability variability(const xmlNode* n) const {
        const auto v = attr(n, "variability");
        if (!v) return Variability::continuous;  // default, section 2.2.7
        if (const auto x = fmi_vocabulary::parse<Variability>(fmi_vocabulary::variabilities, *v)) return *x;
        invalid(n, "unknown variability '" + *v + "'");
    }

    std::optional<Initial> initial(const xmlNode* n) const {
        const auto v = attr(n, "initial");
        if (!v) return std::nullopt;
        // "none" is no word of the standard: the attribute is absent instead.
        if (const auto i = fmi_vocabulary::parse<Initial>(fmi_vocabulary::initials, *v); i && *i != Initial::none)
            return *i;
        invalid(n, "unknown initial '" + *v + "'");
    }

    static std::optional<VariableType> type_of(const xmlNode* n) {
        if (is(n, "Real")) return VariableType::real;
        if (is(n, "Integer")) return VariableType::integer;
        if (is(n, "Boolean")) return VariableType::boolean;
        if (is(n, "String")) return VariableType::string;
        if (is(n, "Enumeration")) return VariableType::enumeration;
        return std::nullopt;
    }

    // Whitespace-separated non-negative integers of at least `minimum` (FMI 2.0 indices start at 1,
    // FMI 3.0 value references at 0).
    std::vector<std::size_t> index_list(const xmlNode* n, const std::string& list, long long minimum = 1) const {
        std::vector<std::size_t> out;
        std::istringstream in(list);
        std::string token;
        while (in >> token) {
            char* end = nullptr;
            errno = 0;
            const long long v = std::strtoll(token.c_str(), &end, 10);
            if (*end != '\0' || v < minimum || errno == ERANGE)
                invalid(n, "bad index '" + shorten(token) + "' in dependencies");
            out.push_back(static_cast<std::size_t>(v));
        }
        return out;
    }

    std::vector<Unknown> unknowns(const xmlNode* parent) const {
        std::vector<Unknown> out;
        for (const xmlNode* u = parent->children; u; u = u->next) {
            if (!is(u, "Unknown")) continue;
            Unknown unknown;
            unknown.index = index(u, "index");
            if (const auto deps = attr(u, "dependencies")) unknown.dependencies = index_list(u, *deps);
            if (const auto kinds = attr(u, "dependenciesKind")) {
                std::istringstream in(*kinds);
                std::string k;
                while (in >> k) {
                    if (k != "dependent" && k != "constant" && k != "fixed" && k != "tunable" && k != "discrete")
                        invalid(u, "unknown dependenciesKind '" + k + "'");
                    unknown.dependencies_kind.push_back(k);
                }
                // Whether the kinds pair one to one with dependencies (section 2.2.8) is left to
                // validators: tools read such files, so the loader keeps them as written.
            }
            out.push_back(std::move(unknown));
        }
        return out;
    }

    void unit_definitions(const xmlNode* parent, ModelDescription& md) const {
        for (const xmlNode* n = parent->children; n; n = n->next) {
            if (!is(n, "Unit")) continue;
            Unit unit;
            unit.name = required(n, "name");
            for (const xmlNode* c = n->children; c; c = c->next) {
                if (is(c, "BaseUnit")) {
                    BaseUnit b;
                    b.kg = static_cast<int>(integer(c, "kg").value_or(0));
                    b.m = static_cast<int>(integer(c, "m").value_or(0));
                    b.s = static_cast<int>(integer(c, "s").value_or(0));
                    b.A = static_cast<int>(integer(c, "A").value_or(0));
                    b.K = static_cast<int>(integer(c, "K").value_or(0));
                    b.mol = static_cast<int>(integer(c, "mol").value_or(0));
                    b.cd = static_cast<int>(integer(c, "cd").value_or(0));
                    b.rad = static_cast<int>(integer(c, "rad").value_or(0));
                    b.factor = real(c, "factor").value_or(1.0);
                    b.offset = real(c, "offset").value_or(0.0);
                    unit.base_unit = b;
                } else if (is(c, "DisplayUnit")) {
                    unit.display_units.push_back(
                        {required(c, "name"), real(c, "factor").value_or(1.0), real(c, "offset").value_or(0.0)});
                }
            }
            md.unit_definitions.push_back(std::move(unit));
        }
    }

    void type_definitions(const xmlNode* parent, ModelDescription& md) const {
        for (const xmlNode* n = parent->children; n; n = n->next) {
            if (!is(n, "SimpleType")) continue;
            SimpleType t;
            t.name = required(n, "name");
            t.description = text(n, "description");
            const xmlNode* body = nullptr;
            for (const xmlNode* c = n->children; c; c = c->next)
                if (type_of(c)) {
                    body = c;
                    break;
                }
            if (!body) invalid(n, "SimpleType '" + t.name + "' has no Real/Integer/Boolean/String/Enumeration element");
            t.type = *type_of(body);
            t.quantity = text(body, "quantity");
            t.unit = text(body, "unit");
            t.display_unit = text(body, "displayUnit");
            t.min = real(body, "min");
            t.max = real(body, "max");
            t.nominal = real(body, "nominal");
            for (const xmlNode* item = body->children; item; item = item->next) {
                if (!is(item, "Item")) continue;
                const auto value = integer(item, "value");
                if (!value) invalid(item, "Item lacks 'value'");
                t.items.push_back({required(item, "name"), *value, text(item, "description")});
            }
            md.type_definitions.push_back(std::move(t));
        }
    }

    ScalarVariable scalar_variable(const xmlNode* n, const ModelDescription& md) const {
        ScalarVariable v;
        v.name = required(n, "name");
        const auto vr = integer(n, "valueReference");
        if (!vr) invalid(n, "ScalarVariable '" + v.name + "' lacks 'valueReference'");
        if (*vr < 0 || *vr > 0xFFFFFFFFLL) invalid(n, "valueReference of '" + v.name + "' out of range");
        v.value_reference = static_cast<std::uint32_t>(*vr);
        v.description = text(n, "description");
        v.causality = causality(n);
        v.variability = variability(n);
        v.can_handle_multiple_set_per_time_instant = boolean(n, "canHandleMultipleSetPerTimeInstant", true);
        const auto init = initial(n);
        v.initial_given = init.has_value();
        v.initial = init ? *init : default_initial(v.causality, v.variability);

        const xmlNode* body = nullptr;
        for (const xmlNode* c = n->children; c; c = c->next) {
            if (!type_of(c)) continue;
            if (body) invalid(c, "ScalarVariable '" + v.name + "' has more than one type element");
            body = c;
        }
        if (!body) invalid(n, "ScalarVariable '" + v.name + "' has no type element");
        v.type = *type_of(body);
        v.declared_type = text(body, "declaredType");
        v.start = attr(body, "start");
        v.quantity = text(body, "quantity");
        v.unit = text(body, "unit");
        v.display_unit = text(body, "displayUnit");
        v.min = real(body, "min");
        v.max = real(body, "max");
        v.nominal = real(body, "nominal");
        v.relative_quantity = boolean(body, "relativeQuantity", false);
        v.reinit = boolean(body, "reinit", false);
        if (const auto d = integer(body, "derivative")) {
            if (*d < 1) invalid(body, "derivative index of '" + v.name + "' must be >= 1");
            v.derivative = static_cast<std::size_t>(*d);
        }
        // Attributes a variable omits are inherited from its declared type (section 2.2.3).
        if (!v.declared_type.empty()) {
            const SimpleType* t = md.find_type(v.declared_type);
            if (!t) invalid(body, "declaredType '" + v.declared_type + "' of '" + v.name + "' is not defined");
            if (v.quantity.empty()) v.quantity = t->quantity;
            if (v.unit.empty()) v.unit = t->unit;
            if (v.display_unit.empty()) v.display_unit = t->display_unit;
            if (!v.min) v.min = t->min;
            if (!v.max) v.max = t->max;
            if (!v.nominal) v.nominal = t->nominal;
        }
        return v;
    }

    ModelDescription read(const xmlNode* root) const {
        if (!root || !is(root, "fmiModelDescription")) invalid(root, "root element is not <fmiModelDescription>");
        ModelDescription md;
        md.fmi_version = required(root, "fmiVersion");
        if (md.fmi_version.rfind("3.", 0) == 0) return read3(root);
        if (md.fmi_version.rfind("2.", 0) != 0)
            invalid(root, "fmiVersion '" + md.fmi_version + "' is neither 2.x nor 3.x");
        md.model_name = required(root, "modelName");
        md.guid = required(root, "guid");
        md.description = text(root, "description");
        md.author = text(root, "author");
        md.version = text(root, "version");
        md.generation_tool = text(root, "generationTool");
        md.variable_naming_convention = attr(root, "variableNamingConvention").value_or("flat");
        if (md.variable_naming_convention != "flat" && md.variable_naming_convention != "structured")
            invalid(root, "unknown variableNamingConvention '" + md.variable_naming_convention + "'");
        const auto nz = integer(root, "numberOfEventIndicators").value_or(0);
        if (nz < 0) invalid(root, "numberOfEventIndicators is negative");
        if (static_cast<unsigned long long>(nz) > limits_.max_event_indicators)
            throw LoaderError(LoaderErrc::limit, "'" + source_ + "': numberOfEventIndicators " + std::to_string(nz) +
                                                     " is more than the limit of " +
                                                     std::to_string(limits_.max_event_indicators) +
                                                     " (max_event_indicators)");
        md.number_of_event_indicators = static_cast<std::size_t>(nz);

        // Types first: variables inherit from them whatever the element order in the file.
        for (const xmlNode* n = root->children; n; n = n->next) {
            if (is(n, "UnitDefinitions"))
                unit_definitions(n, md);
            else if (is(n, "TypeDefinitions"))
                type_definitions(n, md);
        }
        for (const xmlNode* n = root->children; n; n = n->next) {
            if (is(n, "ModelExchange")) {
                ModelExchangeInfo me;
                me.model_identifier = required(n, "modelIdentifier");
                check_model_identifier(n, me.model_identifier);
                me.needs_execution_tool = boolean(n, "needsExecutionTool", false);
                me.completed_integrator_step_not_needed = boolean(n, "completedIntegratorStepNotNeeded", false);
                me.can_be_instantiated_only_once_per_process = boolean(n, "canBeInstantiatedOnlyOncePerProcess", false);
                me.can_not_use_memory_management_functions = boolean(n, "canNotUseMemoryManagementFunctions", false);
                me.can_get_and_set_fmu_state = boolean(n, "canGetAndSetFMUstate", false);
                me.can_serialize_fmu_state = boolean(n, "canSerializeFMUstate", false);
                me.provides_directional_derivative = boolean(n, "providesDirectionalDerivative", false);
                md.model_exchange = me;
            } else if (is(n, "CoSimulation")) {
                CoSimulationInfo cs;
                cs.model_identifier = required(n, "modelIdentifier");
                check_model_identifier(n, cs.model_identifier);
                cs.needs_execution_tool = boolean(n, "needsExecutionTool", false);
                cs.can_handle_variable_communication_step_size =
                    boolean(n, "canHandleVariableCommunicationStepSize", false);
                cs.can_interpolate_inputs = boolean(n, "canInterpolateInputs", false);
                cs.max_output_derivative_order = static_cast<int>(integer(n, "maxOutputDerivativeOrder").value_or(0));
                cs.can_run_asynchronuously = boolean(n, "canRunAsynchronuously", false);
                cs.can_be_instantiated_only_once_per_process = boolean(n, "canBeInstantiatedOnlyOncePerProcess", false);
                cs.can_not_use_memory_management_functions = boolean(n, "canNotUseMemoryManagementFunctions", false);
                cs.can_get_and_set_fmu_state = boolean(n, "canGetAndSetFMUstate", false);
                cs.can_serialize_fmu_state = boolean(n, "canSerializeFMUstate", false);
                cs.provides_directional_derivative = boolean(n, "providesDirectionalDerivative", false);
                md.co_simulation = cs;
            } else if (is(n, "LogCategories")) {
                for (const xmlNode* c = n->children; c; c = c->next)
                    if (is(c, "Category")) md.log_categories.push_back({required(c, "name"), text(c, "description")});
            } else if (is(n, "DefaultExperiment")) {
                md.default_experiment = DefaultExperiment{real(n, "startTime"), real(n, "stopTime"),
                                                          real(n, "tolerance"), real(n, "stepSize")};
            } else if (is(n, "ModelVariables")) {
                for (const xmlNode* c = n->children; c; c = c->next) {
                    if (!is(c, "ScalarVariable")) continue;
                    add_variable(md, scalar_variable(c, md));
                }
            } else if (is(n, "ModelStructure")) {
                for (const xmlNode* c = n->children; c; c = c->next) {
                    if (is(c, "Outputs"))
                        md.model_structure.outputs = unknowns(c);
                    else if (is(c, "Derivatives"))
                        md.model_structure.derivatives = unknowns(c);
                    else if (is(c, "InitialUnknowns"))
                        md.model_structure.initial_unknowns = unknowns(c);
                }
            }
        }
        if (!md.model_exchange && !md.co_simulation)
            invalid(root, "neither <ModelExchange> nor <CoSimulation> is declared");
        check_unique(root, md);
        check_indices(root, md);
        return md;
    }

    void add_variable(ModelDescription& md, ScalarVariable v) const {
        if (md.model_variables.size() == limits_.max_variables)
            throw LoaderError(LoaderErrc::limit, "'" + source_ + "': more than the limit of " +
                                                     std::to_string(limits_.max_variables) +
                                                     " variables (max_variables)");
        md.model_variables.push_back(std::move(v));
    }

    // FMI 2.0.4 section 2.2.1: modelIdentifier is the prefix of the C function names and the name of
    // the shared library, so it must be a plain C identifier; anything else ("../x", "/abs/evil")
    // would make the loader open a library outside the unpacked FMU.
    void check_model_identifier(const xmlNode* n, const std::string& id) const {
        const auto letter = [](unsigned char c) {
            return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
        };
        bool ok = !id.empty() && letter(static_cast<unsigned char>(id[0])) && id.size() <= 200;
        for (const unsigned char c : id) ok = ok && (letter(c) || (c >= '0' && c <= '9'));
        if (!ok)
            invalid(n, "modelIdentifier '" + shorten(id) +
                           "' is not a C identifier ([A-Za-z_][A-Za-z0-9_]*, at most 200 characters)");
    }

    // Names are unique (section 2.2.7). Variables of one base type sharing a valueReference are
    // aliases of one value; at most one of an alias set may carry a start value, or setting one
    // name would silently change another's.
    void check_unique(const xmlNode* root, const ModelDescription& md) const {
        std::map<std::string_view, std::size_t> names;
        std::map<std::pair<int, std::uint32_t>, std::size_t> started;
        for (std::size_t i = 0; i < md.model_variables.size(); ++i) {
            const auto& v = md.model_variables[i];
            if (const auto [it, fresh] = names.emplace(v.name, i); !fresh)
                invalid(root, "variable name '" + shorten(v.name) + "' is declared twice (variables " +
                                  std::to_string(it->second + 1) + " and " + std::to_string(i + 1) + ")");
            if (!v.start) continue;
            const int base = v.type == VariableType::enumeration ? static_cast<int>(VariableType::integer)
                                                                 : static_cast<int>(v.type);
            if (const auto [it, fresh] = started.emplace(std::pair{base, v.value_reference}, i); !fresh)
                invalid(root, "variables '" + shorten(md.model_variables[it->second].name) + "' and '" +
                                  shorten(v.name) + "' share valueReference " + std::to_string(v.value_reference) +
                                  " and both have a start value (an alias set allows one)");
        }
    }

    // Indices into ModelVariables must name a variable (section 2.2.8).
    void check_indices(const xmlNode* root, const ModelDescription& md) const {
        const std::size_t count = md.model_variables.size();
        auto in_range = [&](std::size_t index, const char* where) {
            if (index > count)
                invalid(root, std::string(where) + " index " + std::to_string(index) + " is beyond the " +
                                  std::to_string(count) + " variables");
        };
        for (const auto* list :
             {&md.model_structure.outputs, &md.model_structure.derivatives, &md.model_structure.initial_unknowns})
            for (const auto& u : *list) {
                in_range(u.index, "ModelStructure");
                if (u.dependencies)
                    for (const auto d : *u.dependencies) in_range(d, "dependencies");
            }
        for (const auto& v : md.model_variables)
            if (v.derivative) in_range(*v.derivative, "derivative");
    }

    // FMI 3.0 (model_description3.cpp).
    ModelDescription read3(const xmlNode* root) const;
    void type_definitions3(const xmlNode* parent, ModelDescription& md) const;
    ScalarVariable variable3(const xmlNode* n, Fmi3Type type, const ModelDescription& md) const;
    std::vector<Unknown> unknowns3(const xmlNode* parent, const char* element, const ModelDescription& md) const;
    void interfaces3(const xmlNode* n, ModelDescription& md) const;
    void check3(const xmlNode* root, ModelDescription& md) const;
    std::size_t index_of_reference(const xmlNode* n, const ModelDescription& md, std::uint32_t vr) const;

private:
    std::string source_;
    const Limits& limits_;
    mutable bool fmi3_ = false;
};

}  // namespace fmi_loader::detail
