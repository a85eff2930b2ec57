// The campaign's report, from the results table in run order: summary.md (runs, failures, the
// campaign's own statistics, percentiles across runs of every metric column, the failed runs) and the
// PNG figures drawn with gnuplot (the CDF over runs of each angle metric, the same split by the
// values of the first grid draw, and each angle metric against each drawn quantity).
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "campaign_run.hpp"
#include "collector.hpp"

namespace campaign {

// The table's rows split into cells, in run order, with the header to find columns by name.
struct ResultRows {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;
    std::size_t column(const std::string& name) const;  // throws when absent
    // The numeric values of a column over the runs whose status is ok or stopped (NaN and text skipped).
    std::vector<double> finished_values(const std::string& name) const;
};
ResultRows split_rows(const std::vector<std::string>& header, const std::map<long, std::string>& rows);

// A finished campaign's results.csv read back whole, to judge its aims afterwards (the C API's
// pvatt_campaign_aims): every row with the header's number of cells, the header's first column "run" and its
// last two "status" and "message", as the campaign writes them. Refused: a missing or unreadable file, one
// larger than max_table_bytes, a last row without its line end (a campaign still running or stopped: resume
// it first), a row of another width.
inline constexpr std::uintmax_t max_table_bytes = std::uintmax_t{1} << 30;  // 1 GiB
ResultRows read_table(const std::filesystem::path& file);
// The same from the table's text; `name` says where it came from in an error.
ResultRows parse_table(const std::string& text, const std::string& name);

// A cell as a finite number, or nothing.
std::optional<double> number_in(const std::string& cell);

// Returns the files written; throws when gnuplot is missing or fails.
std::vector<std::filesystem::path> draw_figures(const std::filesystem::path& dir, const CampaignSpec& spec,
                                                const ResultRows& table);

// The system's declared measures (CampaignSpec::measures) over the finished runs, one line per measure
// column that has a value: "measure.filter.converged.sunlit.p95: median 0.31, p95 0.52, max 0.61 (8 runs)".
// The end of `cosim campaign`; summary.md holds the same columns in its tables (with mean, min, p5).
void print_measures_over_runs(const CampaignSpec& spec, const ResultRows& table, std::ostream& out);

void write_summary(const std::filesystem::path& file, const CampaignSetup& setup, const ResultRows& table,
                   const CampaignStatistics& stats, const std::vector<std::filesystem::path>& figures,
                   const std::string& figure_note);

}  // namespace campaign
