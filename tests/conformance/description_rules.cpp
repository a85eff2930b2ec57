#include "description_rules.hpp"

#include <cctype>
#include <map>
#include <set>

namespace conformance {

using namespace fmi_loader;

int accessor_class(VariableType type) {
    switch (type) {
        case VariableType::real:
            return 0;
        case VariableType::integer:
        case VariableType::enumeration:
            return 1;
        case VariableType::boolean:
            return 2;
        case VariableType::string:
            return 3;
    }
    return 4;
}

namespace {

// Recursive-descent parser for section 2.2.9:
//   name        = identifier | "der(" identifier ["," unsignedInteger] ")"
//   identifier  = B-name [arrayIndices] {"." B-name [arrayIndices]}
//   B-name      = nondigit {digit | nondigit} | Q-name
//   nondigit    = "_" | letters "a".."z" | "A".."Z"
//   Q-name      = "'" (Q-char | escape) {Q-char | escape} "'"
//   arrayIndices= "[" unsignedInteger {"," unsignedInteger} "]"
class NameParser {
public:
    explicit NameParser(std::string_view s) : s_(s) {}

    bool name() {
        if (s_.substr(0, 4) == "der(") {
            pos_ = 4;
            if (!identifier()) return false;
            if (peek() == ',') {
                ++pos_;
                if (!unsigned_integer()) return false;
            }
            if (peek() != ')') return false;
            ++pos_;
            return pos_ == s_.size();
        }
        return identifier() && pos_ == s_.size();
    }

private:
    char peek() const { return pos_ < s_.size() ? s_[pos_] : '\0'; }
    static bool nondigit(char c) { return c == '_' || std::isalpha(static_cast<unsigned char>(c)); }
    static bool digit(char c) { return std::isdigit(static_cast<unsigned char>(c)); }

    bool unsigned_integer() {
        const std::size_t start = pos_;
        while (digit(peek())) ++pos_;
        return pos_ > start;
    }
    bool q_name() {
        ++pos_;  // opening quote
        std::size_t chars = 0;
        while (pos_ < s_.size() && s_[pos_] != '\'') {
            if (s_[pos_] == '\\') {
                if (pos_ + 1 >= s_.size()) return false;
                const char e = s_[pos_ + 1];
                if (std::string_view("'\"?\\abfnrtv").find(e) == std::string_view::npos) return false;
                pos_ += 2;
            } else {
                // Q-char: any printable character except "'" and "\".
                if (!std::isprint(static_cast<unsigned char>(s_[pos_]))) return false;
                ++pos_;
            }
            ++chars;
        }
        if (peek() != '\'' || chars == 0) return false;
        ++pos_;
        return true;
    }
    bool b_name() {
        if (peek() == '\'') return q_name();
        if (!nondigit(peek())) return false;
        while (nondigit(peek()) || digit(peek())) ++pos_;
        return true;
    }
    bool array_indices() {
        ++pos_;  // '['
        if (!unsigned_integer()) return false;
        while (peek() == ',') {
            ++pos_;
            if (!unsigned_integer()) return false;
        }
        if (peek() != ']') return false;
        ++pos_;
        return true;
    }
    bool identifier() {
        for (;;) {
            if (!b_name()) return false;
            if (peek() == '[' && !array_indices()) return false;
            if (peek() != '.') return true;
            ++pos_;
        }
    }

    std::string_view s_;
    std::size_t pos_ = 0;
};

bool is_c_identifier(const std::string& s) {
    if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
    for (char c : s)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
    return true;
}

std::string label(const ScalarVariable& v, std::size_t index) {
    return "variable " + std::to_string(index) + " '" + v.name + "'";
}

}  // namespace

bool is_structured_name(std::string_view name) {
    return NameParser(name).name();
}

std::vector<std::string> description_violations(const ModelDescription& md) {
    std::vector<std::string> out;
    const auto& vars = md.model_variables;
    const std::size_t n = vars.size();

    if (md.guid.empty()) out.push_back("guid is empty");
    if (md.model_exchange && !is_c_identifier(md.model_exchange->model_identifier))
        out.push_back("ModelExchange modelIdentifier '" + md.model_exchange->model_identifier +
                      "' is not a C identifier");
    if (md.co_simulation && !is_c_identifier(md.co_simulation->model_identifier))
        out.push_back("CoSimulation modelIdentifier '" + md.co_simulation->model_identifier +
                      "' is not a C identifier");
    if (const auto& de = md.default_experiment) {
        if (de->start_time && de->stop_time && *de->stop_time <= *de->start_time)
            out.push_back("DefaultExperiment stopTime is not after startTime");
        if (de->step_size && *de->step_size <= 0) out.push_back("DefaultExperiment stepSize is not positive");
        if (de->tolerance && *de->tolerance <= 0) out.push_back("DefaultExperiment tolerance is not positive");
    }
    for (const auto& t : md.type_definitions)
        if (!t.unit.empty() && !md.find_unit(t.unit))
            out.push_back("SimpleType '" + t.name + "' uses undefined unit '" + t.unit + "'");

    std::map<std::string, std::size_t> names;
    std::map<std::pair<int, std::uint32_t>, std::size_t> refs;
    for (std::size_t i = 0; i < n; ++i) {
        const ScalarVariable& v = vars[i];
        const std::string who = label(v, i + 1);
        if (v.name.empty()) out.push_back(who + ": empty name");
        if (auto [it, fresh] = names.emplace(v.name, i + 1); !fresh)
            out.push_back(who + ": name already used by variable " + std::to_string(it->second));
        if (auto [it, fresh] = refs.emplace(std::pair{accessor_class(v.type), v.value_reference}, i + 1); !fresh)
            out.push_back(who + ": valueReference " + std::to_string(v.value_reference) +
                          " of the same type already used by variable " + std::to_string(it->second));
        if (md.variable_naming_convention == "structured" && !is_structured_name(v.name))
            out.push_back(who + ": not a valid structured name (section 2.2.9)");

        // Section 2.2.7 table.
        if (!is_valid_combination(v.causality, v.variability)) {
            out.push_back(who + ": causality " + std::string(to_string(v.causality)) + " with variability " +
                          std::string(to_string(v.variability)) + " is not allowed");
        } else if (!is_allowed_initial(v.causality, v.variability, v.initial)) {
            out.push_back(who + ": initial=" + std::string(to_string(v.initial)) + " is not allowed for " +
                          std::string(to_string(v.causality)) + "/" + std::string(to_string(v.variability)));
        }
        if (v.variability == Variability::continuous && v.type != VariableType::real)
            out.push_back(who + ": only Real variables may be continuous");
        const bool start_required =
            v.initial == Initial::exact || v.initial == Initial::approx || v.causality == Causality::input;
        const bool start_forbidden = v.initial == Initial::calculated || v.causality == Causality::independent;
        if (start_required && !v.start) out.push_back(who + ": start value required (initial/causality) but absent");
        if (start_forbidden && v.start)
            out.push_back(who + ": start value given but initial=calculated or independent forbids it");

        if (v.start) {
            const bool numeric =
                v.type == VariableType::real || v.type == VariableType::integer || v.type == VariableType::enumeration;
            if (numeric && !v.start_as_real()) out.push_back(who + ": start '" + *v.start + "' is not a number");
            if (v.type == VariableType::boolean && !v.start_as_boolean())
                out.push_back(who + ": start '" + *v.start + "' is not a boolean");
            if (numeric && v.start_as_real()) {
                const double s = *v.start_as_real();
                if ((v.min && s < *v.min) || (v.max && s > *v.max)) out.push_back(who + ": start outside [min, max]");
            }
        }
        if (v.min && v.max && *v.min > *v.max) out.push_back(who + ": min > max");
        if (v.type == VariableType::real && !v.unit.empty()) {
            const Unit* unit = md.find_unit(v.unit);
            if (!unit) {
                out.push_back(who + ": unit '" + v.unit + "' is not defined in UnitDefinitions");
            } else if (!v.display_unit.empty()) {
                bool found = false;
                for (const auto& d : unit->display_units) found = found || d.name == v.display_unit;
                if (!found)
                    out.push_back(who + ": displayUnit '" + v.display_unit + "' is not a DisplayUnit of '" + v.unit +
                                  "'");
            }
        }
        if (!v.declared_type.empty()) {
            const SimpleType* t = md.find_type(v.declared_type);
            if (t && t->type != v.type)
                out.push_back(who + ": declaredType '" + v.declared_type + "' has another base type");
        }
        if (v.derivative) {
            if (v.type != VariableType::real) out.push_back(who + ": derivative attribute on a non-Real");
            if (*v.derivative > n)
                out.push_back(who + ": derivative index " + std::to_string(*v.derivative) + " out of range");
            else if (vars[*v.derivative - 1].type != VariableType::real)
                out.push_back(who + ": derivative points at a non-Real");
        }
    }

    // Section 2.2.8, ModelStructure.
    std::set<std::size_t> states;
    for (const auto& v : vars)
        if (v.derivative && *v.derivative <= n) states.insert(*v.derivative);
    auto in_range = [&](const char* list, std::size_t index) {
        if (index >= 1 && index <= n) return true;
        out.push_back(std::string(list) + ": index " + std::to_string(index) + " out of range 1.." + std::to_string(n));
        return false;
    };
    auto check_dependencies = [&](const char* list, const Unknown& u, bool initial_unknowns) {
        if (!u.dependencies_kind.empty() && (!u.dependencies || u.dependencies->size() != u.dependencies_kind.size()))
            out.push_back(std::string(list) + ": unknown " + std::to_string(u.index) +
                          " has a dependenciesKind list that does not pair with its dependencies");
        if (!u.dependencies) return;
        for (std::size_t d : *u.dependencies) {
            if (!in_range(list, d)) continue;
            const ScalarVariable& k = vars[d - 1];
            const bool known =
                k.causality == Causality::input || k.causality == Causality::independent || states.count(d) ||
                (initial_unknowns &&
                 (k.initial == Initial::exact || k.initial == Initial::approx || k.causality == Causality::parameter));
            // Derivatives of states may depend on other InitialUnknowns only in InitialUnknowns.
            if (!known && !initial_unknowns)
                out.push_back(std::string(list) + ": unknown " + std::to_string(u.index) + " depends on " +
                              std::to_string(d) + " which is neither input, state nor independent");
        }
    };
    std::set<std::size_t> listed_outputs;
    for (const auto& u : md.model_structure.outputs) {
        if (!in_range("Outputs", u.index)) continue;
        if (vars[u.index - 1].causality != Causality::output)
            out.push_back("Outputs: index " + std::to_string(u.index) + " is not causality=output");
        if (!listed_outputs.insert(u.index).second)
            out.push_back("Outputs: index " + std::to_string(u.index) + " listed twice");
        check_dependencies("Outputs", u, false);
    }
    for (std::size_t i = 0; i < n; ++i)
        if (vars[i].causality == Causality::output && !listed_outputs.count(i + 1))
            out.push_back(label(vars[i], i + 1) + ": output missing from ModelStructure/Outputs");
    std::set<std::size_t> listed_derivatives;
    for (const auto& u : md.model_structure.derivatives) {
        if (!in_range("Derivatives", u.index)) continue;
        if (!vars[u.index - 1].derivative)
            out.push_back("Derivatives: index " + std::to_string(u.index) + " has no derivative attribute");
        if (!listed_derivatives.insert(u.index).second)
            out.push_back("Derivatives: index " + std::to_string(u.index) + " listed twice");
        check_dependencies("Derivatives", u, false);
    }
    // InitialUnknowns must list exactly: outputs with initial approx/calculated, calculated
    // parameters, and states and derivatives with initial approx/calculated (section 2.2.8).
    std::set<std::size_t> expected_initial;
    auto approx_or_calculated = [](const ScalarVariable& v) {
        return v.initial == Initial::approx || v.initial == Initial::calculated;
    };
    for (std::size_t i = 0; i < n; ++i) {
        const ScalarVariable& v = vars[i];
        if ((v.causality == Causality::output && approx_or_calculated(v)) ||
            v.causality == Causality::calculated_parameter)
            expected_initial.insert(i + 1);
    }
    for (std::size_t d : listed_derivatives) {
        if (approx_or_calculated(vars[d - 1])) expected_initial.insert(d);
        if (!vars[d - 1].derivative) continue;  // already reported above; no state to look at
        const std::size_t s = *vars[d - 1].derivative;
        if (s >= 1 && s <= n && approx_or_calculated(vars[s - 1])) expected_initial.insert(s);
    }
    std::set<std::size_t> listed_initial;
    for (const auto& u : md.model_structure.initial_unknowns) {
        if (!in_range("InitialUnknowns", u.index)) continue;
        if (!listed_initial.insert(u.index).second)
            out.push_back("InitialUnknowns: index " + std::to_string(u.index) + " listed twice");
        check_dependencies("InitialUnknowns", u, true);
    }
    for (std::size_t i : expected_initial)
        if (!listed_initial.count(i))
            out.push_back(label(vars[i - 1], i) + ": missing from ModelStructure/InitialUnknowns");
    for (std::size_t i : listed_initial)
        if (!expected_initial.count(i))
            out.push_back(label(vars[i - 1], i) + ": listed in InitialUnknowns but is not an initial unknown");
    return out;
}

}  // namespace conformance
