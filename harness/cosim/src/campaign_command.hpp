// `cosim campaign SPEC`: a Monte-Carlo campaign of whole-system runs, in one process or over the
// ranks of an MPI job; `--run K` replays run K alone with its full CSV. README.md of this folder is
// the user's guide.
#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace campaign {

struct CampaignOptions {
    std::filesystem::path spec;
    std::optional<long> runs;
    std::optional<double> stop_time;
    std::optional<std::filesystem::path> output;
    std::vector<std::filesystem::path> fmu_dirs;  // after the spec's fmu_dirs
    std::vector<std::string> settings;            // --set, after the spec's [set]
    std::optional<long> replay;                   // --run K
    bool resume = false;
    bool figures = true;
    bool progress = true;         // on a terminal
    bool progress_lines = false;  // --progress: as log lines when stderr is not a terminal
};

// Returns the process exit code: 0 when the campaign completed (failed runs included: they are
// results), non-zero only for errors of the campaign itself, which throw.
int run_campaign(const CampaignOptions& options, std::ostream& out);

}  // namespace campaign
