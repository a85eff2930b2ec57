#include "run_command.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <cstdio>
#include <iomanip>

#include "cosim_error.hpp"

namespace cosim {

namespace {

// The smallest step size and tolerance any component's DefaultExperiment asks for.
void defaults_from_components(const System& system, double& interval, double& tolerance) {
    for (const auto& c : system.components()) {
        const auto& ex = c.description().default_experiment;
        if (!ex) continue;
        if (ex->step_size && *ex->step_size > 0) interval = std::min(interval, *ex->step_size);
        if (ex->tolerance && *ex->tolerance > 0) tolerance = std::min(tolerance, *ex->tolerance);
    }
}

}  // namespace

RunStatistics run_system(const RunOptions& options, std::ostream& report) {
    const SystemDescription description = read_system_description(options.ssd);
    SystemOptions system_options = options.system;
    if (options.tolerance) system_options.tolerance = options.tolerance;
    if (options.communication_step) system_options.communication_step = options.communication_step;
    if (options.reference) {
        if (!system_options.co_simulation.empty()) throw CosimError("--reference runs every component as Model Exchange: drop --cs");
        system_options.model_exchange_only = true;
    }
    System system(description, system_options);

    ExecutionOptions ex;
    ex.start_time = description.start_time.value_or(0.0);
    const auto stop = options.stop_time ? options.stop_time : description.stop_time;
    if (!stop) throw CosimError(options.ssd.string() + " has no DefaultExperiment stopTime: give --stop-time");
    ex.stop_time = *stop;
    double interval = std::numeric_limits<double>::infinity(), tolerance = 1e-6;
    defaults_from_components(system, interval, tolerance);
    // The .ssd's own output interval, else no finer than a thousandth of the run: an orbit at the FMUs'
    // 1 ms default would write millions of rows.
    const double span = ex.stop_time - ex.start_time;
    if (description.output_interval) interval = *description.output_interval;
    else if (!std::isfinite(interval) || interval < span / 1000.0) interval = span / 1000.0;
    ex.output_interval = options.output_interval.value_or(interval);
    ex.relative_tolerance = options.tolerance.value_or(tolerance);
    ex.realtime = options.realtime;
    ex.event_rows = options.event_rows;
    ex.reference = options.reference;

    const bool tty = options.progress && isatty(fileno(stderr));
    const auto started = std::chrono::steady_clock::now();
    int last_percent = -1;
    if (tty) {
        ex.progress = [&](double fraction) {
            const int percent = static_cast<int>(fraction * 100.0);
            if (percent == last_percent) return;
            if (std::chrono::steady_clock::now() - started < std::chrono::seconds(1)) return;
            last_percent = percent;
            const int bar = percent / 2;
            std::fprintf(stderr, "\r[%-50s] %3d%%", std::string(static_cast<std::size_t>(bar), '#').c_str(), percent);
            std::fflush(stderr);
        };
    }

    std::vector<Observer*> observers;
    std::unique_ptr<CsvWriter> csv;
    if (options.csv) {
        csv = std::make_unique<CsvWriter>(*options.csv, system, options.columns);
        observers.push_back(csv.get());
    }
    Execution execution(system, ex);
    const RunStatistics stats = execution.run(observers);
    if (tty && last_percent >= 0) std::fprintf(stderr, "\r%60s\r", "");
    print_statistics(stats, report);
    return stats;
}

void print_statistics(const RunStatistics& s, std::ostream& out) {
    const double rtf = s.wall_time > 0 ? s.simulated_time / s.wall_time : 0.0;
    out << std::setprecision(4);
    out << "simulated " << s.simulated_time << " s in " << s.wall_time << " s wall (real-time factor " << rtf << ")"
        << (s.terminated_early ? ", stopped early at a component's request" : "") << "\n";
    out << "integrator steps " << s.integrator_steps << ", right-hand sides " << s.rhs_evaluations << ", time events "
        << s.time_events << ", state events " << s.state_events << ", step events " << s.step_events
        << ", communication points " << s.communication_points << ", integrator restarts " << s.restarts << "\n";
    if (s.late_realtime_points) out << "real-time: " << s.late_realtime_points << " output points were late\n";
    for (const auto& c : s.components) {
        out << "  " << std::left << std::setw(20) << c.name << std::right;
        if (c.steps) out << " co-simulation steps " << c.steps << "\n";
        else out << " derivative evaluations " << c.rhs_evaluations << ", events " << c.events << "\n";
        if (c.link) {
            const auto& l = *c.link;
            out << "    hardware link: " << l.exchanges << " frames, " << l.answered << " answered, " << l.misses
                << " missed, " << l.late << " late, " << l.malformed << " malformed\n";
            if (l.answered)
                out << "    latency ms: min " << l.latency_min * 1e3 << ", median " << l.latency_median * 1e3 << ", p95 "
                    << l.latency_p95 * 1e3 << ", max " << l.latency_max * 1e3 << "\n";
        }
    }
}

}  // namespace cosim
