// `cosim run SYSTEM.ssd`: load, check and run a system; CSV results and run statistics.
#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "execution.hpp"
#include "system.hpp"

namespace cosim {

struct RunOptions {
    std::filesystem::path ssd;
    std::optional<double> stop_time, output_interval, tolerance, communication_step;
    std::optional<std::filesystem::path> csv;
    SystemOptions system;
    std::vector<std::string> columns;
    bool realtime = false;
    bool event_rows = false;
    bool reference = false;  // the reference execution (every component Model Exchange, every event everywhere)
    bool progress = true;  // a progress bar when stderr is a terminal and the run is long
};

RunStatistics run_system(const RunOptions& options, std::ostream& report);
void print_statistics(const RunStatistics& stats, std::ostream& out);

}  // namespace cosim
