#include "aims.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "analysis/json_text.hpp"
#include "campaign_error.hpp"
#include "engine/value_text.hpp"
#include "metric_observer.hpp"
#include "results_table.hpp"

namespace campaign {

namespace {

// At most this many run numbers are listed per aim (the rest are in results.csv).
constexpr std::size_t listed_runs = 40;

std::string run_list(const std::vector<std::string>& runs) {
    std::string out;
    for (std::size_t i = 0; i < runs.size() && i < listed_runs; ++i) out += (i ? ", " : "") + runs[i];
    if (runs.size() > listed_runs) out += " and " + std::to_string(runs.size() - listed_runs) + " more";
    return out;
}

}  // namespace

std::string aim_text(const Aim& aim) {
    const auto n = [](double x) { return cosim::format_real(x); };
    switch (aim.kind) {
        case AimKind::below:
            return aim.column + " < " + n(aim.high);
        case AimKind::at_least:
            return aim.column + " >= " + n(aim.low);
        case AimKind::within:
            return aim.column + " in [" + n(aim.low) + ", " + n(aim.high) + "]";
    }
    return aim.column;
}

bool meets(const Aim& aim, double value) {
    switch (aim.kind) {
        case AimKind::below:
            return value < aim.high;
        case AimKind::at_least:
            return value >= aim.low;
        case AimKind::within:
            return value >= aim.low && value <= aim.high;
    }
    return false;
}

void check_aim_columns(const CampaignSpec& spec) {
    const auto columns = metric_columns(spec);
    for (std::size_t i = 0; i < spec.aims.size(); ++i)
        if (std::find(columns.begin(), columns.end(), spec.aims[i].column) == columns.end())
            throw CampaignError(spec.file.string() + ": aim " + std::to_string(i + 1) + ": '" + spec.aims[i].column +
                                "' is not a column of the results table (a metric's name.stat" +
                                (spec.measures ? " or a measure.* column)" : ")"));
}

AimsReport judge_aims(const CampaignSpec& spec, const ResultRows& table,
                      const std::function<bool(const std::vector<std::string>&)>& keep) {
    AimsReport r;
    r.per_aim.resize(spec.aims.size());
    if (spec.aims.empty()) return r;
    const std::size_t status = table.header.size() - 2;
    std::vector<std::size_t> columns;
    for (const auto& aim : spec.aims) columns.push_back(table.column(aim.column));
    for (const auto& row : table.rows) {
        if (keep && !keep(row)) continue;
        if (row[status] == "failed") {
            ++r.failed;
            continue;
        }
        ++r.finished;
        bool all = true;
        for (std::size_t i = 0; i < spec.aims.size(); ++i) {
            const auto value = number_in(row[columns[i]]);
            AimTally& t = r.per_aim[i];
            if (!value && spec.aims[i].skip_empty) {
                ++t.not_judged;
            } else if (value && meets(spec.aims[i], *value)) {
                ++t.met;
            } else {
                ++t.missed;
                t.missing_runs.push_back(row[run_column]);
                all = false;
            }
        }
        if (all)
            ++r.every;
        else
            r.missing_any.push_back(row[run_column]);
    }
    return r;
}

std::vector<AimsByValue> judge_aims_by_category(const CampaignSpec& spec, const ResultRows& table) {
    std::vector<AimsByValue> out;
    if (spec.aims.empty()) return out;
    // The kinds of scene a spec names: an orbit draw's class, a choice or grid of text, a case (not a date's
    // text, nor a number).
    std::vector<std::string> columns;
    for (const auto& d : spec.draws) {
        if (d.kind == DrawKind::orbit) columns.push_back(d.target + ".class");
        if ((d.kind == DrawKind::choice || d.kind == DrawKind::grid) && !d.values.empty() &&
            std::none_of(d.values.begin(), d.values.end(), [](const SpecValue& v) { return v.numeric; }))
            columns.push_back(d.target);
    }
    if (!spec.cases.empty()) columns.push_back("case");
    const std::size_t status = table.header.size() - 2;
    for (const auto& name : columns) {
        if (std::find(table.header.begin(), table.header.end(), name) == table.header.end()) continue;
        const std::size_t c = table.column(name);
        std::vector<std::string> values;
        for (const auto& row : table.rows)  // up to one past the limit: enough to skip the column
            if (row[status] != "failed" && std::find(values.begin(), values.end(), row[c]) == values.end() &&
                values.size() <= max_category_values)
                values.push_back(row[c]);
        if (values.size() < 2 || values.size() > max_category_values) continue;
        AimsByValue by{name, {}};
        for (const auto& v : values)
            by.values.emplace_back(
                v, judge_aims(spec, table, [&](const std::vector<std::string>& row) { return row[c] == v; }));
        out.push_back(std::move(by));
    }
    return out;
}

void write_aims(std::ostream& md, const CampaignSpec& spec, const AimsReport& report,
                const std::vector<AimsByValue>& by_category) {
    if (spec.aims.empty()) return;
    md << "\n## Aims\n\nEach finished run judged by each of the spec's aims (" << report.finished << " finished runs";
    if (report.failed > 0) md << "; " << report.failed << " failed, not judged";
    md << "). A run with no value misses an aim, except one marked skip_empty (not judged: the metric sampled "
          "nothing, as a run without an eclipse).\n\n| aim | met | missed | not judged | runs that miss |\n"
          "|---|---|---|---|---|\n";
    for (std::size_t i = 0; i < spec.aims.size(); ++i) {
        const AimTally& t = report.per_aim[i];
        md << "| " << aim_text(spec.aims[i]) << " | " << t.met << " | " << t.missed << " | " << t.not_judged << " | "
           << (t.missing_runs.empty() ? std::string("–") : run_list(t.missing_runs)) << " |\n";
    }
    md << "\n**Every aim: " << report.every << " of " << report.finished << " finished runs.**";
    if (!report.missing_any.empty()) md << " Runs that miss one or more: " << run_list(report.missing_any) << ".";
    md << "\n";
    for (const auto& by : by_category) {
        md << "\n### Aims by " << by.column
           << "\n\nPer value: the runs, those that meet every aim, and per aim the runs that meet it / the runs it "
              "judges.\n\n| "
           << by.column << " | runs | every aim |";
        for (const auto& aim : spec.aims) md << " " << aim_text(aim) << " |";
        md << "\n|---|---|---|";
        for (std::size_t i = 0; i < spec.aims.size(); ++i) md << "---|";
        md << "\n";
        for (const auto& [value, r] : by.values) {
            md << "| " << value << " | " << r.finished << " | " << r.every << " |";
            for (const auto& t : r.per_aim) md << " " << t.met << "/" << t.met + t.missed << " |";
            md << "\n";
        }
    }
}

void print_aims(const CampaignSpec& spec, const AimsReport& report, const std::vector<AimsByValue>& by_category,
                std::ostream& out) {
    if (spec.aims.empty()) return;
    out << "aims, per run (" << report.finished << " finished runs"
        << (report.failed > 0 ? ", " + std::to_string(report.failed) + " failed, not judged" : std::string()) << "):\n";
    for (std::size_t i = 0; i < spec.aims.size(); ++i) {
        const AimTally& t = report.per_aim[i];
        out << "  " << aim_text(spec.aims[i]) << ": " << t.met << " met, " << t.missed << " missed";
        if (!t.missing_runs.empty())
            out << (t.missing_runs.size() == 1 ? " (run " : " (runs ") << run_list(t.missing_runs) << ")";
        if (t.not_judged > 0) out << ", " << t.not_judged << " not judged (no value)";
        out << "\n";
    }
    out << "  every aim: " << report.every << " of " << report.finished << " runs\n";
    for (const auto& by : by_category) {
        out << "  every aim by " << by.column << ":";
        for (std::size_t i = 0; i < by.values.size(); ++i)
            out << (i ? ", " : " ") << by.values[i].first << " " << by.values[i].second.every << " of "
                << by.values[i].second.finished;
        out << "\n";
    }
}

namespace {

// A run's cell as JSON: its number (the run column holds integers), or the text when it is not one.
std::string json_run(const std::string& cell) {
    const auto x = number_in(cell);
    return x && *x == std::floor(*x) ? analysis::json_number(*x) : analysis::json_string(cell);
}

std::string json_runs(const std::vector<std::string>& runs) {
    std::string out = "[";
    for (std::size_t i = 0; i < runs.size(); ++i) out += (i ? ", " : "") + json_run(runs[i]);
    return out + "]";
}

std::string json_counts(const std::vector<AimTally>& per_aim, bool judged) {
    std::string out = "[";
    for (std::size_t i = 0; i < per_aim.size(); ++i)
        out += (i ? ", " : "") + std::to_string(per_aim[i].met + (judged ? per_aim[i].missed : 0));
    return out + "]";
}

const char* kind_name(AimKind kind) {
    switch (kind) {
        case AimKind::below:
            return "below";
        case AimKind::at_least:
            return "at_least";
        case AimKind::within:
            return "within";
    }
    return "";
}

}  // namespace

std::string aims_json(const CampaignSpec& spec, const AimsReport& report, const std::vector<AimsByValue>& by_category) {
    using analysis::json_number, analysis::json_string;
    std::string out = "{\"finished\": " + std::to_string(report.finished) +
                      ", \"failed\": " + std::to_string(report.failed) +
                      ", \"every\": " + std::to_string(report.every) +
                      ", \"missing_any\": " + json_runs(report.missing_any) + ", \"aims\": [";
    for (std::size_t i = 0; i < spec.aims.size(); ++i) {
        const Aim& a = spec.aims[i];
        const AimTally& t = report.per_aim[i];
        const bool low = a.kind != AimKind::below, high = a.kind != AimKind::at_least;
        out += std::string(i ? ", " : "") + "{\"column\": " + json_string(a.column) +
               ", \"condition\": " + json_string(aim_text(a)) + ", \"kind\": " + json_string(kind_name(a.kind)) +
               ", \"low\": " + (low ? json_number(a.low) : "null") +
               ", \"high\": " + (high ? json_number(a.high) : "null") +
               ", \"skip_empty\": " + (a.skip_empty ? "true" : "false") + ", \"met\": " + std::to_string(t.met) +
               ", \"missed\": " + std::to_string(t.missed) + ", \"not_judged\": " + std::to_string(t.not_judged) +
               ", \"missing_runs\": " + json_runs(t.missing_runs) + "}";
    }
    out += "], \"by_category\": [";
    for (std::size_t i = 0; i < by_category.size(); ++i) {
        out += std::string(i ? ", " : "") + "{\"column\": " + json_string(by_category[i].column) + ", \"values\": [";
        const auto& values = by_category[i].values;
        for (std::size_t j = 0; j < values.size(); ++j) {
            const AimsReport& r = values[j].second;
            out += std::string(j ? ", " : "") + "{\"value\": " + json_string(values[j].first) +
                   ", \"finished\": " + std::to_string(r.finished) + ", \"failed\": " + std::to_string(r.failed) +
                   ", \"every\": " + std::to_string(r.every) + ", \"met\": " + json_counts(r.per_aim, false) +
                   ", \"judged\": " + json_counts(r.per_aim, true) + "}";
        }
        out += "]}";
    }
    return out + "]}";
}

}  // namespace campaign
