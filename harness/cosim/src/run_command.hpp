// `cosim run SYSTEM.ssd`: load, check and run a system; CSV results and run statistics.
#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "engine/execution.hpp"
#include "engine/run_defaults.hpp"
#include "engine/system.hpp"

namespace cosim {

struct RunOptions {
    std::filesystem::path ssd;
    std::optional<double> stop_time, output_interval, tolerance, communication_step, max_step;
    std::optional<std::filesystem::path> csv;
    SystemOptions system;
    std::vector<std::string> columns;
    bool realtime = false;
    double realtime_tolerance = 1e-3;  // s
    bool event_rows = false;
    bool reference = false;       // the reference execution (every component Model Exchange, every event everywhere)
    bool progress = true;         // a progress bar when stderr is a terminal and the run is long
    bool force = false;           // run even past max_run_points or a CSV larger than the free disk space
    bool allow_mismatch = false;  // blocks that must agree and do not (analysis/couplings.hpp): warn, run
};

// From this many rows on, the CSV's size is announced on stderr before the run.
inline constexpr double large_output_rows = 1e6;

// Refuses, before the run: --cs of an unknown component, a non-finite stop time, intervals that are
// not positive and finite, longer than the run or more than max_run_points points, and a CSV that
// would not fit on its disk (the last two unless `force`). Throws Interrupted after a signal
// (install_interrupt_handlers), with the CSV closed and a line of statistics on `report`.
RunStatistics run_system(const RunOptions& options, std::ostream& report);
void print_statistics(const RunStatistics& stats, std::ostream& out);

}  // namespace cosim
