#include "collector.hpp"

#include <cstdio>
#include <iomanip>

#include "campaign_error.hpp"
#include "engine/value_text.hpp"

namespace campaign {

Collector::Collector(ResultsWriter& writer, std::map<long, std::string>& rows, long to_do, int ranks, Progress progress)
    : writer_(writer),
      rows_(rows),
      to_do_(to_do),
      progress_(progress),
      started_(std::chrono::steady_clock::now()),
      last_shown_(started_) {
    stats_.ranks.resize(static_cast<std::size_t>(ranks));
}

void Collector::accept(int rank, const std::string& row) {
    const auto cells = split_csv_line(row);
    if (cells.size() < 1 + trailing_columns)
        throw CampaignError("rank " + std::to_string(rank) + " sent a malformed row");
    const long index = cosim::parse_integer(cells[run_column], "run index from rank " + std::to_string(rank));
    const double wall = cosim::parse_real(cells[cells.size() - 3], "wall time from rank " + std::to_string(rank));
    const std::string& status = cells[cells.size() - 2];
    writer_.append(row);
    if (!rows_.emplace(index, row).second) throw CampaignError("run " + std::to_string(index) + " finished twice");
    ++stats_.runs;
    if (status == "failed") ++stats_.failed;
    if (status == "stopped") ++stats_.stopped;
    auto& r = stats_.ranks.at(static_cast<std::size_t>(rank));
    ++r.runs;
    r.busy += wall;
    show_progress();
}

void Collector::show_progress() {
    if (progress_ == Progress::none) return;
    const auto now = std::chrono::steady_clock::now();
    const auto every =
        progress_ == Progress::terminal ? std::chrono::milliseconds(250) : std::chrono::milliseconds(10'000);
    if (stats_.runs != to_do_ && now - last_shown_ < every) return;
    last_shown_ = now;
    const double elapsed = std::chrono::duration<double>(now - started_).count();
    const double left = elapsed / static_cast<double>(stats_.runs) * static_cast<double>(to_do_ - stats_.runs);
    std::fprintf(stderr, "%scampaign: %ld/%ld runs, %ld failed, %.2f runs/s, about %.0f s left%s",
                 progress_ == Progress::terminal ? "\r" : "", stats_.runs, to_do_, stats_.failed,
                 static_cast<double>(stats_.runs) / elapsed, left, progress_ == Progress::terminal ? "   " : "\n");
    std::fflush(stderr);
    shown_ = progress_ == Progress::terminal;
}

CampaignStatistics Collector::finish() {
    stats_.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    if (shown_) std::fprintf(stderr, "\r%78s\r", "");
    return stats_;
}

void print_statistics(const CampaignStatistics& s, std::ostream& out) {
    const auto flags = out.flags();
    const auto precision = out.precision();
    out << std::fixed << std::setprecision(3);
    out << s.runs << " runs (" << s.runs - s.failed - s.stopped << " ok, " << s.stopped << " stopped early, "
        << s.failed << " failed) in " << s.wall_time
        << " s wall: " << (s.wall_time > 0 ? static_cast<double>(s.runs) / s.wall_time : 0.0) << " runs/s on "
        << s.ranks.size() << (s.ranks.size() == 1 ? " rank\n" : " ranks\n");
    for (std::size_t i = 0; i < s.ranks.size(); ++i)
        out << "  rank " << i << ": " << s.ranks[i].runs << " runs, busy " << s.ranks[i].busy << " s ("
            << std::setprecision(1) << (s.wall_time > 0 ? 100.0 * s.ranks[i].busy / s.wall_time : 0.0)
            << " % utilisation)\n"
            << std::setprecision(3);
    out.flags(flags);
    out.precision(precision);
}

}  // namespace campaign
