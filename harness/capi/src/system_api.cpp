// pvatt_system_*: opening a system, listing it, settings and callback components.
#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstring>
#include <limits>

#include "capi_error.hpp"
#include "capi_handles.hpp"
#include "engine/callback_instance.hpp"
#include "engine/cosim_error.hpp"
#include "engine/interrupt.hpp"
#include "engine/run_defaults.hpp"
#include "engine/setting.hpp"
#include "fmi_loader/fmu.hpp"
#include "fmi_loader/loader_error.hpp"

using namespace pvatt_capi;

namespace {

constexpr double no_value = std::numeric_limits<double>::quiet_NaN();

// A lone FMU as a system of one component named after its file (ssr_plant.fmu -> ssr_plant), run
// through Model Exchange when it has it (as in a system), else through Co-Simulation.
cosim::SystemDescription single_fmu_system(const std::filesystem::path& fmu, cosim::SystemOptions& options) {
    const auto absolute = std::filesystem::absolute(fmu);
    cosim::SystemDescription d;
    d.file = absolute;
    d.name = absolute.stem().string();
    cosim::ComponentDescription c;
    c.name = d.name;
    c.source = absolute.string();
    d.components.push_back(c);
    const fmi_loader::Fmu probe(absolute);
    if (!probe.description().model_exchange) options.co_simulation.push_back(c.name);
    if (const auto& ex = probe.description().default_experiment) {
        d.start_time = ex->start_time;
        d.stop_time = ex->stop_time;
    }
    return d;
}

std::string_view type_name(fmi_loader::VariableType t) {
    switch (t) {
        case fmi_loader::VariableType::real:
            return "Real";
        case fmi_loader::VariableType::integer:
            return "Integer";
        case fmi_loader::VariableType::boolean:
            return "Boolean";
        case fmi_loader::VariableType::string:
            return "String";
        case fmi_loader::VariableType::enumeration:
            return "Enumeration";
    }
    return "";
}

// For the functions that return a value, not a status: whether the handle is open, with the message of
// a refusal as the last error when it is not.
bool usable(const pvatt_system* s) {
    return guarded([&] { open_system(s); }) == PVATT_OK;
}

const cosim::Component& component_at(const pvatt_system* s, std::size_t i) {
    const auto& comps = open_system(s).loaded->components();
    if (i >= comps.size())
        throw InvalidArgument("component index " + std::to_string(i) + " out of range (" +
                              std::to_string(comps.size()) + " components)");
    return comps[i];
}

}  // namespace

namespace pvatt_capi {

VariableRef find_variable(const cosim::System& system, const std::string& name) {
    const auto dot = name.find('.');
    if (dot == std::string::npos) throw InvalidArgument("expected component.variable, got '" + name + "'");
    const auto component = name.substr(0, dot);
    const auto& comps = system.components();
    for (std::size_t i = 0; i < comps.size(); ++i) {
        if (comps[i].name != component) continue;
        const auto* v = comps[i].description().find_variable(name.substr(dot + 1));
        if (!v) throw InvalidArgument("no variable '" + name.substr(dot + 1) + "' in component '" + component + "'");
        return {i, v};
    }
    throw InvalidArgument("no component named '" + component + "'");
}

std::unique_ptr<cosim::System> build_system(const pvatt_system& handle, bool reference) {
    cosim::SystemOptions options = handle.options;
    for (const auto& [name, value] : handle.settings) options.settings.push_back(name + "=" + value);
    if (reference) {
        options.model_exchange_only = true;
        options.co_simulation.clear();
    }
    auto system = std::make_unique<cosim::System>(handle.description, options);
    if (handle.replacements.empty()) return system;
    // A callback component keeps its FMU's interface and is a stateless Model Exchange component, as a
    // bridged one: the replaced FMU's states and indicators leave the integrator's vectors.
    std::size_t states = 0, indicators = 0;
    for (auto& c : system->components()) {
        if (const auto r = handle.replacements.find(c.name); r != handle.replacements.end()) {
            const auto callback = r->second.callback;
            void* const user = r->second.user_data;
            const std::string name = c.name;
            c.instance = std::make_unique<cosim::CallbackInstance>(
                c.description(), c.name, r->second.period,
                [callback, user, name](double t, std::span<const double> in, std::span<double> out) {
                    const CallbackScope inside;  // what the callback may call back (capi_registry.hpp)
                    if (callback(user, t, in.data(), in.size(), out.data(), out.size()) != 0)
                        throw CallbackFailed(name + ": the callback component failed at t = " + std::to_string(t));
                },
                r->second.current_inputs);
            c.interface = cosim::Interface::model_exchange;
            c.state_count = c.indicator_count = 0;
            c.completed_step_needed = false;
            c.communication_step.reset();
        }
        c.state_offset = states;
        c.indicator_offset = indicators;
        states += c.state_count;
        indicators += c.indicator_count;
    }
    return system;
}

}  // namespace pvatt_capi

namespace {

// A value checked against what it names: a system parameter (every component parameter it feeds), else
// "comp.var"; `ssv_type` as in a parameter file (empty: any). InvalidArgument naming `where` when refused.
void check_named_value(const pvatt_system& system, const std::string& n, const std::string& text,
                       const std::string& ssv_type, const std::string& where) {
    try {
        if (system.loaded->is_system_parameter(n))
            return system.loaded->check_parameter_value(n, text, ssv_type, where);
    } catch (const std::exception& e) {
        throw InvalidArgument(e.what());
    }
    const auto ref = find_variable(*system.loaded, n);
    const auto& md = system.loaded->components()[ref.component].description();
    try {
        cosim::typed_value(md, *ref.variable, {"", ref.variable->name, text, ssv_type}, where);
    } catch (const std::exception& e) {
        throw InvalidArgument(e.what());
    }
}

void keep_setting(pvatt_system& system, const std::string& n, const std::string& text) {
    auto it = std::find_if(system.settings.begin(), system.settings.end(), [&](const auto& p) { return p.first == n; });
    if (it != system.settings.end())
        it->second = text;
    else
        system.settings.emplace_back(n, text);
}

}  // namespace

extern "C" {

int pvatt_api_version(void) {
    return PVATT_API_VERSION;
}

pvatt_status pvatt_system_open(const char* path, const char* const* fmu_dirs, size_t fmu_dir_count,
                               pvatt_system** out) {
    return guarded([&] {
        required(out, "out");
        *out = nullptr;
        refuse_in_callback("pvatt_system_open");
        const std::filesystem::path file(required(path, "path"));
        if (fmu_dir_count) required(fmu_dirs, "fmu_dirs");
        BlockingCall blocking;  // unpacking the FMUs takes a while: Ctrl-C stops it
        auto handle = std::make_unique<pvatt_system>();
        for (std::size_t i = 0; i < fmu_dir_count; ++i)
            handle->options.fmu_dirs.emplace_back(required(fmu_dirs[i], "fmu_dirs[i]"));
        try {
            handle->description = file.extension() == ".fmu" ? single_fmu_system(file, handle->options)
                                                             : cosim::read_system_description(file);
            // Every run builds its System through the engine's import cache: each FMU is unpacked and
            // dlopen'ed once per process (an FMU with libstdc++ linked in keeps ~70 kB at each dlopen).
            handle->loaded = std::make_unique<cosim::System>(handle->description, handle->options);
        } catch (const fmi_loader::LoaderError& e) {
            if (e.code() != fmi_loader::LoaderErrc::cancelled) throw;
            blocking.reported();  // Ctrl-C while unpacking: an interrupt, reported as one
            throw cosim::Interrupted(SIGINT);
        }
        handle->variable_strings.resize(handle->loaded->components().size());
        for (std::size_t i = 0; i < handle->variable_strings.size(); ++i)
            handle->variable_strings[i].resize(handle->loaded->components()[i].description().model_variables.size());
        register_handle(handle.get());
        *out = handle.release();
    });
}

void pvatt_system_close(pvatt_system* system) {
    if (system && !close_system(system))
        set_last_error("pvatt_system_close: the system is not open (closed already, or never returned by the library)");
}

double pvatt_system_default_stop_time(const pvatt_system* system) {
    return usable(system) && system->description.stop_time ? *system->description.stop_time : no_value;
}

double pvatt_system_default_output_interval(const pvatt_system* system, double stop_time) {
    if (!usable(system)) return no_value;
    const double start = system->description.start_time.value_or(0.0);
    if (!(stop_time > start) || !std::isfinite(stop_time)) return no_value;
    return cosim::run_defaults(*system->loaded, start, stop_time).output_interval;
}

size_t pvatt_system_component_count(const pvatt_system* system) {
    return usable(system) ? system->loaded->components().size() : 0;
}

const char* pvatt_system_component_name(const pvatt_system* system, size_t component) {
    if (!usable(system) || component >= system->loaded->components().size()) return nullptr;
    return system->loaded->components()[component].name.c_str();
}

size_t pvatt_system_variable_count(const pvatt_system* system, size_t component) {
    if (!usable(system) || component >= system->loaded->components().size()) return 0;
    return system->loaded->components()[component].description().model_variables.size();
}

pvatt_status pvatt_system_variable(const pvatt_system* system, size_t component, size_t variable,
                                   pvatt_variable_info* out) {
    return guarded([&] {
        required(out, "out");
        const auto& c = component_at(system, component);
        const auto& md = c.description();
        if (variable >= md.model_variables.size())
            throw InvalidArgument("variable index " + std::to_string(variable) + " out of range (" + c.name + " has " +
                                  std::to_string(md.model_variables.size()) + ")");
        const auto& v = md.model_variables[variable];
        auto& strings = const_cast<pvatt_system*>(system)->variable_strings[component][variable];
        if (!strings) {
            strings = std::make_unique<pvatt_system::VariableStrings>();
            if (const auto* t = md.find_type(v.declared_type); t && v.type == fmi_loader::VariableType::enumeration)
                for (const auto& item : t->items) {
                    strings->items.push_back(item.name);
                    strings->item_values.push_back(static_cast<int>(item.value));
                }
            for (const auto& name : strings->items) strings->item_names.push_back(name.c_str());
        }
        out->name = v.name.c_str();
        out->type = type_name(v.type).data();
        out->causality = fmi_loader::to_string(v.causality).data();
        out->variability = fmi_loader::to_string(v.variability).data();
        out->unit = v.unit.c_str();
        out->description = v.description.c_str();
        out->start = v.start ? v.start->c_str() : "";
        out->item_count = strings->items.size();
        out->items = strings->items.empty() ? nullptr : strings->item_names.data();
        out->item_values = strings->items.empty() ? nullptr : strings->item_values.data();
        out->value_reference = v.value_reference;
    });
}

size_t pvatt_system_parameter_count(const pvatt_system* system) {
    return system ? system->description.parameters.size() : 0;
}

const char* pvatt_system_parameter_name(const pvatt_system* system, size_t parameter) {
    if (!system || parameter >= system->description.parameters.size()) return nullptr;
    return system->description.parameters[parameter].name.c_str();
}

pvatt_status pvatt_system_load_parameters(pvatt_system* system, const char* path) {
    return guarded([&] {
        required(system, "system");
        const std::filesystem::path file(required(path, "path"));
        cosim::ParameterValues read;
        try {
            read = cosim::read_parameter_values(file);
        } catch (const cosim::CosimError& e) {
            throw InvalidArgument(e.what());
        }
        for (std::size_t k = 0; k < read.values.size(); ++k) {
            const auto& v = read.values[k];
            try {
                check_named_value(*system, v.variable, v.value, v.ssv_type, read.places[k] + ": " + v.variable);
            } catch (const InvalidArgument& e) {
                const std::string what = e.what();
                throw InvalidArgument(what.starts_with(read.places[k]) ? what : read.places[k] + ": " + what);
            }
        }
        for (const auto& v : read.values) keep_setting(*system, v.variable, v.value);
    });
}

pvatt_status pvatt_system_set(pvatt_system* system, const char* name, const char* value) {
    return guarded([&] {
        open_system(system);
        const std::string n(required(name, "name")), text(required(value, "value"));
        if (system->loaded->is_system_parameter(n)) {
            check_named_value(*system, n, text, "", n);
            return keep_setting(*system, n, text);
        }
        const auto ref = find_variable(*system->loaded, n);
        const auto& md = system->loaded->components()[ref.component].description();
        cosim::Setting s{system->loaded->components()[ref.component].name, ref.variable->name, text, ""};
        try {
            cosim::typed_value(md, *ref.variable, s, n);  // refuses a value the variable cannot take
        } catch (const std::exception& e) {
            throw InvalidArgument(e.what());
        }
        auto it =
            std::find_if(system->settings.begin(), system->settings.end(), [&](const auto& p) { return p.first == n; });
        if (it != system->settings.end())
            it->second = text;
        else
            system->settings.emplace_back(n, text);
    });
}

pvatt_status pvatt_system_get(const pvatt_system* system, const char* name, char* buffer, size_t size, size_t* needed) {
    std::string text;
    const pvatt_status found = guarded([&] {
        open_system(system);
        const std::string n(required(name, "name"));
        if (system->loaded->is_system_parameter(n)) {
            // The value set, else the one this system's loading took (its bindings).
            const auto it = std::find_if(system->settings.begin(), system->settings.end(),
                                         [&](const auto& p) { return p.first == n; });
            if (it != system->settings.end()) {
                text = it->second;
                return;
            }
            const auto& params = system->description.parameters;
            for (std::size_t i = 0; i < params.size(); ++i)
                if (params[i].name == n) text = system->loaded->system_parameter_values()[i].value;
            return;
        }
        const auto ref = find_variable(*system->loaded, n);
        const auto it =
            std::find_if(system->settings.begin(), system->settings.end(), [&](const auto& p) { return p.first == n; });
        if (it != system->settings.end()) {
            text = it->second;
            return;
        }
        // The description's parameter binding, else the FMU's start value.
        const auto& cd = system->description.components[ref.component];
        for (const auto& p : cd.parameters)
            if (p.variable == ref.variable->name) text = p.value;
        if (text.empty()) text = ref.variable->start.value_or("");
    });
    return found != PVATT_OK ? found : guarded([&] { copy_text(text, buffer, size, needed); });
}

void pvatt_system_clear_settings(pvatt_system* system) {
    if (usable(system)) system->settings.clear();
}

pvatt_status pvatt_system_replace(pvatt_system* system, const char* component, double sample_period,
                                  pvatt_step_callback callback, void* user_data) {
    return guarded([&] {
        open_system(system);
        const std::string name(required(component, "component"));
        const auto& comps = system->loaded->components();
        if (std::none_of(comps.begin(), comps.end(), [&](const auto& c) { return c.name == name; }))
            throw InvalidArgument("no component named '" + name + "'");
        if (!callback) {
            system->replacements.erase(name);
            return;
        }
        if (!(sample_period > 0.0) || !std::isfinite(sample_period))
            throw InvalidArgument(name + ": the sample period must be positive and finite, got " +
                                  std::to_string(sample_period));
        system->replacements[name] = {sample_period, callback, user_data};
    });
}

pvatt_status pvatt_system_replace_current_inputs(pvatt_system* system, const char* component, int current_inputs) {
    return guarded([&] {
        required(system, "system");
        const std::string name(required(component, "component"));
        const auto r = system->replacements.find(name);
        if (r == system->replacements.end())
            throw InvalidArgument("'" + name + "' is not replaced by a callback (pvatt_system_replace first)");
        r->second.current_inputs = current_inputs != 0;
    });
}

}  // extern "C"
