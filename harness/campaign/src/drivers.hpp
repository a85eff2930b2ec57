// How the runs still to do are executed: one after the other in this process, or spread over the
// ranks of an MPI job with dynamic distribution (rank 0 hands out one run index at a time to whichever
// rank asks, so long and short runs balance). Either way every finished row reaches the Collector on
// rank 0, which is what makes the two tables identical.
#pragma once

#include <vector>

#include "campaign_run.hpp"
#include "collector.hpp"

namespace campaign {

void run_sequential(const CampaignSetup& setup, const std::vector<long>& to_do, Collector& collector);

#ifdef PVATT_MPI
// Rank 0: hands out `to_do`, runs some itself on a second thread, collects every row.
void run_distributed(const CampaignSetup& setup, const std::vector<long>& to_do, Collector& collector, int ranks);
// Every other rank: asks rank 0 for work until told to stop.
void serve_as_worker(const CampaignSetup& setup);
#endif

}  // namespace campaign
