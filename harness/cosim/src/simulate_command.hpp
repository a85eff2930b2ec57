// `cosim simulate X.fmu`: one FMU on its own in Co-Simulation, results as a table or CSV.
#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace cosim {

struct SimulateOptions {
    std::filesystem::path fmu;
    std::optional<double> stop_time, output_interval, tolerance;
    std::vector<std::string> settings;  // "name=value", applied before initialization
    std::vector<std::string> columns;   // variables to report; empty: every output
    std::optional<std::filesystem::path> csv;
    bool fmi3_event_mode = true;  // an FMI 3.0 FMU with event mode: use it (false: the FMU handles its events)
};

// Runs the FMU; writes CSV to options.csv if given, else a fixed-width table to `out`.
void simulate(const SimulateOptions& options, std::ostream& out);

}  // namespace cosim
