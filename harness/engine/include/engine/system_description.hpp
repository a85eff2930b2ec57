// An SSP 1.0 System Structure Description (.ssd) as plain data: components with their source and
// connectors, parameter values (inline or from a referenced .ssv), connections and the default
// experiment. Parsed with libxml2 with no network access and no DTD or external entities.
#pragma once

#include <cstdint>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/setting.hpp"
#include "fmi_loader/fmu_archive.hpp"

namespace cosim {

// The largest .ssd read (16 MiB: the bundled systems are a few kB).
inline constexpr std::uintmax_t max_ssd_bytes = std::uintmax_t{16} << 20;

enum class ConnectorKind { input, output, parameter, calculated_parameter, inout, unspecified };

struct ConnectorDescription {
    std::string name;
    ConnectorKind kind = ConnectorKind::unspecified;
    std::string type;  // "Real", "Integer", "Boolean", "String", "Enumeration" or "" when not given
    std::string unit;
};

// A component run on external hardware instead of its FMU (protocol/README.md): the .ssd
// marks it with <ssc:Annotation type="org.pvatt.hardware-bridge"><hw:Bridge .../></ssc:Annotation>.
inline constexpr const char* hardware_bridge_annotation = "org.pvatt.hardware-bridge";

struct BridgeDescription {
    std::string transport = "udp";  // "udp" or "serial"
    std::string host = "127.0.0.1";
    int port = 50505;
    std::string device;           // serial only
    int baud = 115200;            // serial only
    int timeout_ms = 200;         // how long to wait for each answer
    int max_misses = 5;           // consecutive misses before policy "stop" gives up
    std::string policy = "hold";  // "hold" (keep the last outputs) or "stop" (error)
};

// How the master runs a component and what it writes by default, when the .ssd says
// (<ssc:Annotation type="org.pvatt.execution">, see harness/systems/README.md).
inline constexpr const char* execution_annotation = "org.pvatt.execution";

struct ExecutionHint {
    bool co_simulation = false;                // interface="CoSimulation": its own solver, its own step
    std::optional<double> communication_step;  // communicationStep="0.001"
};

struct ComponentDescription {
    std::string name;
    std::string source;  // as written in the .ssd
    std::vector<ConnectorDescription> connectors;
    std::vector<Setting> parameters;            // its parameter bindings: variable, value and SSV type as written
    std::vector<std::string> parameter_places;  // "file:line" of each binding (the .ssd or .ssv), for messages
    std::optional<BridgeDescription> bridge;
    std::optional<ExecutionHint> execution;
};

struct ConnectionDescription {
    std::string start_element, start_connector, end_element, end_connector;
    std::string place;  // "file:line" of its <ssd:Connection>, for messages
};

// A parameter of the system itself, the SSP 1.0 way: an <ssd:Connector kind="parameter"> of the <ssd:System>
// (typed: <ssc:Real unit=".."/>, Integer, Boolean, String or Enumeration), its value from the system's own
// <ssd:ParameterBindings>, and <ssd:Connection>s that leave out the system's element (startElement or
// endElement absent) carrying it to components' parameters. The scenario's facts that several blocks
// share (the date at t = 0, the orbit, the spacecraft's properties) are said once this way.
struct SystemParameter {
    std::string name;  // no '.' (a '.' separates component and variable in every setting)
    std::string type;  // "Real", "Integer", "Boolean", "String" or "Enumeration"
    std::string unit;
    std::string place;  // "file:line" of its connector
};

// A connection from a system parameter to a component's parameter.
struct ParameterFeed {
    std::string parameter;  // the system parameter
    std::string component, variable;
    std::string place;  // "file:line" of its <ssd:Connection>
};

// Values read from a parameter set (.ssv, or a binding's inline <ssv:ParameterSet>): each name as written
// (a system parameter, or component.variable at the system level), its value and SSV type, and where.
struct ParameterValues {
    std::vector<Setting> values;      // component empty; variable holds the name as written
    std::vector<std::string> places;  // "file:line" of each
};

struct SystemDescription {
    std::filesystem::path file;  // where it was read from; relative sources resolve against it
    // An SSP archive (.ssp) read from: unpacked in a private directory kept while any copy of this
    // description lives; `file` is its SystemStructure.ssd, the FMUs lie beside it under resources/.
    std::shared_ptr<const fmi_loader::FmuArchive> archive;
    std::vector<std::filesystem::path> parameter_files;  // the .ssv files its bindings read
    std::string name;
    std::vector<ComponentDescription> components;
    std::vector<ConnectionDescription> connections;  // between components
    std::vector<SystemParameter> parameters;         // the system's own parameter connectors
    std::vector<ParameterFeed> feeds;                // system parameter -> component parameter
    // The system's own <ssd:ParameterBindings>, in order: a system parameter's name, or component.variable
    // (SSP's hierarchical name; it takes precedence over the component's own binding).
    ParameterValues system_bindings;
    std::optional<double> start_time, stop_time;
    std::optional<double> output_interval;  // DefaultExperiment's execution annotation <Output interval=".."/>
    std::optional<double> max_step;         // and <Integrator maxStep=".."/>
    // and <Stop orbits=".."/>: the run lasts this many orbits of the system's truth, derived by the front
    // end that knows the system (harness/systems/analysis) instead of written; stopTime stays for other tools.
    std::optional<double> stop_orbits;
    // and <Measures report="attitude consistency first_valid faults" convergedAfter=".."/>: what a run of
    // this system says it reached at its end (the names are the analysis front end's, checked there).
    struct Measures {
        std::vector<std::string> report;
        std::optional<double> converged_after;  // s: "after convergence" starts here
    };
    std::optional<Measures> measures;
};

// An .ssd, or an .ssp archive (by its extension) unpacked first within the loader's archive limits
// (fmi_loader/limits.hpp: entries, sizes, compression ratio, no path leaving the archive).
// Throws CosimError naming the file, line and cause for anything malformed or unsupported.
SystemDescription read_system_description(const std::filesystem::path& ssd);

// An SSP parameter set file (.ssv, root <ssv:ParameterSet>), its names as written. Refused with CosimError
// naming the file, line and parameter: not a regular file, over max_ssd_bytes, not well-formed, another root,
// a parameter without a name or a typed value, a typed value without its value attribute.
ParameterValues read_parameter_values(const std::filesystem::path& ssv);

// The system parameter of that name, or null.
const SystemParameter* find_system_parameter(const SystemDescription& d, const std::string& name);

// A file an .ssp names (a component's source, a parameter file): an .ssp is a closed world, so only a
// relative reference that stays inside the unpacked archive is taken (resolved against its root, where
// SystemStructure.ssd is). Refused with CosimError: a URI with a scheme (file:, http:, ...), an absolute
// path, a path that climbs out with '..', or one that leaves the archive through a link.
std::filesystem::path inside_archive(const fmi_loader::FmuArchive& archive, const std::string& reference,
                                     const std::string& what);

}  // namespace cosim
