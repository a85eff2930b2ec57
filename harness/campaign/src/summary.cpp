#include "summary.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <set>
#include <sstream>

#include "aims.hpp"
#include "analysis/run_measures.hpp"
#include "campaign_error.hpp"
#include "draws.hpp"
#include "engine/cosim_error.hpp"
#include "engine/gnuplot.hpp"
#include "engine/value_text.hpp"
#include "metric_observer.hpp"
#include "results_table.hpp"
#include "statistics.hpp"

namespace campaign {

std::size_t ResultRows::column(const std::string& name) const {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end()) throw CampaignError("results table: no column '" + name + "'");
    return static_cast<std::size_t>(it - header.begin());
}

std::optional<double> number_in(const std::string& cell) {
    double x = 0.0;
    const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), x);
    if (ec != std::errc() || end != cell.data() + cell.size() || cell.empty() || !std::isfinite(x)) return std::nullopt;
    return x;
}

std::vector<double> ResultRows::finished_values(const std::string& name) const {
    const std::size_t c = column(name), status = header.size() - 2;
    std::vector<double> out;
    for (const auto& row : rows)
        if (row[status] != "failed")
            if (const auto x = number_in(row[c])) out.push_back(*x);
    return out;
}

ResultRows split_rows(const std::vector<std::string>& header, const std::map<long, std::string>& rows) {
    ResultRows t;
    t.header = header;
    for (const auto& [index, line] : rows) t.rows.push_back(split_csv_line(line));
    return t;
}

ResultRows parse_table(const std::string& text, const std::string& name) {
    if (text.empty()) throw CampaignError("the " + name + " is empty");
    if (text.back() != '\n')
        throw CampaignError("the " + name +
                            " ends in a row without its line end: the campaign is still running or was stopped "
                            "(resume it first)");
    ResultRows t;
    std::size_t start = 0, line_number = 0;
    while (start < text.size()) {
        const auto end = text.find('\n', start);
        auto cells = split_csv_line(text.substr(start, end - start));
        start = end + 1;
        ++line_number;
        if (line_number == 1) {
            if (cells.size() < 3 || cells.front() != "run" || cells[cells.size() - 2] != "status" ||
                cells.back() != "message")
                throw CampaignError(name +
                                    ":1: not a campaign's results table (its first column is 'run', its last "
                                    "two 'status' and 'message')");
            t.header = std::move(cells);
        } else if (cells.size() != t.header.size()) {
            throw CampaignError(name + ":" + std::to_string(line_number) + ": a row of " +
                                std::to_string(cells.size()) + " cells where the header has " +
                                std::to_string(t.header.size()));
        } else {
            t.rows.push_back(std::move(cells));
        }
    }
    return t;
}

ResultRows read_table(const std::filesystem::path& file) {
    const std::string name = "results table " + file.string();
    std::error_code ec;
    const auto bytes = std::filesystem::file_size(file, ec);
    if (ec) throw CampaignError("cannot read the " + name + ": " + ec.message());
    if (bytes > max_table_bytes)
        throw CampaignError("the " + name + " has " + std::to_string(bytes) + " bytes, more than max_table_bytes (" +
                            std::to_string(max_table_bytes) + ")");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw CampaignError("cannot open the " + name);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw CampaignError("cannot read the " + name);
    return parse_table(text, name);
}

namespace {

using cosim::gnuplot_string;

std::string file_name(const std::string& text) {
    return cosim::safe_file_name(text);
}

// gnuplot runs in the campaign's folder and the script names files there by their names alone
// (cosim::run_gnuplot): the folder's own name never reaches gnuplot. A figure that fails is a
// message on stderr, leaves no PNG and does not stop the others: false.
bool run_gnuplot(const std::string& script, const std::filesystem::path& png) {
    try {
        cosim::run_gnuplot(png.parent_path(), script, png.filename().string());
        return true;
    } catch (const cosim::CosimError& e) {
        std::cerr << "cosim campaign: " << e.what() << "\n";
        return false;
    }
}

std::string preamble(const std::filesystem::path& png, const std::string& title, const std::string& xlabel,
                     const std::string& ylabel) {
    return "set terminal pngcairo noenhanced size 1000,650 font 'sans,11'\nset output " +
           gnuplot_string(png.filename().string()) + "\nset title " + gnuplot_string(title) + "\nset xlabel " +
           gnuplot_string(xlabel) + "\nset ylabel " + gnuplot_string(ylabel) + "\nset grid\nset key bottom right\n";
}

// The data files of the figures: removed when the figures are drawn, or when drawing fails.
struct TemporaryFiles {
    std::vector<std::filesystem::path> files;
    ~TemporaryFiles() {
        std::error_code ignored;
        for (const auto& f : files) std::filesystem::remove(f, ignored);
    }
};

void write_data(const std::filesystem::path& file, const std::string& text) {
    std::ofstream out(file);
    out << text;
    out.close();
    if (!out) throw CampaignError("cannot write " + file.string());
}

// A number as the summary writes it ("–" for none).
std::string figure(double x) {
    if (!std::isfinite(x)) return "–";
    std::ostringstream cell;
    cell << std::setprecision(4) << x;
    return cell.str();
}

// The rows of each case (all rows under one name "all runs" when the spec has none), failed runs left out.
std::vector<std::pair<std::string, std::vector<const std::vector<std::string>*>>> rows_by_case(
    const CampaignSpec& spec, const ResultRows& table) {
    const std::size_t status = table.header.size() - 2;
    std::vector<std::pair<std::string, std::vector<const std::vector<std::string>*>>> out;
    if (spec.cases.empty()) out.emplace_back("all runs", std::vector<const std::vector<std::string>*>{});
    for (const auto& c : spec.cases) out.emplace_back(c.name, std::vector<const std::vector<std::string>*>{});
    const std::size_t k = spec.cases.empty() ? 0 : table.column("case");
    for (const auto& row : table.rows) {
        if (row[status] == "failed") continue;
        for (auto& [name, rows] : out)
            if (spec.cases.empty() || row[k] == name) rows.push_back(&row);
    }
    return out;
}

// Per detection metric, one row per case: how often and how fast the fault was declared, whether the
// right element was, which words were declared, and the false alarms.
void write_detection(std::ostream& md, const CampaignSpec& spec, const ResultRows& table) {
    for (const auto& m : spec.metrics) {
        if (m.kind != MetricKind::detection) continue;
        auto col = [&](const char* cell) { return table.column(m.name + "." + cell); };
        const std::size_t detected = col("detected"), time = col("time"), isolated = col("isolated"),
                          declared = col("declared"), before = col("before"), orbits = col("orbits"),
                          which = col("which");
        // A spec whose cases say when their fault can first be seen: the time to detect from then too.
        const bool from_observable = reports_observable(m);
        const std::size_t observable = from_observable ? col("observable") : 0,
                          time_observable = from_observable ? col("time_observable") : 0;
        md << "\n## Detection: " << m.name << "\n\n"
           << "Per case over its finished runs: detected (a declaration at or after the onset), the time from the "
              "onset to the first declaration, isolated right (exactly the expected elements declared after the "
              "onset), the words declared (word: runs), the declarations per period of "
           << figure(m.period) << " s over the whole run (from " << figure(m.after)
           << " s) in a case without an onset (the control's false alarms: declarations in periods), and the "
              "declarations before the onset in a case with one.";
        if (from_observable)
            md << " A case with an `observable` also has the runs where its fault became observable after the onset "
                  "(its condition held at an output point), and over those detected, the time from that moment to "
                  "the first declaration (negative: declared before) and the runs within "
               << figure(m.within) << " s of it.";
        md << "\n\n| case | runs | detected | time to detect median / p95 / max (s) | within " << figure(m.within)
           << " s | isolated right | words declared | declarations per period | before the onset |"
           << (from_observable
                   ? " observable | from observable median / p95 / max (s) | within " + figure(m.within) + " s of it |"
                   : std::string())
           << "\n|---|---|---|---|---|---|---|---|---|" << (from_observable ? "---|---|---|" : "") << "\n";
        for (const auto& [name, rows] : rows_by_case(spec, table)) {
            const Case* c = nullptr;
            for (const auto& x : spec.cases)
                if (x.name == name) c = &x;
            const bool has_onset = c && !c->onset.empty();
            long n = 0, hits = 0, right = 0, within = 0, seen = 0, within_seen = 0;
            double count = 0.0, span = 0.0, early = 0.0;
            std::vector<double> times, seen_times;
            std::map<std::string, long> words;
            for (const auto* row : rows) {
                ++n;
                hits += number_in((*row)[detected]).value_or(0.0) == 1.0;
                right += number_in((*row)[isolated]).value_or(0.0) == 1.0;
                if (const auto t = number_in((*row)[time])) {
                    times.push_back(*t);
                    within += *t <= m.within;
                }
                if (from_observable) {
                    seen += number_in((*row)[observable]).has_value();
                    if (const auto t = number_in((*row)[time_observable])) {
                        seen_times.push_back(*t);
                        within_seen += *t <= m.within;
                    }
                }
                count += number_in((*row)[declared]).value_or(0.0);
                span += number_in((*row)[orbits]).value_or(0.0);
                early += number_in((*row)[before]).value_or(0.0);
                std::set<std::string> seen;  // each word once per run
                std::istringstream items((*row)[which]);
                for (std::string item; items >> item;) seen.insert(item.substr(item.rfind('=') + 1));
                for (const auto& w : seen) ++words[w];
            }
            std::sort(times.begin(), times.end());
            std::sort(seen_times.begin(), seen_times.end());
            const auto spread = [](const std::vector<double>& x) {
                return x.empty()
                           ? std::string("–")
                           : figure(percentile(x, 50)) + " / " + figure(percentile(x, 95)) + " / " + figure(x.back());
            };
            std::string declared_words;
            for (const auto& [w, runs] : words)
                declared_words += (declared_words.empty() ? "" : ", ") + w + ": " + std::to_string(runs);
            md << "| " << name << " | " << n << " | " << hits << " | " << spread(times) << " | "
               << (has_onset ? std::to_string(within) : "–") << " | " << right << " | "
               << (declared_words.empty() ? "–" : declared_words) << " | "
               << (!has_onset && span > 0 ? figure(count / span) + " (" + figure(count) + " in " + figure(span) + ")"
                                          : std::string("–"))
               << " | " << (has_onset ? figure(early) : "–") << " |";
            if (from_observable) {
                if (c && !c->observable.column.empty())
                    md << " " << seen << " | " << spread(seen_times) << " | " << within_seen << " |";
                else
                    md << " – | – | – |";
            }
            md << "\n";
        }
    }
}

// Each case against its paired control (the same scene and grid combination without the fault): for every
// angle metric with a p95, the p95s side by side and their ratio per pair.
void write_paired(std::ostream& md, const CampaignSpec& spec, const ResultRows& table) {
    const auto control = std::find_if(spec.cases.begin(), spec.cases.end(), [](const Case& c) { return c.control; });
    if (control == spec.cases.end()) return;
    md << "\n## Against the paired control\n\n";
    if (!spec.paired) {
        md << "The spec is not `paired`: its runs share no scene with a control run, so no ratio is formed.\n";
        return;
    }
    std::map<long, const std::vector<std::string>*> by_run;
    const std::size_t status = table.header.size() - 2;
    for (const auto& row : table.rows)
        if (row[status] != "failed")
            if (const auto i = number_in(row[run_column])) by_run[static_cast<long>(*i)] = &row;
    md << "Per case, over the runs whose paired control (case " << control->name
       << ", the same scene) finished: the median of the runs' p95 against the controls', and the ratio run / "
          "control per pair (median / p95 / max).\n\n";
    for (const auto& m : spec.metrics) {
        if (m.kind == MetricKind::column || m.kind == MetricKind::detection) continue;
        if (std::find(m.stats.begin(), m.stats.end(), "p95") == m.stats.end()) continue;
        const std::size_t c = table.column(m.name + ".p95");
        md << "\n### " << m.name
           << ".p95\n\n| case | pairs | run p95 median | control p95 median | ratio median / "
              "p95 / max |\n|---|---|---|---|---|\n";
        for (const auto& [name, rows] : rows_by_case(spec, table)) {
            if (name == control->name) continue;
            std::vector<double> runs, controls, ratios;
            for (const auto* row : rows) {
                const auto i = number_in((*row)[run_column]);
                const auto pair = i ? paired_control(spec, static_cast<long>(*i)) : std::nullopt;
                const auto other = pair ? by_run.find(*pair) : by_run.end();
                if (other == by_run.end()) continue;
                const auto a = number_in((*row)[c]), b = number_in((*other->second)[c]);
                if (!a || !b || *b <= 0.0) continue;
                runs.push_back(*a);
                controls.push_back(*b);
                ratios.push_back(*a / *b);
            }
            for (auto* v : {&runs, &controls, &ratios}) std::sort(v->begin(), v->end());
            md << "| " << name << " | " << ratios.size() << " | " << figure(percentile(runs, 50)) << " | "
               << figure(percentile(controls, 50)) << " | "
               << (ratios.empty() ? std::string("–")
                                  : figure(percentile(ratios, 50)) + " / " + figure(percentile(ratios, 95)) + " / " +
                                        figure(ratios.back()))
               << " |\n";
        }
    }
}

}  // namespace

std::vector<std::filesystem::path> draw_figures(const std::filesystem::path& dir, const CampaignSpec& spec,
                                                const ResultRows& table) {
    std::vector<std::filesystem::path> written;
    TemporaryFiles temporary;
    const auto columns = draw_columns(spec);
    for (const auto& m : spec.metrics) {
        // A normalized error's per-run NEES/dof and coverage (%) share no axis: in the table only.
        if (m.kind == MetricKind::column || m.kind == MetricKind::detection || m.kind == MetricKind::normalized_error)
            continue;
        // CDF over runs of each of the metric's per-run statistics.
        const auto png = dir / ("cdf_" + file_name(m.name) + ".png");
        std::string plots;
        std::vector<std::filesystem::path> data_files;
        for (const auto& s : m.stats) {
            if (s == "count") continue;
            auto values = table.finished_values(m.name + "." + s);
            if (values.empty()) continue;
            std::sort(values.begin(), values.end());
            std::ostringstream text;
            for (std::size_t i = 0; i < values.size(); ++i)
                text << cosim::format_real(values[i]) << ' '
                     << static_cast<double>(i + 1) / static_cast<double>(values.size()) << '\n';
            data_files.push_back(dir / ("cdf_" + file_name(m.name) + "_" + file_name(s) + ".dat"));
            temporary.files.push_back(data_files.back());
            write_data(data_files.back(), text.str());
            plots += std::string(plots.empty() ? "plot " : ", ") +
                     gnuplot_string(data_files.back().filename().string()) + " using 1:2 with steps lw 2 title " +
                     gnuplot_string("per-run " + s);
        }
        if (!plots.empty()) {
            if (run_gnuplot(preamble(png, m.name + ": distribution over runs", "degrees", "fraction of runs") +
                                "set yrange [0:1]\n" + plots + "\n",
                            png))
                written.push_back(png);
        }
        for (const auto& f : data_files) std::filesystem::remove(f);

        // The same distribution split by the values of the first grid draw (the compared designs), and by
        // case where the spec has cases.
        auto split_cdf = [&](const std::string& column, const std::vector<std::string>& labels) {
            const std::string stat_column = m.name + "." + m.figure_stat;
            const std::size_t g = table.column(column), y = table.column(stat_column), status = table.header.size() - 2;
            const auto by = dir / ("cdf_" + file_name(m.name) + "_by_" + file_name(column) + ".png");
            std::string lines;
            std::vector<std::filesystem::path> files;
            for (const auto& label : labels) {
                std::vector<double> values;
                for (const auto& row : table.rows)
                    if (row[status] != "failed" && row[g] == label)
                        if (const auto v = number_in(row[y])) values.push_back(*v);
                if (values.empty()) continue;
                std::sort(values.begin(), values.end());
                std::ostringstream text;
                for (std::size_t i = 0; i < values.size(); ++i)
                    text << cosim::format_real(values[i]) << ' '
                         << static_cast<double>(i + 1) / static_cast<double>(values.size()) << '\n';
                files.push_back(dir / ("cdf_by_" + file_name(m.name) + "_" + file_name(label) + ".dat"));
                temporary.files.push_back(files.back());
                write_data(files.back(), text.str());
                lines += std::string(lines.empty() ? "plot " : ", ") +
                         gnuplot_string(files.back().filename().string()) + " using 1:2 with steps lw 2 title " +
                         gnuplot_string(label);
            }
            if (!lines.empty()) {
                if (run_gnuplot(preamble(by, stat_column + " by " + column + ": distribution over runs", "degrees",
                                         "fraction of runs") +
                                    "set yrange [0:1]\n" + lines + "\n",
                                by))
                    written.push_back(by);
            }
            for (const auto& f : files) std::filesystem::remove(f);
        };
        if (const auto grid = std::find_if(spec.draws.begin(), spec.draws.end(),
                                           [](const Draw& d) { return d.kind == DrawKind::grid; });
            grid != spec.draws.end()) {
            std::vector<std::string> labels;
            for (const auto& value : grid->values) labels.push_back(value.text);
            split_cdf(grid->target, labels);
        }
        if (!spec.cases.empty()) {
            std::vector<std::string> labels;
            for (const auto& c : spec.cases) labels.push_back(c.name);
            split_cdf("case", labels);
        }

        // The metric's figure statistic against each drawn quantity; text values as categories.
        const std::string y_name = m.name + "." + m.figure_stat;
        const std::size_t y = table.column(y_name), status = table.header.size() - 2;
        for (const auto& c : columns) {
            if (!c.plotted) continue;
            const std::size_t x = table.column(c.name);
            std::vector<std::string> categories;
            bool numeric = true;
            for (const auto& row : table.rows) numeric = numeric && number_in(row[x]).has_value();
            if (!numeric) {
                std::set<std::string> distinct;
                for (const auto& row : table.rows) distinct.insert(row[x]);
                categories.assign(distinct.begin(), distinct.end());
            }
            std::ostringstream text;
            std::size_t points = 0;
            for (const auto& row : table.rows) {
                const auto value = number_in(row[y]);
                if (row[status] == "failed" || !value) continue;
                const double xv = numeric
                                      ? *number_in(row[x])
                                      : static_cast<double>(std::find(categories.begin(), categories.end(), row[x]) -
                                                            categories.begin());
                text << cosim::format_real(xv) << ' ' << cosim::format_real(*value) << '\n';
                ++points;
            }
            if (points == 0) continue;
            const auto data = dir / (file_name(m.name) + "_vs_" + file_name(c.name) + ".dat");
            const auto scatter = dir / (file_name(m.name) + "_vs_" + file_name(c.name) + ".png");
            temporary.files.push_back(data);
            write_data(data, text.str());
            std::string script =
                preamble(scatter, y_name + " against " + c.name, c.name, y_name + " (degrees)") + "set key off\n";
            if (!numeric) {
                script += "set xrange [-0.5:" + std::to_string(categories.size() - 0.5) + "]\nset xtics (";
                for (std::size_t i = 0; i < categories.size(); ++i)
                    script += (i ? ", " : "") + gnuplot_string(categories[i]) + " " + std::to_string(i);
                script += ")\n";
            }
            script += "plot " + gnuplot_string(data.filename().string()) + " using 1:2 with points pt 7 ps 0.8\n";
            if (run_gnuplot(script, scatter)) written.push_back(scatter);
            std::filesystem::remove(data);
        }
    }
    return written;
}

void print_measures_over_runs(const CampaignSpec& spec, const ResultRows& table, std::ostream& out) {
    if (!spec.measures) return;
    bool said = false;
    for (const auto& name : analysis::measure_columns(spec.measure_report)) {
        auto v = table.finished_values(name);
        if (v.empty()) continue;
        std::sort(v.begin(), v.end());
        if (!said) out << "what the runs reached (the system's declared measures; angles in degrees, over runs):\n";
        said = true;
        out << std::setprecision(4) << "  " << name << ": median " << percentile(v, 50) << ", p95 " << percentile(v, 95)
            << ", max " << v.back() << " (" << v.size() << " runs)\n";
    }
}

void write_summary(const std::filesystem::path& file, const CampaignSetup& setup, const ResultRows& table,
                   const CampaignStatistics& stats, const std::vector<std::filesystem::path>& figures,
                   const std::string& figure_note) {
    const auto& spec = setup.spec;
    const std::size_t status = table.header.size() - 2, message = table.header.size() - 1;
    long ok = 0, stopped = 0, failed = 0;
    for (const auto& row : table.rows) {
        if (row[status] == "ok")
            ++ok;
        else if (row[status] == "stopped")
            ++stopped;
        else
            ++failed;
    }
    std::ostringstream md;
    md << std::setprecision(4);
    md << "# Campaign " << spec.file.filename().string() << "\n\n";
    md << "- system: `" << spec.system.string() << "`, from " << setup.start_time << " s to " << setup.stop_time
       << " s, output interval " << setup.output_interval << " s, tolerance " << setup.tolerance << "\n";
    md << "- runs in the table: " << table.rows.size() << " of " << spec.runs << " (" << ok << " ok, " << stopped
       << " stopped early, " << failed << " failed); base seed " << spec.seed << (spec.paired ? ", paired scenes" : "")
       << "\n";
    md << "- this invocation: " << stats.runs << " runs in " << stats.wall_time << " s wall, "
       << (stats.wall_time > 0 ? static_cast<double>(stats.runs) / stats.wall_time : 0.0) << " runs/s on "
       << stats.ranks.size() << " rank(s)\n";
    for (std::size_t i = 0; i < stats.ranks.size(); ++i)
        md << "  - rank " << i << ": " << stats.ranks[i].runs << " runs, utilisation "
           << (stats.wall_time > 0 ? 100.0 * stats.ranks[i].busy / stats.wall_time : 0.0) << " %\n";

    // Runs that finished without one valid sample of a metric (an orbit started in eclipse, a filter that
    // never converged): counted and said, since their empty cells leave them out of its statistics.
    for (const auto& m : spec.metrics) {
        if (m.kind == MetricKind::column || m.kind == MetricKind::detection) continue;
        const std::size_t c = table.column(m.name + "." + m.stats.front());
        long finished = 0, empty = 0;
        for (const auto& row : table.rows) {
            if (row[status] == "failed") continue;
            ++finished;
            if (!number_in(row[c])) ++empty;
        }
        if (empty > 0)
            md << "- " << m.name << ": " << empty << " of " << finished
               << " finished runs had no valid sample (left out of its statistics)\n";
    }

    // One table over the rows `keep` selects.
    auto metrics_table = [&](const std::function<bool(const std::vector<std::string>&)>& keep) {
        md << "| column | runs | mean | min | p5 | p50 | p95 | max |\n|---|---|---|---|---|---|---|---|\n";
        for (const auto& name : metric_columns(spec)) {
            if (name.ends_with(".which")) continue;  // a detection's text: in its own table below
            const std::size_t c = table.column(name);
            std::vector<double> v;
            for (const auto& row : table.rows)
                if (row[status] != "failed" && keep(row))
                    if (const auto x = number_in(row[c])) v.push_back(*x);
            std::sort(v.begin(), v.end());
            md << "| " << name << " | " << v.size();
            for (const char* st : {"mean", "min", "p5", "p50", "p95", "max"})
                md << " | " << (v.empty() ? std::string("–") : [&] {
                    std::ostringstream cell;
                    cell << std::setprecision(4) << statistic(st, v);
                    return cell.str();
                }());
            md << " |\n";
        }
    };
    md << "\n## Metrics across runs\n\nPercentiles over the runs that finished (ok or stopped early) with a value; "
          "angles in degrees.";
    if (spec.measures)
        md << " The `measure.*` columns are what the system declares it reached (its `<ex:Measures>`: the same "
              "numbers as the end of `cosim run`; `run` the whole run, `converged` after convergence).";
    md << "\n\n";
    metrics_table([](const auto&) { return true; });
    // The compared designs apart: one table per value of each grid draw (averaging them together would
    // mix what the grid separates).
    for (const auto& d : spec.draws) {
        if (d.kind != DrawKind::grid) continue;
        const std::size_t g = table.column(d.target);
        for (const auto& value : d.values) {
            const long runs = std::count_if(table.rows.begin(), table.rows.end(),
                                            [&](const auto& row) { return row[g] == value.text; });
            md << "\n### " << d.target << " = " << value.text << " (" << runs << " runs)\n\n";
            metrics_table([&](const std::vector<std::string>& row) { return row[g] == value.text; });
        }
    }
    // Each case apart, as a grid value.
    if (!spec.cases.empty()) {
        const std::size_t k = table.column("case");
        for (const auto& c : spec.cases) {
            const long runs =
                std::count_if(table.rows.begin(), table.rows.end(), [&](const auto& row) { return row[k] == c.name; });
            md << "\n### case = " << c.name << " (" << runs << " runs)\n\n";
            metrics_table([&](const std::vector<std::string>& row) { return row[k] == c.name; });
        }
    }
    write_aims(md, spec, judge_aims(spec, table), judge_aims_by_category(spec, table));
    write_detection(md, spec, table);
    write_paired(md, spec, table);
    if (failed > 0) {
        md << "\n## Failed runs\n\n| run | message |\n|---|---|\n";
        long listed = 0;
        for (const auto& row : table.rows) {
            if (row[status] != "failed") continue;
            if (++listed > 50) {
                md << "| … | " << failed - 50 << " more in results.csv |\n";
                break;
            }
            std::string text = row[message];
            std::replace(text.begin(), text.end(), '|', '/');
            md << "| " << row[run_column] << " | " << text << " |\n";
        }
    }
    md << "\n## Figures\n\n";
    for (const auto& f : figures) md << "- [" << f.filename().string() << "](" << f.filename().string() << ")\n";
    if (!figure_note.empty()) md << "- " << figure_note << "\n";
    std::ofstream out(file);
    out << md.str();
    out.close();
    if (!out) throw CampaignError("cannot write " + file.string());
}

}  // namespace campaign
