// What makes two invocations the same campaign: everything that decides a run's result (system, times,
// tolerance, seed, settings, draws, metrics) but not the number of runs. Written beside the results
// table as campaign.txt; --resume refuses a folder whose campaign.txt differs, so that rows of another
// stop time, seed or setting are never mixed into one table.
#pragma once

#include <filesystem>
#include <string>

#include "campaign_run.hpp"

namespace campaign {

std::string campaign_identity(const CampaignSetup& setup);

// Writes `identity` to dir/campaign.txt, or with `resume` checks it against the file there (an
// error naming the first line that differs).
void record_identity(const std::filesystem::path& dir, const std::string& identity, bool resume);

}  // namespace campaign
