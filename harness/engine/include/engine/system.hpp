// A loaded system: the components of an .ssd instantiated from their FMUs, the connections checked
// (names, causality, type, unit, one source per input, start values of open inputs, algebraic
// loops) and put in an order in which values can flow in one pass.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "engine/component_instance.hpp"
#include "engine/setting.hpp"
#include "engine/system_description.hpp"
#include "fmi_loader/fmu.hpp"

namespace cosim {

enum class Interface { model_exchange, co_simulation };

struct Component {
    std::string name;
    std::shared_ptr<fmi_loader::Fmu> fmu;         // its modelDescription; its binary too unless bridged
    std::unique_ptr<ComponentInstance> instance;  // Fmi2Instance, or HardwareBridge when bridged
    Interface interface = Interface::model_exchange;
    std::size_t state_offset = 0, state_count = 0;          // slice of the ME state vector
    std::size_t indicator_offset = 0, indicator_count = 0;  // slice of the root functions
    std::optional<double> communication_step;               // Co-Simulation: its own step (.ssd annotation or --step)
    bool interpolates_inputs = false;                       // Co-Simulation: canInterpolateInputs
    bool completed_step_needed = false;                     // Model Exchange: wants fmi2CompletedIntegratorStep
    // Model Exchange components whose inputs matter between events: those with states or event
    // indicators, and those whose outputs feed them. The others see their inputs at events only.
    bool continuous_consumer = false;
    double next_time_event = 0.0;  // +inf when none
    long rhs_evaluations = 0;
    long events = 0;
    bool has_dynamics() const { return state_count > 0 || indicator_count > 0; }
    // The instance's view (an FMI 3.0 FMU's arrays as scalars); the FMU's own before it is instantiated.
    const fmi_loader::ModelDescription& description() const {
        return instance ? instance->description() : fmu->description();
    }
};

struct Connection {
    std::size_t from, to;  // component indices
    const fmi_loader::ScalarVariable* source;
    const fmi_loader::ScalarVariable* target;
};

struct SystemOptions {
    std::vector<std::filesystem::path> fmu_dirs;  // searched for a source not found beside the .ssd
    // Parameter sets (.ssv) read after the .ssd's own bindings, later files winning; their names are system
    // parameters or component.variable, as in the system's own <ssd:ParameterBindings> (SSP 1.0).
    std::vector<std::filesystem::path> parameter_files;
    // "component.variable=value", or "name=value" for a system parameter; after the parameter files.
    std::vector<std::string> settings;
    std::vector<std::string> co_simulation;    // components to run through their CS interface
    std::optional<double> communication_step;  // of every Co-Simulation component (replaces the .ssd's)
    bool model_exchange_only = false;          // ignore the .ssd's execution annotations (reference runs)
    std::optional<double> tolerance;
    std::optional<int> bridge_port;            // replaces the port of every UDP hardware bridge
    std::optional<std::string> bridge_device;  // replaces the device of every serial hardware bridge
    bool fmi3_event_mode = true;               // FMI 3.0 Co-Simulation: use event mode where the FMU has it
};

// Consecutive connections (in flow order) between the same two components, copied in one get and
// one set call. Reals are batched; any other type travels one connection per group. The last values
// given are kept for change detection (Reals compared bit for bit).
struct TransferGroup {
    std::size_t from = 0, to = 0;
    fmi_loader::VariableType type = fmi_loader::VariableType::real;
    bool continuous_target = false;  // every target a continuous Real input
    std::vector<fmi2ValueReference> source_vrs, target_vrs;
    std::vector<double> values, last;  // Reals (and Integer/Boolean as exact doubles)
    std::string last_string;
    bool given = false;  // a value was transferred at least once
    // The source's values_version() when it was last read: while it stays, its values are `last`.
    std::optional<std::uint64_t> read_at_version;
    // Co-Simulation targets: the values at the last communication point, the start of the next step.
    std::vector<double> step_start;
    std::string step_start_string;
};

// Which connections a propagation pass copies.
enum class Pass {
    all,          // every connection (initialization)
    integrating,  // between events: continuous Real inputs of continuous consumers, from Model Exchange sources
    continuous,   // at an output point or before an event: every continuous Real input of Model Exchange components
    event,        // in event mode: every input of Model Exchange components
};

// A system parameter's value as the run takes it, and where it was given.
struct SystemParameterValue {
    std::string value;     // as written; empty with no place: none given
    std::string ssv_type;  // the binding's SSV type, empty from --set
    std::string place;     // "file:line", or "--set"
};

class System {
public:
    System(const SystemDescription& description, const SystemOptions& options);

    std::vector<Component>& components() { return components_; }
    const std::vector<Component>& components() const { return components_; }
    // In an order in which one pass gives every input its source's current value.
    const std::vector<Connection>& connections() const { return connections_; }
    const SystemDescription& description() const { return description_; }
    std::size_t component_index(const std::string& name) const;

    // Copy source values to targets in an order in which one pass gives every input its source's
    // current value. Co-Simulation inputs are set only by step_co_simulation. Returns true when any
    // target received a value different from the last one it was given; input_changed(c) tells which.
    // In Pass::event, a discrete input about to change is announced first (the master puts its
    // component into event mode, the only mode in which it may be set).
    bool propagate(Pass pass, const std::function<void(std::size_t)>& before_discrete_change = {});
    bool input_changed(std::size_t component) const { return changed_[component] != 0; }
    // A discrete (not continuous-Real) input changed: the component must go through event mode.
    bool discrete_input_changed(std::size_t component) const { return discrete_changed_[component] != 0; }
    void clear_changes();

    // Steps Co-Simulation component c from t - h to t. Its inputs follow their sources' values at
    // t - h (recorded by the previous call, or at initialization) and, where the FMU can
    // interpolate, move linearly to the values they have now; the current values are recorded.
    void step_co_simulation(std::size_t c, double t, double h);

    // Setup, parameters, initialization mode with values propagated, exit.
    void initialize(double start_time, std::optional<double> stop_time);

    // The system's parameters (description().parameters, same order) with the values this run gives them.
    const std::vector<SystemParameterValue>& system_parameter_values() const { return parameter_values_; }
    bool is_system_parameter(const std::string& name) const { return find_system_parameter(description_, name); }
    // Component parameters a system parameter feeds that are also set directly (component.variable in a
    // parameter file, the system's bindings or --set): the direct value wins for that component only.
    // "est.inertia[1] (system parameter inertia[1])", one per such parameter.
    std::vector<std::string> fed_parameters_set_directly() const;
    // Refuses (CosimError naming `where`) a value that some component parameter the system parameter `name`
    // feeds cannot take; `ssv_type` as in Setting (empty: any).
    void check_parameter_value(const std::string& name, const std::string& value, const std::string& ssv_type,
                               const std::string& where) const;

    // The value initialize() gives variable `variable` of component c: the last direct setting naming it
    // (--set, a parameter file, the system's bindings), else the system parameter feeding it, else the
    // .ssd's binding, else the FMU's start value (as its text; an Enumeration as its number); nullopt when
    // none (no such variable, or no start). For checks made before a run (front ends).
    std::optional<std::string> initial_value(std::size_t c, const std::string& variable) const;

private:
    std::filesystem::path resolve_source(const std::string& source, const SystemOptions& options) const;
    void load_components(const SystemOptions& options);
    void check_connectors();
    void connect();
    void order_connections();
    void check_open_inputs() const;
    void check_settings() const;
    void collect_values(const SystemOptions& options);
    void take_value(const Setting& named, const std::string& place, bool command_line);
    void connect_parameters();
    void mark_continuous_consumers();
    void group_transfers();
    bool read_sources(TransferGroup& g, std::string& text);
    void accept(TransferGroup& g, std::string& text);
    void write_targets(const TransferGroup& g, std::span<const double> values, const std::string& text);
    bool transfer(TransferGroup& g, const std::function<void(std::size_t)>& before_discrete_change);
    void record_co_simulation_inputs(std::size_t c);

    SystemDescription description_;
    std::vector<Component> components_;
    std::vector<Connection> connections_;
    std::vector<TransferGroup> groups_;             // connections_ in order, batched by (source, target) component
    std::vector<char> changed_, discrete_changed_;  // per component, since clear_changes()
    std::vector<double> slopes_;                    // step_co_simulation's input derivatives
    std::vector<std::pair<std::size_t, Setting>> settings_;  // component index, its setting (direct, in order)
    std::vector<std::string> setting_places_;                // of each: "file:line", or "" for --set
    std::vector<SystemParameterValue> parameter_values_;     // per description_.parameters
    std::vector<std::pair<std::size_t, Setting>> fed_;       // component index, the value a system parameter feeds
    std::optional<double> tolerance_;
};

}  // namespace cosim
