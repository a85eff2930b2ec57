// modelDescription.xml reader. The rules and defaults quoted below are from the FMI 2.0.4 standard,
// section 2.2 (the XML schema) and its table of causality/variability/initial (section 2.2.7).
#include "fmi_loader/model_description.hpp"

#include <libxml/parser.h>
#include <libxml/tree.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>

#include "fmi/vocabulary.hpp"
#include "fmi_loader/loader_error.hpp"

namespace fmi_loader {

// The words are the runtime's (fmi/vocabulary.hpp), in the order of the enums in model_description.hpp.
static_assert(fmi_vocabulary::spelling(fmi_vocabulary::causalities, Causality::independent) == "independent");
static_assert(fmi_vocabulary::spelling(fmi_vocabulary::variabilities, Variability::continuous) == "continuous");
static_assert(fmi_vocabulary::spelling(fmi_vocabulary::initials, Initial::calculated) == "calculated");

std::string_view to_string(Causality c) noexcept {
    return fmi_vocabulary::spelling(fmi_vocabulary::causalities, c);
}

std::string_view to_string(Variability v) noexcept {
    return fmi_vocabulary::spelling(fmi_vocabulary::variabilities, v);
}

std::string_view to_string(Initial i) noexcept {
    return fmi_vocabulary::spelling(fmi_vocabulary::initials, i);
}

std::string_view to_string(VariableType t) noexcept {
    switch (t) {
        case VariableType::real:
            return "Real";
        case VariableType::integer:
            return "Integer";
        case VariableType::boolean:
            return "Boolean";
        case VariableType::string:
            return "String";
        case VariableType::enumeration:
            return "Enumeration";
    }
    return "?";
}

bool is_valid_combination(Causality c, Variability v) noexcept {
    using enum Variability;
    switch (c) {
        case Causality::parameter:
        case Causality::calculated_parameter:
            return v == fixed || v == tunable;
        case Causality::input:
            return v == discrete || v == continuous;
        case Causality::output:
            return v == constant || v == discrete || v == continuous;
        case Causality::local:
            return true;
        case Causality::independent:
            return v == continuous;
    }
    return false;
}

Initial default_initial(Causality c, Variability v) noexcept {
    // Cases of the 2.2.7 table: A -> exact, B and C -> calculated, D and E -> no initial.
    switch (c) {
        case Causality::parameter:
            return Initial::exact;  // A
        case Causality::calculated_parameter:
            return Initial::calculated;  // B
        case Causality::input:
        case Causality::independent:
            return Initial::none;  // D, E
        case Causality::output:
        case Causality::local:
            return v == Variability::constant ? Initial::exact : Initial::calculated;  // A; B or C
    }
    return Initial::none;
}

bool is_allowed_initial(Causality c, Variability v, Initial i) noexcept {
    if (!is_valid_combination(c, v)) return false;
    switch (c) {
        case Causality::parameter:
            return i == Initial::exact;  // A
        case Causality::calculated_parameter:
            return i == Initial::calculated || i == Initial::approx;  // B
        case Causality::input:
        case Causality::independent:
            return i == Initial::none;  // D, E
        case Causality::output:
        case Causality::local:
            if (v == Variability::constant) return i == Initial::exact;  // A
            if (v == Variability::fixed || v == Variability::tunable)
                return i == Initial::calculated || i == Initial::approx;                     // B
            return i == Initial::exact || i == Initial::approx || i == Initial::calculated;  // C
    }
    return false;
}

std::optional<double> ScalarVariable::start_as_real() const {
    if (!start || type == VariableType::string || type == VariableType::boolean) return std::nullopt;
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(start->c_str(), &end);
    if (end == start->c_str() || *end != '\0' || errno == ERANGE) return std::nullopt;
    return value;
}

std::optional<bool> ScalarVariable::start_as_boolean() const {
    if (!start || type != VariableType::boolean) return std::nullopt;
    if (*start == "true" || *start == "1") return true;
    if (*start == "false" || *start == "0") return false;
    return std::nullopt;
}

const ScalarVariable* ModelDescription::find_variable(std::string_view name) const noexcept {
    for (const auto& v : model_variables)
        if (v.name == name) return &v;
    return nullptr;
}

const Unit* ModelDescription::find_unit(std::string_view name) const noexcept {
    for (const auto& u : unit_definitions)
        if (u.name == name) return &u;
    return nullptr;
}

const SimpleType* ModelDescription::find_type(std::string_view name) const noexcept {
    for (const auto& t : type_definitions)
        if (t.name == name) return &t;
    return nullptr;
}

namespace {

struct DocFree {
    void operator()(xmlDoc* d) const noexcept { xmlFreeDoc(d); }
};
struct CtxtFree {
    void operator()(xmlParserCtxt* c) const noexcept { xmlFreeParserCtxt(c); }
};

struct FirstError {
    std::string message;
    int line = 0;
    // libxml2 passes the parser context as user data; _private points back at this record.
    static void record(void* user, xmlErrorPtr error) {
        auto* ctxt = static_cast<xmlParserCtxt*>(user);
        auto* self = ctxt ? static_cast<FirstError*>(ctxt->_private) : nullptr;
        if (!self || !error || !self->message.empty() || error->level < XML_ERR_ERROR) return;
        self->message = error->message ? error->message : "error";
        self->line = error->line;
    }
};

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

    std::vector<std::size_t> index_list(const xmlNode* n, const std::string& list) const {
        std::vector<std::size_t> out;
        std::istringstream in(list);
        std::string token;
        while (in >> token) {
            char* end = nullptr;
            errno = 0;
            const long long v = std::strtoll(token.c_str(), &end, 10);
            if (*end != '\0' || v < 1 || errno == ERANGE)
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
        if (md.fmi_version.rfind("2.", 0) != 0) invalid(root, "fmiVersion '" + md.fmi_version + "' is not 2.x");
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
                    if (md.model_variables.size() == limits_.max_variables)
                        throw LoaderError(LoaderErrc::limit, "'" + source_ + "': more than the limit of " +
                                                                 std::to_string(limits_.max_variables) +
                                                                 " variables (max_variables)");
                    md.model_variables.push_back(scalar_variable(c, md));
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

private:
    std::string source_;
    const Limits& limits_;
};

}  // namespace

ModelDescription parse_model_description(std::string_view xml, const std::string& source_name, const Limits& limits) {
    if (xml.size() > limits.max_description_bytes)
        throw LoaderError(LoaderErrc::limit,
                          "'" + source_name + "' is " + std::to_string(xml.size()) + " bytes, more than the limit of " +
                              std::to_string(limits.max_description_bytes) + " bytes (max_description_bytes)");
    std::unique_ptr<xmlParserCtxt, CtxtFree> ctxt(xmlNewParserCtxt());
    if (!ctxt) throw LoaderError(LoaderErrc::xml_parse, "'" + source_name + "': cannot create parser");
    // NONET: no network; neither DTDLOAD nor NOENT: no external subset and no entity expansion.
    // NOERROR/NOWARNING: the message goes into the exception, not to stderr.
    const int options = XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING;
    // The first error says what is wrong ("AttValue length too long"); the last is often a consequence
    // ("Extra content at the end of the document").
    FirstError first;
    ctxt->sax->serror = &FirstError::record;
    ctxt->_private = &first;
    std::unique_ptr<xmlDoc, DocFree> doc(
        xmlCtxtReadMemory(ctxt.get(), xml.data(), static_cast<int>(xml.size()), nullptr, nullptr, options));
    if (!doc || !ctxt->wellFormed) {
        const xmlError* last = xmlCtxtGetLastError(ctxt.get());
        std::string cause = !first.message.empty()  ? first.message
                            : last && last->message ? last->message
                                                    : "not well-formed";
        while (!cause.empty() && cause.back() == '\n') cause.pop_back();
        const int line = !first.message.empty() ? first.line : last ? last->line : 0;
        throw LoaderError(LoaderErrc::xml_parse, "'" + source_name + "' line " + std::to_string(line) + ": " + cause);
    }
    // A DOCTYPE is the only way to declare entities; FMI never uses one, so refuse it outright.
    if (doc->intSubset || doc->extSubset)
        throw LoaderError(LoaderErrc::xml_invalid,
                          "'" + source_name + "': DOCTYPE declarations are not allowed in modelDescription.xml");
    return Reader(source_name, limits).read(xmlDocGetRootElement(doc.get()));
}

ModelDescription read_model_description(const std::filesystem::path& file, const Limits& limits) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw LoaderError(LoaderErrc::xml_parse, "'" + file.string() + "': cannot open file");
    // The size is checked before a byte is read: a 2 GB file must not be read into memory first.
    std::error_code ec;
    const auto size = std::filesystem::file_size(file, ec);
    if (!ec && size > limits.max_description_bytes)
        throw LoaderError(LoaderErrc::limit,
                          "'" + file.string() + "' is " + std::to_string(size) + " bytes, more than the limit of " +
                              std::to_string(limits.max_description_bytes) + " bytes (max_description_bytes)");
    std::string content;
    content.resize(ec ? 0 : static_cast<std::size_t>(size));
    in.read(content.data(), static_cast<std::streamsize>(content.size()));
    if (in.gcount() != static_cast<std::streamsize>(content.size()) || ec)
        throw LoaderError(LoaderErrc::xml_parse,
                          "'" + file.string() + "': cannot read the file" + (ec ? ": " + ec.message() : ""));
    return parse_model_description(content, file.string(), limits);
}

}  // namespace fmi_loader
