#include "analysis/result_figures.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>

#include "analysis/angle_error.hpp"
#include "analysis/derived_signals.hpp"
#include "analysis/run_measures.hpp"
#include "engine/cosim_error.hpp"
#include "engine/csv_table.hpp"
#include "engine/gnuplot.hpp"

namespace analysis {

using cosim::CosimError;
using cosim::CsvTable;
using cosim::gnuplot_string;
using cosim::read_csv;
using cosim::run_gnuplot;

namespace {

struct Series {
    std::string title;
    std::vector<double> values;  // NaN: no point at this row
    bool points = false;         // markers (samples) rather than a line
};

std::string degrees(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", x);
    return buf;
}

// A y range for a figure whose values are all equal (a battery that stays full over a short run): gnuplot
// would widen it itself, with a warning on the terminal. Empty when the values vary.
std::string flat_range(const std::vector<Series>& series, std::size_t first_row) {
    double lo = INFINITY, hi = -INFINITY;
    for (const auto& s : series)
        for (std::size_t r = first_row; r < s.values.size(); ++r)
            if (std::isfinite(s.values[r])) {
                lo = std::min(lo, s.values[r]);
                hi = std::max(hi, s.values[r]);
            }
    if (!(lo == hi)) return "";
    const double margin = lo == 0.0 ? 1.0 : 0.05 * std::abs(lo);
    char buf[96];
    std::snprintf(buf, sizeof buf, "set yrange [%.17g:%.17g]\n", lo - margin, hi + margin);
    return buf;
}

// How every figure of one plot_results call is drawn: the terminal, and the eclipse to shade.
struct Style {
    std::string format = "png";
    const std::vector<double>* irradiance = nullptr;  // 0 in the Earth's shadow; null: no shading
    std::vector<FaultDeclaration> marks;              // a vertical line at each fault's declaration
    std::vector<FaultOnset> onsets;                   // and at each injected fault's onset
};

// gnuplot commands for the fault declarations: a dashed red line from the bottom to the top of the plot at
// each, labelled at its top (the label through gnuplot_string: quotes doubled, control characters gone).
std::string fault_marks(const std::vector<FaultDeclaration>& marks, const std::vector<FaultOnset>& onsets) {
    std::string out;
    // Each injected fault's onset: a dotted orange line, labelled at its foot.
    for (const auto& f : onsets) {
        char t[40];
        std::snprintf(t, sizeof t, "%.17g", f.onset);
        out += std::string("set arrow from ") + t + ", graph 0 to " + t +
               ", graph 1 nohead dashtype 3 lw 1.5 lc rgb 'dark-orange' front\n" + "set label " +
               gnuplot_string("onset: " + (f.component.empty() ? "" : f.component + " ") + f.group) + " at " + t +
               ", graph 0.02 rotate by 90 left offset -0.6,0 font ',8' tc rgb 'dark-orange' front\n";
    }
    for (const auto& m : marks) {
        char t[40];
        std::snprintf(t, sizeof t, "%.17g", m.time);
        out += std::string("set arrow from ") + t + ", graph 0 to " + t +
               ", graph 1 nohead dashtype 2 lw 1.5 lc rgb 'red' front\n" + "set label " +
               gnuplot_string("declared: " + m.what) + " at " + t +
               ", graph 0.98 rotate by 90 right offset -0.6,0 font ',8' tc rgb 'red' front\n";
    }
    return out;
}

// One figure: writes the data and a gnuplot script, runs gnuplot in out_dir (no path in the script),
// returns the image. The eclipse (irradiance 0) is shaded grey behind the series.
std::filesystem::path draw(const std::filesystem::path& out_dir, const Style& style, const std::string& name,
                           const std::string& title, const std::string& ylabel, const std::vector<double>& time,
                           const std::vector<Series>& series, std::size_t first_row = 0) {
    const std::string data = name + ".dat", image = name + "." + style.format;
    struct Remove {
        std::filesystem::path file;
        ~Remove() {
            std::error_code ec;
            std::filesystem::remove(file, ec);
        }
    } remove_data{out_dir / data};
    bool shaded = false;
    {
        std::ofstream d(out_dir / data);
        for (std::size_t r = first_row; r < time.size(); ++r) {
            d << time[r];
            for (const auto& s : series) d << ' ' << s.values[r];
            const bool eclipse = style.irradiance && (*style.irradiance)[r] <= 0.0;
            shaded = shaded || eclipse;
            // Each eclipse row's box spans to the next row: gnuplot's own width (the distance to the next
            // point drawn) would bridge the sunlit rows between two eclipses, which are not drawn.
            const double width = r + 1 < time.size() ? time[r + 1] - time[r] : 0.0;
            d << ' ' << (eclipse ? "1" : "nan") << ' ' << width << '\n';
        }
        d.flush();
        if (!d) throw CosimError("cannot write " + (out_dir / data).string());
    }
    const std::string terminal = style.format == "svg" ? "svg noenhanced size 1100,600 font 'sans,11'"
                                                       : "pngcairo noenhanced size 1100,600 font 'sans,11'";
    std::string script = "set terminal " + terminal + "\nset output " + gnuplot_string(image) + "\nset title " +
                         gnuplot_string(title) + "\nset xlabel 'time (s)'\nset ylabel " + gnuplot_string(ylabel) +
                         "\nset grid\nset key below\nset datafile missing 'nan'\n" + flat_range(series, first_row) +
                         fault_marks(style.marks, style.onsets);
    std::string plots;
    if (shaded) {
        // Eclipse rows as boxes of height 1 on the second y axis (0..1, not shown): grey bands behind.
        script += "set y2range [0:1]\nunset y2tics\nset style fill transparent solid 0.15 noborder\n";
        plots += gnuplot_string(data) + " using ($1+$" + std::to_string(series.size() + 3) +
                 "/2):" + std::to_string(series.size() + 2) + ":" + std::to_string(series.size() + 3) +
                 " axes x1y2 with boxes lc rgb 'gray30' title 'eclipse'";
    }
    for (std::size_t i = 0; i < series.size(); ++i)
        plots += (plots.empty() ? "" : ", ") + gnuplot_string(data) + " using 1:" + std::to_string(i + 2) +
                 (series[i].points ? " with points pt 7 ps 0.7" : " with lines lw 2") + " title " +
                 gnuplot_string(series[i].title);
    script += "plot " + plots + "\n";
    run_gnuplot(out_dir, script, image);
    return out_dir / image;
}

// A derived signal of every row: NaN where it is not kept (no new sample, or invalid).
struct Derived {
    std::string name;
    std::vector<double> values;
};

std::vector<double> kept(const std::vector<double>& values, const std::vector<bool>& use) {
    std::vector<double> out(values.size(), std::nan(""));
    for (std::size_t r = 0; r < values.size(); ++r)
        if (use[r]) out[r] = values[r];
    return out;
}

// --derived: time and every derived signal as CSV columns (empty cells where not kept).
void write_derived(const std::filesystem::path& file, const std::vector<double>& time,
                   const std::vector<Derived>& derived) {
    std::ofstream out(file);
    out << "time";
    for (const auto& d : derived) out << "," << d.name;
    out << "\n" << std::setprecision(17);
    for (std::size_t r = 0; r < time.size(); ++r) {
        out << time[r];
        for (const auto& d : derived) {
            out << ",";
            if (std::isfinite(d.values[r])) out << d.values[r];
        }
        out << "\n";
    }
    out.flush();
    if (!out) throw CosimError("cannot write " + file.string());
}

// Rows where the estimate changed (the on-board computer took a sample) while it was valid: where an error
// against the moving truth means something. Between samples the estimate is held and the truth moves on,
// so an error drawn through every row saws up to the turn of one sample period.
std::vector<bool> update_rows(const std::vector<const std::vector<double>*>& estimate,
                              const std::vector<double>* valid) {
    const std::size_t n = estimate.front()->size();
    std::vector<bool> use(n, false);
    for (std::size_t r = 0; r < n; ++r) {
        bool changed = r == 0;
        for (const auto* c : estimate) changed = changed || (*c)[r] != (*c)[r - 1];
        use[r] = changed && (!valid || (*valid)[r] > 0.5);
    }
    return use;
}

// An error series at the update rows, titled with its median and 95th percentile.
Series error_series(const std::string& what, const std::vector<double>& error, const std::vector<bool>& use,
                    std::ostream& summary) {
    Series s{what, std::vector<double>(error.size(), std::nan("")), true};
    std::vector<double> kept;
    for (std::size_t r = 0; r < error.size(); ++r)
        if (use[r] && std::isfinite(error[r])) {  // no angle (a zero vector): no sample
            s.values[r] = error[r];
            kept.push_back(error[r]);
        }
    const double median = error_percentile(kept, 0.5), p95 = error_percentile(kept, 0.95);
    s.title +=
        " (median " + degrees(median) + ", p95 " + degrees(p95) + " deg, " + std::to_string(kept.size()) + " samples)";
    summary << "<tr><td>" << what << "</td><td>" << kept.size() << "</td><td>" << degrees(median) << "</td><td>"
            << degrees(p95) << "</td></tr>\n";
    return s;
}

// A CSV sampled finer than 50 us (a tenth of a 5 kHz PWM period) is a close-up of the bus: its ripple only.
bool close_up_csv(const std::vector<double>& time) {
    return time.size() > 2 && time[1] - time[0] <= 50e-6;
}

std::string html_escape(const std::string& text) {
    std::string out;
    for (char c : text)
        out += c == '<'   ? std::string("&lt;")
               : c == '&' ? std::string("&amp;")
               : c == '"' ? std::string("&quot;")
                          : std::string(1, c);
    return out;
}

// results/index.html: every figure of the folder, the error statistics of this CSV, and the run's
// statistics when a run_statistics.txt lies beside them (scripts/run_seed.sh writes it).
void write_index(const std::filesystem::path& out_dir, const std::filesystem::path& csv, const std::string& summary,
                 const std::string& measures) {
    std::vector<std::filesystem::path> pngs;
    for (const auto& e : std::filesystem::recursive_directory_iterator(out_dir))
        if (e.path().extension() == ".png" || e.path().extension() == ".svg")
            pngs.push_back(std::filesystem::relative(e.path(), out_dir));
    std::sort(pngs.begin(), pngs.end());
    const auto index = out_dir / "index.html";
    std::ofstream h(index);
    h << "<!doctype html>\n<html><head><meta charset=\"utf-8\"><title>cosim results</title>"
         "<style>body{font-family:sans-serif;max-width:1150px;margin:auto}td,th{padding:2px 10px}"
         "img{max-width:100%}</style></head><body>\n<h1>Results</h1>\n<p>From <code>"
      << html_escape(csv.filename().string()) << "</code> (<a href=\""
      << html_escape(
             std::filesystem::relative(std::filesystem::absolute(csv), std::filesystem::absolute(out_dir)).string())
      << "\">the CSV</a>).</p>\n";
    if (!summary.empty())
        h << "<h2>Errors at the estimator's samples</h2>\n<table><tr><th>error</th><th>samples</th><th>median "
             "(deg)</th><th>95th percentile (deg)</th></tr>\n"
          << summary << "</table>\n";
    h << measures;
    const auto stats = out_dir / "run_statistics.txt";
    if (std::filesystem::exists(stats)) {
        std::ifstream in(stats);
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        h << "<h2>Run statistics and parameters</h2>\n<pre>" << html_escape(text) << "</pre>\n";
    }
    h << "<h2>Figures</h2>\n";
    for (const auto& p : pngs) h << "<h3>" << p.stem().string() << "</h3>\n<img src=\"" << p.string() << "\">\n";
    h << "</body></html>\n";
    h.flush();
    if (!h) throw CosimError("cannot write " + index.string());
}

}  // namespace

std::vector<std::filesystem::path> plot_results(const std::filesystem::path& csv, const std::filesystem::path& out_dir,
                                                std::ostream& notes, const PlotOptions& options) {
    if (options.format != "png" && options.format != "svg")
        throw CosimError("--format " + options.format + ": png or svg");
    const CsvTable table = read_csv(csv);
    const auto time_col = table.find("time");
    if (!time_col) throw CosimError(csv.string() + ": no time column");
    std::filesystem::create_directories(out_dir);
    const auto& time = table.columns[*time_col];
    std::vector<std::filesystem::path> written;
    std::ostringstream summary;
    // A figure that fails is reported and the others are drawn; the command fails at the end.
    int failed = 0;
    auto add = [&](auto&& make) {
        try {
            written.push_back(make());
        } catch (const CosimError& e) {
            ++failed;
            notes << e.what() << "\n";
        }
    };
    auto column = [&](const std::string& name) -> const std::vector<double>* {
        const auto i = table.find(name);
        return i ? &table.columns[*i] : nullptr;
    };
    std::vector<Derived> derived;  // the derived signals, for --derived
    Style style;
    style.format = options.format;
    style.irradiance = column("irradiance");
    // What the run reached (per phase, after convergence, the filter's consistency) and the faults declared.
    const RunMeasures measures = measure_run(table);
    if (!close_up_csv(time)) {
        style.marks = measures.declarations;
        style.onsets = measures.injected;
    }
    // --columns: any variables against time, in one figure.
    if (!options.columns.empty()) {
        std::vector<Series> chosen;
        for (const auto& name : options.columns) {
            const auto* c = column(name);
            if (!c) throw CosimError(csv.string() + ": no column '" + name + "'");
            chosen.push_back({name, *c});
        }
        add([&] { return draw(out_dir, style, "columns", "Chosen columns", "value", time, chosen); });
    }
    const bool close_up = close_up_csv(time);

    // Seed 000 fig. 8: each component of the acquired sun vector (the estimator's samples) on the real one.
    const char* axis[] = {"x", "y", "z"};
    std::vector<const std::vector<double>*> sun_meas, sun_real;
    for (int i = 1; i <= 3 && !close_up; ++i) {
        const std::string k = std::to_string(i);
        const auto* real = column("sun_body[" + k + "]");
        const auto* meas = column("sun_meas[" + k + "]");
        if (!real || !meas) continue;
        sun_real.push_back(real);
        sun_meas.push_back(meas);
        const auto use = update_rows({meas}, column("sun_valid"));  // an invalid sample is no measurement
        Series acquired{std::string("acquired s") + axis[i - 1], std::vector<double>(time.size(), std::nan("")), true};
        for (std::size_t r = 0; r < time.size(); ++r)
            if (use[r]) acquired.values[r] = (*meas)[r];
        add([&] {
            return draw(out_dir, style, std::string("sun_vector_") + axis[i - 1],
                        std::string("Sun vector, body ") + axis[i - 1] + ": real and acquired (seed 000 fig. 8)",
                        "component", time, {{std::string("real s") + axis[i - 1], *real}, acquired});
        });
    }
    if (!close_up && sun_meas.size() == 3) {
        std::vector<double> error(time.size());
        for (std::size_t r = 0; r < time.size(); ++r) {
            const double m[3] = {(*sun_meas[0])[r], (*sun_meas[1])[r], (*sun_meas[2])[r]},
                         s[3] = {(*sun_real[0])[r], (*sun_real[1])[r], (*sun_real[2])[r]};
            error[r] = vector_angle_degrees(m, s);  // NaN for a zero vector: no sun acquired, left out
        }
        const auto use = update_rows(sun_meas, column("sun_valid"));
        derived.push_back({"sun_error_deg", kept(error, use)});
        add([&] {
            return draw(out_dir, style, "sun_error", "Sun vector error at the estimator samples (while valid)",
                        "degrees", time, {error_series("sun vector error", error, use, summary)});
        });
    } else if (!close_up) {
        notes << "no sun_body / sun_meas columns: sun vector figures skipped\n";
    }

    if (const auto* v = column("v_bus")) {
        if (!close_up)
            add([&] {
                return draw(out_dir, style, "bus_voltage", "Bus voltage (seed 000 fig. 9)", "V", time, {{"v_bus", *v}});
            });
        // The ripple: the last millisecond (five PWM periods at 5 kHz) of a close-up CSV.
        if (close_up) {
            std::size_t first = time.size() - 1;
            while (first > 0 && time.back() - time[first - 1] <= 1e-3) --first;
            add([&] {
                return draw(out_dir, style, "bus_ripple", "Bus voltage ripple over the last millisecond (PWM at 5 kHz)",
                            "V", time, {{"v_bus", *v}}, first);
            });
        }
    } else {
        notes << "no v_bus column: bus voltage figure skipped\n";
    }

    // Every estimate the run holds, each against the truth at its own samples while it is valid, with its own
    // median and p95: the single-frame Q-method (q_est, valid) and the filter (q_filt, filter_valid).
    struct Estimate {
        const char* column;
        const char* valid;
        const char* title;
    };
    const Estimate estimates[] = {{"q_est", "valid", "single-frame q_est"},
                                  {"q_filt", "filter_valid", "filter q_filt"}};
    std::vector<Series> attitude;
    for (const auto& e : estimates) {
        const std::vector<double>* q_true[4];
        std::vector<const std::vector<double>*> q(4);
        bool have = !close_up;
        for (int i = 0; i < 4 && have; ++i) {
            q_true[i] = column("q_true[" + std::to_string(i + 1) + "]");
            q[i] = column(std::string(e.column) + "[" + std::to_string(i + 1) + "]");
            have = have && q_true[i] && q[i];
        }
        if (!have) continue;
        // The error vector of every row (analysis/derived_signals.hpp), kept at the estimate's updates.
        std::vector<double> error(time.size()), axis_error[3];
        for (auto& a : axis_error) a.resize(time.size());
        std::vector<std::array<double, 3>> vectors(time.size());
        for (std::size_t r = 0; r < time.size(); ++r) {
            vectors[r] =
                analysis::attitude_error_vector({(*q_true[0])[r], (*q_true[1])[r], (*q_true[2])[r], (*q_true[3])[r]},
                                                {(*q[0])[r], (*q[1])[r], (*q[2])[r], (*q[3])[r]});
            error[r] = std::hypot(vectors[r][0], vectors[r][1], vectors[r][2]) * 180.0 / std::numbers::pi;
            for (int k = 0; k < 3; ++k)
                axis_error[k][r] = vectors[r][static_cast<std::size_t>(k)] * 180.0 / std::numbers::pi;
        }
        const auto use = update_rows(q, column(e.valid));
        if (std::none_of(use.begin(), use.end(), [](bool u) { return u; })) {
            // A filter the system does not run (filter = none) or that never became valid: nothing to draw.
            notes << e.title << ": no valid sample in the CSV, its figures skipped\n";
            continue;
        }
        attitude.push_back(error_series(e.title, error, use, summary));
        const std::string prefix = e.column;
        derived.push_back({prefix + "_error_deg", kept(error, use)});
        const char* axis_names[] = {"roll", "pitch", "yaw"};
        std::vector<Series> axes;
        for (int k = 0; k < 3; ++k) {
            derived.push_back({prefix + "_" + axis_names[k] + "_deg", kept(axis_error[k], use)});
            axes.push_back({std::string(axis_names[k]) + " (body x, y, z)", derived.back().values, true});
        }
        add([&] {
            return draw(out_dir, style, "attitude_error_axes_" + prefix,
                        std::string("Attitude error of ") + e.title + " about the body axes (while valid)", "degrees",
                        time, axes);
        });
        // The filter's own view of its error: the 3-sigma bound on the figure, its coverage, and the
        // normalized error per degree of freedom from the covariance factor (1 when consistent).
        if (std::string(e.column) != "q_filt") continue;
        if (const auto* bound = column("attitude_bound")) {
            // The filter's own 3-sigma bound (3 sqrt(tr P)) drawn beside its error; its consistency is judged
            // by the chi-square measure below, not by this bound (5.2 sigma per axis for an isotropic P).
            Series b{"filter 3-sigma bound 3 sqrt(tr P)", std::vector<double>(time.size(), std::nan("")), false};
            for (std::size_t r = 0; r < time.size(); ++r)
                if (use[r]) b.values[r] = (*bound)[r] * 180.0 / std::numbers::pi;
            attitude.push_back(b);
        }
        std::vector<const std::vector<double>*> l;
        for (int i = 1; i <= 6; ++i)
            if (const auto* c = column("attitude_cov_sqrt[" + std::to_string(i) + "]")) l.push_back(c);
        if (l.size() == 6) {
            // The normalized error epsilon = dtheta' inv(P) dtheta at every sample, against chi2(3)'s 99 % point.
            std::vector<double> nees(time.size(), std::nan("")), epsilon(time.size(), std::nan(""));
            for (std::size_t r = 0; r < time.size(); ++r) {
                if (!use[r]) continue;
                nees[r] = analysis::normalized_error_per_dof(
                    vectors[r], {(*l[0])[r], (*l[1])[r], (*l[2])[r], (*l[3])[r], (*l[4])[r], (*l[5])[r]});
                epsilon[r] = 3.0 * nees[r];
            }
            derived.push_back({"q_filt_nees_per_dof", nees});
            derived.push_back({"q_filt_nees", epsilon});
            std::vector<double> limit(time.size(), chi2_3dof_99);
            add([&] {
                return draw(out_dir, style, "filter_normalized_error",
                            "Filter normalized error dtheta' inv(P) dtheta (3 degrees of freedom; 3 on average when "
                            "consistent, 99 % of samples below 11.34)",
                            "NEES", time, {{"q_filt NEES", epsilon, true}, {"chi2(3) 99 % point 11.34", limit}});
            });
        }
    }
    if (!attitude.empty()) {
        add([&] {
            return draw(out_dir, style, "attitude_error",
                        "Attitude error of each estimate at its samples (while valid)", "degrees", time, attitude);
        });
    } else if (!close_up) {
        notes << "no q_true with q_est or q_filt columns: attitude error figure skipped\n";
    }

    if (const auto* soc = column("soc"); soc && !close_up)
        add([&] {
            return draw(out_dir, style, "battery_soc", "Battery state of charge", "state of charge (0 to 1)", time,
                        {{"soc", *soc}});
        });
    else if (!close_up)
        notes << "no soc column: battery figure skipped\n";
    if (options.derived) {
        write_derived(*options.derived, time, derived);
        written.push_back(*options.derived);
    }
    write_index(out_dir, csv, summary.str(), measures_html(measures));
    written.push_back(out_dir / "index.html");
    if (failed)
        throw CosimError(std::to_string(failed) + " figure(s) failed (above); the others are in " + out_dir.string());
    return written;
}

}  // namespace analysis
