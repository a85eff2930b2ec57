// How the runs still to do are executed: one after the other in this process, or spread over the
// ranks of an MPI job with dynamic distribution (rank 0 hands out one run index at a time to whichever
// rank asks, so long and short runs balance). Either way every finished row reaches the Collector on
// rank 0, which is what makes the two tables identical.
#pragma once

#include <map>
#include <mutex>
#include <string>

#include "campaign_run.hpp"
#include "collector.hpp"

namespace campaign {

// The run indices still to do, 0 to runs - 1 without those already in the table, handed out one at a
// time (no list of up to max_runs indices in memory). next() is safe from several threads.
class RunQueue {
public:
    RunQueue(long runs, const std::map<long, std::string>& done);
    long size() const { return size_; }
    long next();  // -1 when none is left
    void clear();

private:
    std::mutex mutex_;
    long runs_, next_ = 0, size_;
    const std::map<long, std::string>& done_;
};

void run_sequential(const CampaignSetup& setup, RunQueue& to_do, Collector& collector);

#ifdef PVATT_MPI
// Rank 0: hands out `to_do`, runs some itself on a second thread, collects every row.
void run_distributed(const CampaignSetup& setup, RunQueue& to_do, Collector& collector, int ranks);
// Every other rank: asks rank 0 for work until told to stop.
void serve_as_worker(const CampaignSetup& setup);
#endif

}  // namespace campaign
