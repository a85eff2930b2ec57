// A loaded system: the components of an .ssd instantiated from their FMUs, the connections checked
// (names, causality, type, unit, one source per input, start values of open inputs, algebraic
// loops) and put in an order in which values can flow in one pass.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "component_instance.hpp"
#include "fmi_loader/fmu.hpp"
#include "system_description.hpp"

namespace cosim {

enum class Interface { model_exchange, co_simulation };

struct Component {
    std::string name;
    std::unique_ptr<fmi_loader::Fmu> fmu;  // its modelDescription; its binary too unless bridged
    std::unique_ptr<ComponentInstance> instance;  // Fmi2Instance, or HardwareBridge when bridged
    Interface interface = Interface::model_exchange;
    std::size_t state_offset = 0, state_count = 0;          // slice of the ME state vector
    std::size_t indicator_offset = 0, indicator_count = 0;  // slice of the root functions
    double next_time_event = 0.0;                           // +inf when none
    long rhs_evaluations = 0;
    long events = 0;
    const fmi_loader::ModelDescription& description() const { return fmu->description(); }
};

struct Connection {
    std::size_t from, to;  // component indices
    const fmi_loader::ScalarVariable* source;
    const fmi_loader::ScalarVariable* target;
};

struct SystemOptions {
    std::vector<std::filesystem::path> fmu_dirs;  // searched for a source not found beside the .ssd
    std::vector<std::string> settings;            // "component.variable=value", after the .ssd's parameters
    std::vector<std::string> co_simulation;       // components to run through their CS interface
    std::optional<double> tolerance;
    std::optional<int> bridge_port;               // replaces the port of every UDP hardware bridge
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

    // Copy each connection's source value to its target, in order. In continuous-time mode only
    // continuous Real inputs of Model Exchange components may be set, and only Model Exchange sources
    // change between communication points: `integrating` restricts the pass to those. Outputs of
    // Co-Simulation components are passed on only when `with_cs_sources` (at communication points).
    // Returns true when any target received a value different from the last one it was given.
    bool propagate(bool integrating, bool with_cs_sources = true);
    // Only the connections that end at `target_kind` components (values into CS inputs before a step).
    void propagate_into(Interface target_kind);

    // Setup, parameters, initialization mode with values propagated, exit.
    void initialize(double start_time, std::optional<double> stop_time);

private:
    std::filesystem::path resolve_source(const std::string& source, const SystemOptions& options) const;
    void load_components(const SystemOptions& options);
    void check_connectors();
    void connect();
    void order_connections();
    void check_open_inputs() const;
    bool transfer(std::size_t index);

    SystemDescription description_;
    std::vector<Component> components_;
    std::vector<Connection> connections_;
    std::vector<std::string> last_values_;  // per connection, what was last transferred (as text)
    std::vector<std::pair<std::size_t, std::string>> settings_;  // component, "variable=value"
    std::optional<double> tolerance_;
};

}  // namespace cosim
