#include "engine/system.hpp"

#include <algorithm>
#include <set>

#include "connector_elements.hpp"
#include "engine/cosim_error.hpp"
#include "engine/fmi2_instance.hpp"
#include "engine/fmi3_instance.hpp"
#include "engine/hardware_bridge.hpp"
#include "engine/import_cache.hpp"
#include "engine/name_hint.hpp"
#include "engine/ssp_archive.hpp"
#include "engine/value_text.hpp"
#include "same_bits.hpp"

namespace cosim {

namespace {

using fmi_loader::Causality;
using fmi_loader::VariableType;

// The bytes unpacked below a folder (regular files only).
std::uint64_t unpacked_bytes(const std::filesystem::path& folder) {
    std::uint64_t total = 0;
    std::error_code ec;
    for (auto it = std::filesystem::recursive_directory_iterator(folder, ec);
         !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec))
        if (it->is_regular_file(ec)) total += it->file_size(ec);
    return total;
}

std::string kind_name(ConnectorKind k) {
    switch (k) {
        case ConnectorKind::input:
            return "input";
        case ConnectorKind::output:
            return "output";
        case ConnectorKind::parameter:
            return "parameter";
        case ConnectorKind::calculated_parameter:
            return "calculatedParameter";
        case ConnectorKind::inout:
            return "inout";
        case ConnectorKind::unspecified:
            return "unspecified";
    }
    return "?";
}

bool kind_matches(ConnectorKind k, Causality c) {
    switch (k) {
        case ConnectorKind::input:
            return c == Causality::input;
        case ConnectorKind::output:
            return c == Causality::output;
        case ConnectorKind::parameter:
            return c == Causality::parameter;
        case ConnectorKind::calculated_parameter:
            return c == Causality::calculated_parameter;
        default:
            return true;
    }
}

// Integer and Enumeration values travel as the same fmi2Integer.
bool same_type(VariableType a, VariableType b) {
    auto norm = [](VariableType t) { return t == VariableType::enumeration ? VariableType::integer : t; };
    return norm(a) == norm(b);
}

std::size_t index_in(const fmi_loader::ModelDescription& md, const fmi_loader::ScalarVariable* v) {
    return static_cast<std::size_t>(v - md.model_variables.data());
}

}  // namespace

System::System(const SystemDescription& description, const SystemOptions& options)
    : description_(description), tolerance_(options.tolerance) {
    load_components(options);
    check_connectors();
    connect();
    order_connections();
    group_transfers();
    mark_continuous_consumers();
    changed_.assign(components_.size(), 0);
    discrete_changed_.assign(components_.size(), 0);
    collect_values(options);
    connect_parameters();
    check_settings();
    check_open_inputs();
}

// One value given by name: a system parameter's, or a component variable's (component.variable). Later
// values of one name win (they are applied in order).
void System::take_value(const Setting& named, const std::string& place, bool command_line) {
    const std::string& name = named.variable;
    for (std::size_t i = 0; i < description_.parameters.size(); ++i)
        if (description_.parameters[i].name == name) {
            parameter_values_[i] = {named.value, named.ssv_type, place};
            return;
        }
    auto split = split_variable_name(name);
    if (!split) {
        std::vector<std::string> names;
        for (const auto& p : description_.parameters) names.push_back(p.name);
        const std::string text = (command_line ? std::string() : place + ": ") + "'" + name +
                                 "' is no system parameter of " + description_.file.filename().string() +
                                 name_hint(name, names) + (names.empty() ? " (it has none)" : "") +
                                 "; a component's variable is named component.variable";
        if (command_line) throw SettingError(text);
        throw CosimError(text);
    }
    settings_.emplace_back(component_index(split->component),
                           Setting{split->component, split->variable, named.value, named.ssv_type});
    setting_places_.push_back(command_line ? "" : place);
}

// The values by name, lowest precedence first: the system's own bindings, the parameter files in order, --set.
void System::collect_values(const SystemOptions& options) {
    parameter_values_.assign(description_.parameters.size(), {});
    const auto& own = description_.system_bindings;
    for (std::size_t k = 0; k < own.values.size(); ++k)
        take_value(own.values[k], k < own.places.size() ? own.places[k] : description_.file.string(), false);
    for (const auto& file : options.parameter_files) {
        const ParameterValues read = read_parameter_values(file);
        for (std::size_t k = 0; k < read.values.size(); ++k) take_value(read.values[k], read.places[k], false);
    }
    for (const auto& text : options.settings) {
        const auto eq = text.find('=');
        const std::string name = text.substr(0, eq == std::string::npos ? 0 : eq);
        if (eq != std::string::npos && eq > 0 && name.find('.') == std::string::npos) {
            take_value(Setting{"", name, text.substr(eq + 1), ""}, "--set", true);
            continue;
        }
        Setting setting = parse_setting(text, true);
        settings_.emplace_back(component_index(setting.component), std::move(setting));
        setting_places_.push_back("");
    }
}

namespace {

// An SSP connector type against an FMU variable's type (an Enumeration parameter feeds only Enumerations).
bool parameter_type_fits(const std::string& type, VariableType t) {
    if (type == "Real") return t == VariableType::real;
    // An Integer may carry an Enumeration's item number (cosim pack writes a system Enumeration so).
    if (type == "Integer") return t == VariableType::integer || t == VariableType::enumeration;
    if (type == "Boolean") return t == VariableType::boolean;
    if (type == "String") return t == VariableType::string;
    if (type == "Enumeration") return t == VariableType::enumeration;
    return false;
}

}  // namespace

// Each system parameter's connections (SSP 1.0: system to component connectors of one kind, parameter):
// the end a parameter of its component, of the parameter's type and unit, bound nowhere else in the .ssd,
// and the value given fit for it. The value fed is applied after the component's own bindings.
void System::connect_parameters() {
    for (const auto& f : description_.feeds) {
        const std::size_t c = component_index(f.component);
        const auto& md = components_[c].description();
        const auto& declared = description_.components[c].connectors;
        if (!declared.empty() && std::none_of(declared.begin(), declared.end(),
                                              [&](const ConnectorDescription& d) { return d.name == f.variable; }))
            throw CosimError(f.place + ": component '" + f.component + "' declares no connector '" + f.variable +
                             "' (add <ssd:Connector name=\"" + f.variable + "\" kind=\"parameter\">)");
        const auto elements = connector_elements(md, f.variable);
        if (elements.empty()) throw CosimError(f.place + ": " + unknown_variable_message(md, f.component, f.variable));
        const auto index =
            static_cast<std::size_t>(find_system_parameter(description_, f.parameter) - description_.parameters.data());
        const SystemParameter& p = description_.parameters[index];
        const std::string label = f.place + ": system parameter '" + p.name + "' -> " + f.component + "." + f.variable;
        if (elements.size() != 1)
            throw CosimError(label + ": an array of " + std::to_string(elements.size()) +
                             " elements; a system parameter feeds one scalar (connect each element)");
        const auto* v = elements.front();
        if (v->causality != Causality::parameter)
            throw CosimError(label + ": the end must be a parameter, it is " +
                             std::string(fmi_loader::to_string(v->causality)));
        if (!parameter_type_fits(p.type, v->type))
            throw CosimError(label + ": type mismatch (" + p.type + " to " +
                             std::string(fmi_loader::to_string(v->type)) + ")");
        if (!p.unit.empty() && !v->unit.empty() && p.unit != v->unit)
            throw CosimError(label + ": unit mismatch (" + p.unit + " to " + v->unit + ")");
        const auto& own = description_.components[c];
        for (std::size_t k = 0; k < own.parameters.size(); ++k)
            if (own.parameters[k].variable == v->name)
                throw CosimError(label + ": " + f.component + "." + v->name + " is also bound in its component's " +
                                 "ParameterBindings" +
                                 (k < own.parameter_places.size() ? " at " + own.parameter_places[k] : "") +
                                 ": say it once (remove that binding)");
        const SystemParameterValue& value = parameter_values_[index];
        if (value.place.empty())
            throw CosimError(p.place + ": system parameter '" + p.name +
                             "' has no value: bind it in the system's <ssd:ParameterBindings>, a parameter file "
                             "(--parameters) or --set " +
                             p.name + "=VALUE");
        Setting fed{f.component, v->name, value.value, value.ssv_type};
        try {
            (void)typed_value(md, *v, fed, "system parameter " + p.name + " for " + f.component + "." + v->name);
        } catch (const CosimError& e) {
            if (value.place == "--set") throw SettingError(e.what());
            throw CosimError(value.place + ": " + e.what());
        }
        fed_.emplace_back(c, std::move(fed));
    }
}

void System::check_parameter_value(const std::string& name, const std::string& value, const std::string& ssv_type,
                                   const std::string& where) const {
    for (std::size_t k = 0; k < fed_.size(); ++k) {
        if (description_.feeds[k].parameter != name) continue;
        const auto& [c, fed] = fed_[k];
        const auto& md = components_[c].description();
        (void)typed_value(md, *md.find_variable(fed.variable), Setting{fed.component, fed.variable, value, ssv_type},
                          where);
    }
}

std::vector<std::string> System::fed_parameters_set_directly() const {
    std::vector<std::string> out;
    for (std::size_t k = 0; k < fed_.size(); ++k) {
        // Not a structured binding: clang 14 (the fuzz build) cannot capture one in the lambda below.
        const std::size_t c = fed_[k].first;
        const auto& fed = fed_[k].second;
        const bool direct = std::any_of(settings_.begin(), settings_.end(), [&](const auto& s) {
            return s.first == c && s.second.variable == fed.variable;
        });
        if (direct)
            out.push_back(components_[c].name + "." + fed.variable + " (system parameter " +
                          description_.feeds[k].parameter + ")");
    }
    return out;
}

// Every setting names a variable of its component and holds a value of its type, checked here, before any
// run-time check: a misspelt name is the first thing reported, not a consequence of it. --set is reported as
// a SettingError, a parameter file's or the system's own binding with its file and line.
void System::check_settings() const {
    // The .ssd's (and its .ssv files') bindings, named by file and line.
    for (std::size_t i = 0; i < components_.size(); ++i) {
        const auto& md = components_[i].description();
        const auto& bindings = description_.components[i].parameters;
        const auto& places = description_.components[i].parameter_places;
        for (std::size_t k = 0; k < bindings.size(); ++k) {
            const auto& p = bindings[k];
            const std::string place = k < places.size() ? places[k] : description_.file.string();
            const auto* v = md.find_variable(p.variable);
            if (!v) throw CosimError(place + ": " + unknown_variable_message(md, components_[i].name, p.variable));
            try {
                (void)typed_value(md, *v, p, components_[i].name + "." + p.variable);
            } catch (const CosimError& e) {
                throw CosimError(place + ": " + e.what());
            }
        }
    }
    for (std::size_t k = 0; k < settings_.size(); ++k) {
        const auto& [index, setting] = settings_[k];
        const std::string& place = setting_places_[k];
        const auto& md = components_[index].description();
        const std::string where = components_[index].name + "." + setting.variable;
        const auto* v = md.find_variable(setting.variable);
        if (!v && place.empty())
            throw SettingError(unknown_variable_message(md, components_[index].name, setting.variable));
        if (!v)
            throw CosimError(place + ": " + unknown_variable_message(md, components_[index].name, setting.variable));
        try {
            (void)typed_value(md, *v, setting, where);
        } catch (const CosimError& e) {
            if (place.empty()) throw SettingError(e.what());
            throw CosimError(place + ": " + e.what());
        }
    }
}

std::optional<std::string> System::initial_value(std::size_t c, const std::string& variable) const {
    const auto& md = components_.at(c).description();
    const auto* v = md.find_variable(variable);
    if (!v) return std::nullopt;
    auto as_text = [&](const Setting& s) -> std::string {
        const TypedValue x = typed_value(md, *v, s, components_[c].name + "." + variable);
        if (const auto* r = std::get_if<double>(&x)) return format_real(*r);
        if (const auto* i = std::get_if<fmi2Integer>(&x)) return std::to_string(*i);
        if (const auto* b = std::get_if<bool>(&x)) return *b ? "true" : "false";
        return std::get<std::string>(x);
    };
    for (auto it = settings_.rbegin(); it != settings_.rend(); ++it)
        if (it->first == c && it->second.variable == variable) return as_text(it->second);
    for (const auto& [index, fed] : fed_)
        if (index == c && fed.variable == variable) return as_text(fed);
    const auto& bound = description_.components.at(c).parameters;
    for (auto it = bound.rbegin(); it != bound.rend(); ++it)
        if (it->variable == variable) return as_text(*it);
    return v->start;
}

std::size_t System::component_index(const std::string& name) const {
    for (std::size_t i = 0; i < components_.size(); ++i)
        if (components_[i].name == name) return i;
    std::vector<std::string> names;
    for (const auto& c : components_) names.push_back(c.name);
    throw CosimError(description_.file.string() + ": no component named '" + name + "'" + name_hint(name, names));
}

std::filesystem::path System::resolve_source(const std::string& source, const SystemOptions& options) const {
    return resolve_fmu(description_, source, options.fmu_dirs);
}

void System::load_components(const SystemOptions& options) {
    check_fmus_found(description_, options.fmu_dirs);
    std::size_t states = 0, indicators = 0;
    // Each FMU file is imported once per process (import_cache.hpp) and shared by the components made
    // from it; the loader's max_total_bytes counts the whole system: the .ssp's own unpacked bytes and
    // every FMU's.
    std::set<const fmi_loader::Fmu*> counted;
    fmi_loader::Limits budget;
    if (description_.archive)
        budget.max_total_bytes -= std::min(budget.max_total_bytes, unpacked_bytes(description_.archive->directory()));
    for (const auto& cd : description_.components) {
        for (const auto& other : components_)
            if (other.name == cd.name)
                throw CosimError(description_.file.string() + ": two components named '" + cd.name + "'");
        Component c;
        c.name = cd.name;
        c.fmu = import_fmu(resolve_source(cd.source, options), budget);
        if (counted.insert(c.fmu.get()).second)
            budget.max_total_bytes -= std::min(budget.max_total_bytes, unpacked_bytes(c.fmu->archive().directory()));
        const auto& md = c.fmu->description();
        const bool asked_cs = std::find(options.co_simulation.begin(), options.co_simulation.end(), cd.name) !=
                              options.co_simulation.end();
        const bool annotated_cs = !options.model_exchange_only && cd.execution && cd.execution->co_simulation;
        const bool want_cs = asked_cs || annotated_cs;
        if (cd.bridge) {
            // The block runs elsewhere: its description stays, its binary is never loaded.
            if (want_cs) throw CosimError(cd.name + ": a hardware-bridged component runs as Model Exchange only");
            BridgeDescription bridge = *cd.bridge;
            if (options.bridge_port && bridge.transport == "udp") bridge.port = *options.bridge_port;
            if (options.bridge_device && bridge.transport == "serial") bridge.device = *options.bridge_device;
            c.instance = std::make_unique<HardwareBridge>(md, cd.name, bridge);
            c.state_offset = states;
            c.indicator_offset = indicators;
            components_.push_back(std::move(c));
            continue;
        }
        if (md.is_fmi3()) refuse_unsupported_fmi3(md, cd.name);
        if (want_cs || !md.model_exchange) {
            if (!md.co_simulation) throw CosimError(cd.name + ": the FMU offers no Co-Simulation interface");
            c.interface = Interface::co_simulation;
        }
        const auto kind = c.interface == Interface::model_exchange ? fmi_loader::FmuKind::model_exchange
                                                                   : fmi_loader::FmuKind::co_simulation;
        if (md.is_fmi3())
            c.instance = std::make_unique<Fmi3Instance>(*c.fmu, kind, cd.name, options.fmi3_event_mode);
        else
            c.instance = std::make_unique<Fmi2Instance>(*c.fmu, kind, cd.name);
        if (c.interface == Interface::co_simulation) {
            c.communication_step = options.communication_step;
            if (!c.communication_step && annotated_cs) c.communication_step = cd.execution->communication_step;
            c.interpolates_inputs = md.co_simulation->can_interpolate_inputs;
        } else {
            c.completed_step_needed = !md.model_exchange->completed_integrator_step_not_needed;
        }
        if (c.interface == Interface::model_exchange) {
            c.state_offset = states;
            c.state_count = md.number_of_continuous_states();
            c.indicator_offset = indicators;
            c.indicator_count = md.number_of_event_indicators;
            states += c.state_count;
            indicators += c.indicator_count;
        }
        components_.push_back(std::move(c));
    }
}

void System::check_connectors() {
    for (std::size_t i = 0; i < components_.size(); ++i) {
        const auto& md = components_[i].description();
        for (const auto& k : description_.components[i].connectors) {
            const auto elements = connector_elements(md, k.name);  // an FMI 3.0 array: each element
            if (elements.empty())
                throw CosimError(components_[i].name + ": connector '" + k.name + "' is not a variable of its FMU");
            for (const auto* v : elements) {
                if (!kind_matches(k.kind, v->causality))
                    throw CosimError(components_[i].name + "." + k.name + ": declared " + kind_name(k.kind) +
                                     " in the .ssd but " + std::string(fmi_loader::to_string(v->causality)) +
                                     " in the FMU");
                if (!k.type.empty() && k.type != fmi_loader::to_string(v->type) &&
                    !(k.type == "Integer" && v->type == VariableType::enumeration))
                    throw CosimError(components_[i].name + "." + k.name + ": declared " + k.type + " in the .ssd but " +
                                     std::string(fmi_loader::to_string(v->type)) + " in the FMU");
                if (!k.unit.empty() && !v->unit.empty() && k.unit != v->unit)
                    throw CosimError(components_[i].name + "." + k.name + ": unit " + k.unit + " in the .ssd but " +
                                     v->unit + " in the FMU");
            }
        }
    }
}

void System::connect() {
    auto endpoint = [&](const std::string& comp, const std::string& conn, const std::string& place) {
        const std::size_t i = component_index(comp);
        const auto& declared = description_.components[i].connectors;
        if (!declared.empty() && std::none_of(declared.begin(), declared.end(),
                                              [&](const ConnectorDescription& d) { return d.name == conn; }))
            throw CosimError(place + ": component '" + comp + "' declares no connector '" + conn + "'");
        const auto v = connector_elements(components_[i].description(), conn);
        if (v.empty())
            throw CosimError(place + ": " + unknown_variable_message(components_[i].description(), comp, conn));
        return std::pair{i, v};
    };
    for (const auto& cd : description_.connections) {
        const std::string place = cd.place.empty() ? description_.file.string() : cd.place;
        const auto [from, sources] = endpoint(cd.start_element, cd.start_connector, place);
        const auto [to, targets] = endpoint(cd.end_element, cd.end_connector, place);
        if (sources.size() != targets.size())
            throw CosimError(place + ": " + cd.start_element + "." + cd.start_connector + " -> " + cd.end_element +
                             "." + cd.end_connector + ": " + std::to_string(sources.size()) + " elements to " +
                             std::to_string(targets.size()));
        for (std::size_t e = 0; e < sources.size(); ++e) {
            const auto* source = sources[e];
            const auto* target = targets[e];
            const std::string label =
                place + ": " + cd.start_element + "." + source->name + " -> " + cd.end_element + "." + target->name;
            if (source->causality != Causality::output && source->causality != Causality::calculated_parameter)
                throw CosimError(label + ": the start of a connection must be an output");
            if (target->causality != Causality::input)
                throw CosimError(label + ": the end of a connection must be an input");
            if (!same_type(source->type, target->type))
                throw CosimError(label + ": type mismatch (" + std::string(fmi_loader::to_string(source->type)) +
                                 " to " + std::string(fmi_loader::to_string(target->type)) + ")");
            if (!source->unit.empty() && !target->unit.empty() && source->unit != target->unit)
                throw CosimError(label + ": unit mismatch (" + source->unit + " to " + target->unit + ")");
            for (const auto& existing : connections_)
                if (existing.to == to && existing.target == target)
                    throw CosimError(label + ": the input already has a source (" + components_[existing.from].name +
                                     "." + existing.source->name + ")");
            connections_.push_back({from, to, source, target});
        }
    }
}

// Connection b must come after connection a when a feeds an input of a Model Exchange component
// whose output, the start of b, depends on that input directly (ModelStructure/Outputs; no list
// means "depends on every input"). A cycle of such edges is an algebraic loop, refused here.
void System::order_connections() {
    const std::size_t n = connections_.size();
    auto feeds_through = [&](const Connection& a, const Connection& b) {
        if (a.to != b.from || components_[a.to].interface != Interface::model_exchange) return false;
        const auto& md = components_[a.to].description();
        const std::size_t out_index = index_in(md, b.source) + 1;
        const std::size_t in_index = index_in(md, a.target) + 1;
        for (const auto& u : md.model_structure.outputs) {
            if (u.index != out_index) continue;
            if (!u.dependencies) return true;
            return std::find(u.dependencies->begin(), u.dependencies->end(), in_index) != u.dependencies->end();
        }
        return b.source->causality == Causality::output;  // an output missing from ModelStructure: assume the worst
    };
    std::vector<std::vector<std::size_t>> after(n);
    std::vector<std::size_t> indegree(n, 0);
    for (std::size_t a = 0; a < n; ++a)
        for (std::size_t b = 0; b < n; ++b)
            if (feeds_through(connections_[a], connections_[b])) {
                after[a].push_back(b);
                ++indegree[b];
            }
    std::vector<std::size_t> order, ready;
    for (std::size_t i = 0; i < n; ++i)
        if (indegree[i] == 0) ready.push_back(i);
    while (!ready.empty()) {
        const std::size_t i = ready.front();
        ready.erase(ready.begin());
        order.push_back(i);
        for (auto j : after[i])
            if (--indegree[j] == 0) ready.push_back(j);
    }
    if (order.size() != n) {
        std::string loop;
        for (std::size_t i = 0; i < n; ++i)
            if (indegree[i] > 0)
                loop += "\n  " + components_[connections_[i].from].name + "." + connections_[i].source->name + " -> " +
                        components_[connections_[i].to].name + "." + connections_[i].target->name;
        throw CosimError(description_.file.string() + ": algebraic loop through direct feedthrough:" + loop);
    }
    std::vector<Connection> sorted;
    for (auto i : order) sorted.push_back(connections_[i]);
    connections_ = std::move(sorted);
}

void System::check_open_inputs() const {
    for (std::size_t i = 0; i < components_.size(); ++i) {
        for (const auto& v : components_[i].description().model_variables) {
            if (v.causality != Causality::input || v.start) continue;
            const bool connected = std::any_of(connections_.begin(), connections_.end(),
                                               [&](const Connection& c) { return c.to == i && c.target == &v; });
            const bool set = std::any_of(settings_.begin(), settings_.end(),
                                         [&](const auto& s) { return s.first == i && s.second.variable == v.name; });
            if (!connected && !set)
                throw CosimError(components_[i].name + "." + v.name +
                                 ": input is not connected and has no start value");
        }
    }
}

// Kahn's order refined: among the connections ready to go, take one between the same two components
// as the last, so that runs of them can be copied in one call.
void System::group_transfers() {
    groups_.clear();
    for (const auto& c : connections_) {
        const bool real = c.source->type == VariableType::real;
        const bool continuous = real && c.target->variability == fmi_loader::Variability::continuous;
        if (!groups_.empty()) {
            auto& g = groups_.back();
            if (real && g.type == VariableType::real && g.from == c.from && g.to == c.to &&
                g.continuous_target == continuous) {
                g.source_vrs.push_back(c.source->value_reference);
                g.target_vrs.push_back(c.target->value_reference);
                continue;
            }
        }
        TransferGroup g;
        g.from = c.from;
        g.to = c.to;
        g.type = c.source->type;
        g.continuous_target = continuous;
        g.source_vrs = {c.source->value_reference};
        g.target_vrs = {c.target->value_reference};
        groups_.push_back(std::move(g));
    }
    for (auto& g : groups_) {
        g.values.assign(g.source_vrs.size(), 0.0);
        g.last.assign(g.source_vrs.size(), 0.0);
    }
}

void System::mark_continuous_consumers() {
    for (auto& c : components_) c.continuous_consumer = c.interface == Interface::model_exchange && c.has_dynamics();
    // A Model Exchange component feeding a consumer's continuous input must itself see its inputs
    // between events (its outputs may depend on them): up the connections until nothing changes.
    for (bool grew = true; grew;) {
        grew = false;
        for (const auto& g : groups_) {
            auto& source = components_[g.from];
            if (!components_[g.to].continuous_consumer || !g.continuous_target) continue;
            if (source.interface != Interface::model_exchange || source.continuous_consumer) continue;
            source.continuous_consumer = true;
            grew = true;
        }
    }
}

// The group's source values into g.values (and `text` for a String); true when they differ from the
// last ones given.
bool System::read_sources(TransferGroup& g, std::string& text) {
    auto& from = *components_[g.from].instance;
    // Nothing called on the source since it was last read: the values are the last ones given (read_sources
    // is always followed by accept() when they differ), so not read again.
    const auto version = from.values_version();
    if (g.given && version && g.read_at_version == version) return false;
    g.read_at_version = version;
    bool changed = !g.given;
    switch (g.type) {
        case VariableType::real:
            from.get_reals(g.source_vrs, g.values);
            break;
        case VariableType::integer:
        case VariableType::enumeration:
            g.values[0] = from.get_integer(g.source_vrs[0]);
            break;
        case VariableType::boolean:
            g.values[0] = from.get_boolean(g.source_vrs[0]) ? 1.0 : 0.0;
            break;
        case VariableType::string:
            text = from.get_string(g.source_vrs[0]);
            changed = changed || text != g.last_string;
            break;
    }
    for (std::size_t i = 0; i < g.values.size(); ++i) changed = changed || !same_bits(g.values[i], g.last[i]);
    return changed;
}

// What read_sources read becomes the last values given.
void System::accept(TransferGroup& g, std::string& text) {
    g.last.swap(g.values);
    if (g.type == VariableType::string) g.last_string = std::move(text);
    g.given = true;
}

void System::write_targets(const TransferGroup& g, std::span<const double> values, const std::string& text) {
    auto& to = *components_[g.to].instance;
    switch (g.type) {
        case VariableType::real:
            to.set_reals(g.target_vrs, values);
            break;
        case VariableType::integer:
        case VariableType::enumeration:
            to.set_integer(g.target_vrs[0], static_cast<fmi2Integer>(values[0]));
            break;
        case VariableType::boolean:
            to.set_boolean(g.target_vrs[0], values[0] != 0.0);
            break;
        case VariableType::string:
            to.set_string(g.target_vrs[0], text);
            break;
    }
}

bool System::transfer(TransferGroup& g, const std::function<void(std::size_t)>& before_discrete_change) {
    std::string text;
    // An unchanged value is not set again: the target keeps its evaluated outputs.
    if (!read_sources(g, text)) return false;
    if (!g.continuous_target && before_discrete_change) before_discrete_change(g.to);
    write_targets(g, g.values, text);
    accept(g, text);
    changed_[g.to] = 1;
    if (!g.continuous_target) discrete_changed_[g.to] = 1;
    return true;
}

bool System::propagate(Pass pass, const std::function<void(std::size_t)>& before_discrete_change) {
    bool changed = false;
    for (auto& g : groups_) {
        const auto& target = components_[g.to];
        if (pass != Pass::all && target.interface != Interface::model_exchange) continue;
        if (pass == Pass::integrating || pass == Pass::continuous) {
            if (!g.continuous_target || components_[g.from].interface != Interface::model_exchange) continue;
            if (pass == Pass::integrating && !target.continuous_consumer) continue;
        }
        changed = transfer(g, before_discrete_change) || changed;
    }
    return changed;
}

void System::clear_changes() {
    std::fill(changed_.begin(), changed_.end(), 0);
    std::fill(discrete_changed_.begin(), discrete_changed_.end(), 0);
}

void System::record_co_simulation_inputs(std::size_t c) {
    for (auto& g : groups_) {
        if (g.to != c) continue;
        g.step_start = g.last;
        g.step_start_string = g.last_string;
    }
}

void System::step_co_simulation(std::size_t c, double t, double h) {
    auto& target = *components_[c].instance;
    auto& slopes = slopes_;  // reused: no allocation per communication point
    for (auto& g : groups_) {
        if (g.to != c) continue;
        std::string text;
        if (read_sources(g, text)) accept(g, text);           // the sources' values now, at the end of the step: g.last
        write_targets(g, g.step_start, g.step_start_string);  // the step starts from the values at its start
        const bool interpolate = components_[c].interpolates_inputs && g.continuous_target && h > 0.0 &&
                                 components_[g.from].interface == Interface::model_exchange;
        if (!interpolate) continue;
        slopes.resize(g.last.size());
        for (std::size_t i = 0; i < slopes.size(); ++i) slopes[i] = (g.last[i] - g.step_start[i]) / h;
        target.set_real_input_derivatives(g.target_vrs, slopes);
    }
    target.do_step(t - h, h);
    record_co_simulation_inputs(c);
}

void System::initialize(double start_time, std::optional<double> stop_time) {
    for (std::size_t i = 0; i < components_.size(); ++i) {
        auto& c = components_[i];
        c.instance->setup_experiment(start_time, stop_time, tolerance_);
        for (const auto& p : description_.components[i].parameters) c.instance->apply(p);
        for (const auto& [index, fed] : fed_)
            if (index == i) c.instance->apply(fed);
        for (const auto& [index, setting] : settings_)
            if (index == i) c.instance->apply(setting);
    }
    for (auto& c : components_) c.instance->enter_initialization_mode();
    propagate(Pass::all);  // in connection order: each input sees its source's initial value
    for (auto& c : components_) c.instance->exit_initialization_mode();
    for (std::size_t i = 0; i < components_.size(); ++i)
        if (components_[i].interface == Interface::co_simulation) record_co_simulation_inputs(i);
    clear_changes();
}

}  // namespace cosim
