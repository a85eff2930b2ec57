// One run of a campaign: the system loaded with the spec's settings and the run's draws, run to the
// stop time with the metric observer (and, for a replay, the full CSV writer), reduced to its row.
// A run that throws (an FMU error, a value out of range) becomes a row with status "failed" and the
// message; the campaign goes on.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "campaign_spec.hpp"
#include "engine/system.hpp"
#include "engine/system_description.hpp"
#include "results_table.hpp"

namespace campaign {

// What every run of a campaign shares, prepared once per process.
struct CampaignSetup {
    CampaignSpec spec;
    cosim::SystemDescription description;
    cosim::SystemOptions options;  // FMU folders, the spec's [set] and the command line's --set
    double start_time = 0.0, stop_time = 0.0, output_interval = 0.0, tolerance = 0.0;
};

// Reads the system, applies the defaults `cosim run` uses (output interval: the .ssd's, else the
// FMUs' smallest DefaultExperiment stepSize but no finer than a thousandth of the run; tolerance: the
// FMUs' smallest, else 1e-6) and checks, by loading
// the system once, that every drawn variable and every metric column exists, so that a typo fails the
// campaign at once instead of every run. `extra_settings` (--set) may not name a drawn variable.
CampaignSetup prepare(CampaignSpec spec, const std::vector<std::filesystem::path>& fmu_dirs,
                      const std::vector<std::string>& extra_settings);

// `full_csv`: also write every output at every output point there (the replay of --run). A signal
// (cosim::install_interrupt_handlers) throws cosim::Interrupted out of it: that is not a failed run.
RunResult run_one(const CampaignSetup& setup, long index,
                  const std::optional<std::filesystem::path>& full_csv = std::nullopt);

}  // namespace campaign
