#include "plot_command.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <optional>
#include <string>

#include "cosim_error.hpp"
#include "csv_table.hpp"

namespace cosim {

double attitude_error_degrees(const double q_a[4], const double q_b[4]) {
    double dot = 0.0, na = 0.0, nb = 0.0;
    for (int i = 0; i < 4; ++i) {
        dot += q_a[i] * q_b[i];
        na += q_a[i] * q_a[i];
        nb += q_b[i] * q_b[i];
    }
    const double c = std::min(1.0, std::abs(dot) / std::sqrt(na * nb));  // q and −q are one attitude
    return 2.0 * std::acos(c) * 180.0 / std::numbers::pi;
}

namespace {

struct Series {
    std::string title;
    std::vector<double> values;
};

// One figure: writes the data and a gnuplot script, runs gnuplot, returns the PNG.
std::filesystem::path draw(const std::filesystem::path& out_dir, const std::string& name, const std::string& title,
                           const std::string& ylabel, const std::vector<double>& time,
                           const std::vector<Series>& series) {
    const auto data = out_dir / (name + ".dat");
    {
        std::ofstream d(data);
        for (std::size_t r = 0; r < time.size(); ++r) {
            d << time[r];
            for (const auto& s : series) d << ' ' << s.values[r];
            d << '\n';
        }
    }
    const auto png = out_dir / (name + ".png");
    std::string script = "set terminal pngcairo noenhanced size 1100,600 font 'sans,11'\nset output '" + png.string() +
                         "'\nset title '" + title + "'\nset xlabel 'time (s)'\nset ylabel '" + ylabel +
                         "'\nset grid\nset key outside right\nplot ";
    for (std::size_t i = 0; i < series.size(); ++i)
        script += (i ? ", " : "") + std::string("'") + data.string() + "' using 1:" + std::to_string(i + 2) +
                  (series[i].title.starts_with("acquired") ? " with points pt 7 ps 0.7" : " with lines lw 2") +
                  " title '" + series[i].title + "'";
    script += "\n";
    FILE* gp = popen("gnuplot 2>&1", "w");
    if (!gp) throw CosimError("cannot start gnuplot (install the Debian package gnuplot-nox)");
    std::fputs(script.c_str(), gp);
    const int rc = pclose(gp);
    std::filesystem::remove(data);
    if (rc != 0 || !std::filesystem::exists(png)) throw CosimError("gnuplot failed drawing " + png.string());
    return png;
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
    auto column = [&](const std::string& name) -> const std::vector<double>* {
        const auto i = table.find(name);
        return i ? &table.columns[*i] : nullptr;
    };

    std::vector<Series> sun;
    for (int i = 1; i <= 3; ++i) {
        const std::string k = std::to_string(i);
        if (const auto* real = column("sun_body[" + k + "]")) sun.push_back({"real s" + k, *real});
        if (const auto* meas = column("sun_meas[" + k + "]")) sun.push_back({"acquired s" + k, *meas});
    }
    if (!sun.empty())
        written.push_back(
            draw(out_dir, "sun_vector", "Sun vector in body axes: real and acquired", "component", time, sun));
    else
        notes << "no sun_body / sun_meas columns: sun vector figure skipped\n";

    if (const auto* v = column("v_bus"))
        written.push_back(draw(out_dir, "bus_voltage", "Bus voltage", "V", time, {{"v_bus", *v}}));
    else
        notes << "no v_bus column: bus voltage figure skipped\n";

    const std::vector<double>* q_true[4];
    const std::vector<double>* q_est[4];
    bool have_q = true;
    for (int i = 0; i < 4; ++i) {
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
        written.push_back(
            draw(out_dir, "attitude_error", "Attitude error of the estimate", "degrees", time, {{"error", error}}));
    } else {
        notes << "no q_true / q_est columns: attitude error figure skipped\n";
    }

    if (const auto* soc = column("soc"))
        written.push_back(draw(out_dir, "battery_soc", "Battery state of charge", "1", time, {{"soc", *soc}}));
    else
        notes << "no soc column: battery figure skipped\n";
    return written;
}

}  // namespace cosim
