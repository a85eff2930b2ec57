#include "analysis/result_figures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>

#include "analysis/angle_error.hpp"
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

double percentile(std::vector<double> v, double p) {
    if (v.empty()) return std::nan("");
    std::sort(v.begin(), v.end());
    return v[static_cast<std::size_t>(p * static_cast<double>(v.size() - 1) + 0.5)];
}

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

// One figure: writes the data and a gnuplot script, runs gnuplot in out_dir (no path in the script),
// returns the PNG.
std::filesystem::path draw(const std::filesystem::path& out_dir, const std::string& name, const std::string& title,
                           const std::string& ylabel, const std::vector<double>& time,
                           const std::vector<Series>& series, std::size_t first_row = 0) {
    const std::string data = name + ".dat", png = name + ".png";
    struct Remove {
        std::filesystem::path file;
        ~Remove() {
            std::error_code ec;
            std::filesystem::remove(file, ec);
        }
    } remove_data{out_dir / data};
    {
        std::ofstream d(out_dir / data);
        for (std::size_t r = first_row; r < time.size(); ++r) {
            d << time[r];
            for (const auto& s : series) d << ' ' << s.values[r];
            d << '\n';
        }
        d.flush();
        if (!d) throw CosimError("cannot write " + (out_dir / data).string());
    }
    std::string script =
        "set terminal pngcairo noenhanced size 1100,600 font 'sans,11'\nset output " + gnuplot_string(png) +
        "\nset title " + gnuplot_string(title) + "\nset xlabel 'time (s)'\nset ylabel " + gnuplot_string(ylabel) +
        "\nset grid\nset key outside right\nset datafile missing 'nan'\n" + flat_range(series, first_row) + "plot ";
    for (std::size_t i = 0; i < series.size(); ++i)
        script += (i ? ", " : "") + gnuplot_string(data) + " using 1:" + std::to_string(i + 2) +
                  (series[i].points ? " with points pt 7 ps 0.7" : " with lines lw 2") + " title " +
                  gnuplot_string(series[i].title);
    script += "\n";
    run_gnuplot(out_dir, script, png);
    return out_dir / png;
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
        if (use[r]) {
            s.values[r] = error[r];
            kept.push_back(error[r]);
        }
    const double median = percentile(kept, 0.5), p95 = percentile(kept, 0.95);
    s.title +=
        " (median " + degrees(median) + ", p95 " + degrees(p95) + " deg, " + std::to_string(kept.size()) + " samples)";
    summary << "<tr><td>" << what << "</td><td>" << kept.size() << "</td><td>" << degrees(median) << "</td><td>"
            << degrees(p95) << "</td></tr>\n";
    return s;
}

// results/index.html: every figure of the folder, the error statistics of this CSV, and the run's
// statistics when a run_statistics.txt lies beside them (scripts/run_seed.sh writes it).
void write_index(const std::filesystem::path& out_dir, const std::filesystem::path& csv, const std::string& summary) {
    std::vector<std::filesystem::path> pngs;
    for (const auto& e : std::filesystem::recursive_directory_iterator(out_dir))
        if (e.path().extension() == ".png") pngs.push_back(std::filesystem::relative(e.path(), out_dir));
    std::sort(pngs.begin(), pngs.end());
    const auto index = out_dir / "index.html";
    std::ofstream h(index);
    h << "<!doctype html>\n<html><head><meta charset=\"utf-8\"><title>cosim results</title>"
         "<style>body{font-family:sans-serif;max-width:1150px;margin:auto}td,th{padding:2px 10px}"
         "img{max-width:100%}</style></head><body>\n<h1>Results</h1>\n<p>From <code>"
      << csv.filename().string() << "</code>.</p>\n";
    if (!summary.empty())
        h << "<h2>Errors at the estimator's samples</h2>\n<table><tr><th>error</th><th>samples</th><th>median "
             "(deg)</th><th>95th percentile (deg)</th></tr>\n"
          << summary << "</table>\n";
    const auto stats = out_dir / "run_statistics.txt";
    if (std::filesystem::exists(stats)) {
        std::ifstream in(stats);
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        std::string escaped;
        for (char c : text)
            escaped += c == '<' ? std::string("&lt;") : c == '&' ? std::string("&amp;") : std::string(1, c);
        h << "<h2>Run statistics and parameters</h2>\n<pre>" << escaped << "</pre>\n";
    }
    h << "<h2>Figures</h2>\n";
    for (const auto& p : pngs) h << "<h3>" << p.stem().string() << "</h3>\n<img src=\"" << p.string() << "\">\n";
    h << "</body></html>\n";
    h.flush();
    if (!h) throw CosimError("cannot write " + index.string());
}

}  // namespace

std::vector<std::filesystem::path> plot_results(const std::filesystem::path& csv, const std::filesystem::path& out_dir,
                                                std::ostream& notes) {
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
    // A CSV sampled finer than 50 us (a tenth of a 5 kHz PWM period) is a close-up of the bus: its ripple only.
    const bool close_up = time.size() > 2 && time[1] - time[0] <= 50e-6;

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
        const auto use = update_rows({meas}, nullptr);
        Series acquired{std::string("acquired s") + axis[i - 1], std::vector<double>(time.size(), std::nan("")), true};
        for (std::size_t r = 0; r < time.size(); ++r)
            if (use[r]) acquired.values[r] = (*meas)[r];
        add([&] {
            return draw(out_dir, std::string("sun_vector_") + axis[i - 1],
                        std::string("Sun vector, body ") + axis[i - 1] + ": real and acquired (seed 000 fig. 8)",
                        "component", time, {{std::string("real s") + axis[i - 1], *real}, acquired});
        });
    }
    if (!close_up && sun_meas.size() == 3) {
        std::vector<double> error(time.size());
        for (std::size_t r = 0; r < time.size(); ++r) {
            double m[3], s[3];
            for (int i = 0; i < 3; ++i) {
                m[i] = (*sun_meas[i])[r];
                s[i] = (*sun_real[i])[r];
            }
            const double angle = analysis::vector_angle_degrees(m, s);
            error[r] = std::isfinite(angle) ? angle : 0.0;  // a zero vector (no sun acquired yet)
        }
        const auto use = update_rows(sun_meas, column("sun_valid"));
        add([&] {
            return draw(out_dir, "sun_error", "Sun vector error at the estimator samples (while valid)", "degrees",
                        time, {error_series("sun vector error", error, use, summary)});
        });
    } else if (!close_up) {
        notes << "no sun_body / sun_meas columns: sun vector figures skipped\n";
    }

    if (const auto* v = column("v_bus")) {
        if (!close_up)
            add([&] {
                return draw(out_dir, "bus_voltage", "Bus voltage (seed 000 fig. 9)", "V", time, {{"v_bus", *v}});
            });
        // The ripple: the last millisecond (five PWM periods at 5 kHz) of a close-up CSV.
        if (close_up) {
            std::size_t first = time.size() - 1;
            while (first > 0 && time.back() - time[first - 1] <= 1e-3) --first;
            add([&] {
                return draw(out_dir, "bus_ripple", "Bus voltage ripple over the last millisecond (PWM at 5 kHz)", "V",
                            time, {{"v_bus", *v}}, first);
            });
        }
    } else {
        notes << "no v_bus column: bus voltage figure skipped\n";
    }

    const std::vector<double>* q_true[4];
    std::vector<const std::vector<double>*> q_est(4);
    bool have_q = !close_up;
    for (int i = 0; i < 4 && have_q; ++i) {
        q_true[i] = column("q_true[" + std::to_string(i + 1) + "]");
        q_est[i] = column("q_est[" + std::to_string(i + 1) + "]");
        have_q = have_q && q_true[i] && q_est[i];
    }
    if (have_q) {
        std::vector<double> error(time.size());
        for (std::size_t r = 0; r < time.size(); ++r) {
            double a[4], b[4];
            for (int i = 0; i < 4; ++i) {
                a[i] = (*q_true[i])[r];
                b[i] = (*q_est[i])[r];
            }
            error[r] = attitude_error_degrees(a, b);
        }
        const auto use = update_rows(q_est, column("valid"));
        add([&] {
            return draw(out_dir, "attitude_error", "Attitude error at the estimator samples (while valid)", "degrees",
                        time, {error_series("attitude error", error, use, summary)});
        });
    } else if (!close_up) {
        notes << "no q_true / q_est columns: attitude error figure skipped\n";
    }

    if (const auto* soc = column("soc"); soc && !close_up)
        add([&] { return draw(out_dir, "battery_soc", "Battery state of charge", "1", time, {{"soc", *soc}}); });
    else if (!close_up)
        notes << "no soc column: battery figure skipped\n";
    write_index(out_dir, csv, summary.str());
    written.push_back(out_dir / "index.html");
    if (failed)
        throw CosimError(std::to_string(failed) + " figure(s) failed (above); the others are in " + out_dir.string());
    return written;
}

}  // namespace analysis
