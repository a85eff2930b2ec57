// Rank 0's end of a campaign: every finished row, whichever rank ran it, goes through accept(), which
// appends it to the results table at once, counts it for the campaign's statistics and updates the
// progress line on a terminal.
#pragma once

#include <chrono>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "results_table.hpp"

namespace campaign {

struct RankStatistics {
    long runs = 0;
    double busy = 0.0;  // s of wall time spent in runs
};

struct CampaignStatistics {
    long runs = 0, failed = 0, stopped = 0;  // done by this invocation
    double wall_time = 0.0;
    std::vector<RankStatistics> ranks;
};

// Progress: none; on a terminal (one line rewritten 4 times a second); or as log lines every 10 s
// (--progress under mpirun or a batch system, where stderr is not a terminal).
enum class Progress { none, terminal, log };

class Collector {
public:
    Collector(ResultsWriter& writer, std::map<long, std::string>& rows, long to_do, int ranks, Progress progress);
    void accept(int rank, const std::string& row);
    CampaignStatistics finish();  // clears the progress line

private:
    void show_progress();
    ResultsWriter& writer_;
    std::map<long, std::string>& rows_;
    long to_do_;
    Progress progress_;
    CampaignStatistics stats_;
    std::chrono::steady_clock::time_point started_, last_shown_;
    bool shown_ = false;
};

void print_statistics(const CampaignStatistics& stats, std::ostream& out);

}  // namespace campaign
