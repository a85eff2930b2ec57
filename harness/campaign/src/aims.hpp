// What every run of a campaign should reach (its [[aim]] entries: issue 39's "sunlit p95 below 1 deg" and the
// like), judged per run from the results table: how many runs meet each aim, which miss it, and how many meet
// every aim. The summary's "Aims" section and the end of `cosim campaign` say it, so a campaign answers the
// question it was run for instead of leaving the count to whoever reads the table.
#pragma once

#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "campaign_spec.hpp"
#include "summary.hpp"

namespace campaign {

// The aim as a condition, "error_sunlit.p95 < 1", "nees_sunlit.per_dof in [0.5, 1.5]".
std::string aim_text(const Aim& aim);

// Whether a value meets the aim (a NaN never does).
bool meets(const Aim& aim, double value);

struct AimTally {
    long met = 0, missed = 0, not_judged = 0;
    std::vector<std::string> missing_runs;  // the run numbers that miss it, in table order
};

struct AimsReport {
    long finished = 0;                     // runs with status ok or stopped: the runs judged
    long failed = 0;                       // not judged (a failed run has no metric cells)
    std::vector<AimTally> per_aim;         // in the spec's order
    long every = 0;                        // finished runs that meet every aim they are judged by
    std::vector<std::string> missing_any;  // the finished runs that miss at least one
};

// Judges every finished run of the table by the spec's aims. A run with no value in an aim's column (the
// metric sampled nothing: a run without an eclipse) misses it, unless the aim says skip_empty, which leaves
// that run not judged by it.
// `keep` selects the rows judged (all when empty).
AimsReport judge_aims(const CampaignSpec& spec, const ResultRows& table,
                      const std::function<bool(const std::vector<std::string>&)>& keep = {});

// The same per value of each drawn column that holds names (an orbit draw's class, a choice or grid of text: at
// most max_category_values of them) and per case: which kinds of scene meet the aims.
inline constexpr std::size_t max_category_values = 20;
struct AimsByValue {
    std::string column;
    std::vector<std::pair<std::string, AimsReport>> values;  // in order of first appearance
};
std::vector<AimsByValue> judge_aims_by_category(const CampaignSpec& spec, const ResultRows& table);

// Throws CampaignError naming the aim when its column is not one of the spec's metric or measure columns.
void check_aim_columns(const CampaignSpec& spec);

// The summary's section (nothing when the spec has no aims).
void write_aims(std::ostream& md, const CampaignSpec& spec, const AimsReport& report,
                const std::vector<AimsByValue>& by_category);
// The end of `cosim campaign` (nothing when the spec has no aims): per aim, then every aim per category.
void print_aims(const CampaignSpec& spec, const AimsReport& report, const std::vector<AimsByValue>& by_category,
                std::ostream& out);

// The same as JSON, for the C API (pvatt_campaign_aims) and Python (CampaignResult.aims): {"finished",
// "failed", "every", "missing_any": [runs], "aims": [{"column", "condition", "kind", "low", "high",
// "skip_empty", "met", "missed", "not_judged", "missing_runs": [runs]}], "by_category": [{"column",
// "values": [{"value", "finished", "failed", "every", "met": [per aim], "judged": [per aim]}]}]}. A run is
// its number; every run that misses is listed (the text lists 40).
std::string aims_json(const CampaignSpec& spec, const AimsReport& report, const std::vector<AimsByValue>& by_category);

}  // namespace campaign
