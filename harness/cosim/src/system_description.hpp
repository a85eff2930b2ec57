// An SSP 1.0 System Structure Description (.ssd) as plain data: components with their source and
// connectors, parameter values (inline or from a referenced .ssv), connections and the default
// experiment. Parsed with libxml2 with no network access and no DTD or external entities.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace cosim {

enum class ConnectorKind { input, output, parameter, calculated_parameter, inout, unspecified };

struct ConnectorDescription {
    std::string name;
    ConnectorKind kind = ConnectorKind::unspecified;
    std::string type;  // "Real", "Integer", "Boolean", "String", "Enumeration" or "" when not given
    std::string unit;
};

struct ParameterValue {
    std::string name;
    std::string type;   // "Real", "Integer", "Boolean", "String", "Enumeration"
    std::string value;  // as written
};

struct ComponentDescription {
    std::string name;
    std::string source;  // as written in the .ssd
    std::vector<ConnectorDescription> connectors;
    std::vector<ParameterValue> parameters;
};

struct ConnectionDescription {
    std::string start_element, start_connector, end_element, end_connector;
};

struct SystemDescription {
    std::filesystem::path file;  // where it was read from; relative sources resolve against it
    std::string name;
    std::vector<ComponentDescription> components;
    std::vector<ConnectionDescription> connections;
    std::optional<double> start_time, stop_time;
};

// Throws CosimError naming the file, line and cause for anything malformed or unsupported.
SystemDescription read_system_description(const std::filesystem::path& ssd);

}  // namespace cosim
