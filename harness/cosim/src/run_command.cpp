#include "run_command.hpp"

#include <sys/statvfs.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <memory>

#include "analysis/couplings.hpp"
#include "analysis/run_measures.hpp"
#include "engine/cosim_error.hpp"
#include "engine/interrupt.hpp"
#include "engine/output_file.hpp"
#include "engine/ssp_archive.hpp"
#include "engine/value_text.hpp"

namespace cosim {

namespace {

// Every --cs names a component of the system: a misspelt name would otherwise run the whole system
// through Model Exchange and report success.
void check_co_simulation_names(const SystemDescription& description, const std::vector<std::string>& names) {
    for (const auto& name : names) {
        const bool known = std::any_of(description.components.begin(), description.components.end(),
                                       [&](const auto& c) { return c.name == name; });
        if (!known) throw CosimError("--cs " + name + ": the system has no component of that name");
    }
}

// Before the run: say how large the CSV will be when it is large, and refuse what the disk cannot
// hold unless forced. The estimate is a floor: 25 bytes per cell (a round-trip double and a comma).
void check_output_size(const ExecutionOptions& ex, const CsvWriter& csv, bool force, std::ostream& note) {
    const double rows = std::floor((ex.stop_time - ex.start_time) / ex.output_interval) + 2;  // + start and stop
    const double bytes = rows * static_cast<double>(csv.columns()) * 25.0;
    if (rows >= large_output_rows)
        note << "cosim: " << csv.path().string() << " will have about " << format_real(std::round(rows)) << " rows of "
             << csv.columns() << " columns (" << format_real(std::round(bytes / 1e6)) << " MB or more)"
             << (ex.event_rows ? ", plus two per event" : "") << "\n";
    struct statvfs fs {};
    const auto folder = std::filesystem::absolute(csv.path()).parent_path();
    if (::statvfs(folder.c_str(), &fs) != 0) return;
    const double free_bytes = static_cast<double>(fs.f_bavail) * static_cast<double>(fs.f_frsize);
    if (bytes > free_bytes && !force)
        throw CosimError(csv.path().string() + " would need about " + format_real(std::round(bytes / 1e6)) + " MB; " +
                         folder.string() + " has " + format_real(std::round(free_bytes / 1e6)) +
                         " MB free (give --force to run it anyway, or a larger --output-interval)");
}

// The statistics of a run cut short: what was computed and written before the signal.
void report_interrupted(const Interrupted& e, double last_time, const CsvWriter* csv, double wall,
                        std::ostream& report) {
    report << "interrupted (" << e.what() << ") after " << format_real(wall) << " s wall";
    if (csv)
        report << "; " << csv->rows() << " rows up to t = " << format_real(last_time) << " s written to "
               << csv->path().string();
    else
        report << " at t = " << format_real(last_time) << " s";
    report << "\n";
}

}  // namespace

RunStatistics run_system(const RunOptions& options, std::ostream& report) {
    throw_if_interrupted();
    const SystemDescription description = read_system_description(options.ssd);
    check_co_simulation_names(description, options.system.co_simulation);
    if (options.csv) {
        auto inputs = system_inputs(description, options.system.fmu_dirs);
        inputs.insert(inputs.end(), options.system.parameter_files.begin(), options.system.parameter_files.end());
        refuse_overwriting_inputs("--output", *options.csv, inputs);
    }
    SystemOptions system_options = options.system;
    if (options.tolerance) system_options.tolerance = options.tolerance;
    if (options.communication_step) system_options.communication_step = options.communication_step;
    if (options.reference) {
        if (!system_options.co_simulation.empty())
            throw CosimError("--reference runs every component as Model Exchange: drop --cs");
        system_options.model_exchange_only = true;
    }
    if (options.stop_time && !std::isfinite(*options.stop_time))
        throw CosimError("--stop-time must be finite, got " + format_real(*options.stop_time));
    System system(description, system_options);
    // Without --stop-time: the .ssd's orbits of the truth (derived from its orbit), else its stopTime.
    const auto stop = options.stop_time ? options.stop_time : analysis::default_stop_time(system);
    if (!stop) throw CosimError(options.ssd.string() + " has no DefaultExperiment stopTime: give --stop-time");
    analysis::check_couplings(system, options.allow_mismatch, std::cerr);
    // --columns names variables whether or not a CSV is written: a typo is refused, not ignored.
    if (!options.columns.empty() && !options.csv) (void)output_columns(system, options.columns);
    // A component parameter set directly wins over the system parameter that feeds it, for that component only.
    for (const auto& direct : system.fed_parameters_set_directly())
        std::cerr << "cosim: " << direct << " is set directly: the system parameter no longer feeds it\n";

    ExecutionOptions ex;
    ex.start_time = description.start_time.value_or(0.0);
    ex.stop_time = *stop;
    const RunDefaults defaults = run_defaults(system, ex.start_time, ex.stop_time);
    ex.output_interval = options.output_interval.value_or(defaults.output_interval);
    if (!options.output_interval && defaults.shortened_from && options.csv)
        // The system's interval is for its usual run: a shorter one still gets rows (a hundred), said once.
        std::cerr << "cosim: the output interval " << format_real(*defaults.shortened_from) << " s of "
                  << options.ssd.filename().string() << " is longer than the run ("
                  << format_real(ex.stop_time - ex.start_time) << " s): a row every " << format_real(ex.output_interval)
                  << " s instead (--output-interval to choose)\n";
    ex.relative_tolerance = options.tolerance.value_or(defaults.tolerance);
    ex.realtime = options.realtime;
    ex.realtime_tolerance = options.realtime_tolerance;
    ex.event_rows = options.event_rows;
    ex.reference = options.reference;
    ex.max_step = options.max_step;
    check_run_span(ex, options.communication_step, options.force);

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

    InterruptCheck interrupt;
    std::vector<Observer*> observers{&interrupt};
    // A system that declares its measures (<ex:Measures>) says at the end what the run reached.
    std::unique_ptr<analysis::MeasureRecorder> measures;
    if (description.measures) {
        analysis::check_measure_names(description.measures->report, options.ssd.string());
        measures = std::make_unique<analysis::MeasureRecorder>(system);
        observers.push_back(measures.get());
    }
    std::unique_ptr<CsvWriter> csv;
    if (options.csv) {
        // A run that injects faults writes each one's onset parameter as a column beside the outputs: the CSV
        // alone then gives `cosim plot` the onsets to mark (analysis::measure_run reads them back).
        std::vector<std::string> columns = options.columns;
        if (const auto onsets = analysis::onset_columns(analysis::fault_onsets(system));
            columns.empty() && !onsets.empty()) {
            for (const auto& c : output_columns(system, {}))
                columns.push_back(system.components()[c.component].name + "." + c.variable->name);
            columns.insert(columns.end(), onsets.begin(), onsets.end());
        }
        csv = std::make_unique<CsvWriter>(*options.csv, system, columns);
        check_output_size(ex, *csv, options.force, std::cerr);
        observers.push_back(csv.get());
    }
    Execution execution(system, ex);
    RunStatistics stats;
    try {
        stats = execution.run(observers);
    } catch (const Interrupted& e) {
        if (tty && last_percent >= 0) std::fprintf(stderr, "\r%60s\r", "");
        if (csv) csv->close();  // the rows computed so far, flushed and checked
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        report_interrupted(e, interrupt.last_time, csv.get(), wall, report);
        report.flush();
        throw;
    }
    if (csv) csv->close();
    if (tty && last_percent >= 0) std::fprintf(stderr, "\r%60s\r", "");
    print_statistics(stats, report);
    if (measures) {
        analysis::MeasureOptions mo;
        mo.converged_after = description.measures->converged_after;
        analysis::print_measures(analysis::measure_run(measures->table(), mo), analysis::fault_onsets(system),
                                 description.measures->report, report);
    }
    // What this run changed from the .ssd, for a results page that shows what was run.
    for (const auto& f : options.system.parameter_files) report << "--parameters " << f.string() << "\n";
    for (const auto& s : options.system.settings) report << "--set " << s << "\n";
    return stats;
}

void print_statistics(const RunStatistics& s, std::ostream& out) {
    const double rtf = s.wall_time > 0 ? s.simulated_time / s.wall_time : 0.0;
    out << std::setprecision(4);
    out << "simulated " << s.simulated_time << " s in " << s.wall_time << " s wall (real-time factor " << rtf << ")"
        << (s.terminated_early ? ", stopped early at a component's request" : "") << "\n";
    out << "integrator steps " << s.integrator_steps << ", right-hand sides " << s.rhs_evaluations << ", time events "
        << s.time_events << ", state events " << s.state_events << ", step events " << s.step_events
        << ", communication points " << s.communication_points << ", integrator restarts " << s.restarts
        << (s.failure_restarts > 0 ? ", restarts after repeated step failures " + std::to_string(s.failure_restarts)
                                   : "")
        << "\n";
    if (s.realtime_max_behind != 0.0 || s.late_realtime_points)
        out << "real-time: " << s.late_realtime_points << " output points late by more than "
            << s.realtime_tolerance * 1e3 << " ms; at most " << s.realtime_max_behind * 1e3
            << " ms behind the wall clock\n";
    for (const auto& c : s.components) {
        out << "  " << std::left << std::setw(20) << c.name << std::right;
        if (c.steps)
            out << " co-simulation steps " << c.steps << "\n";
        else
            out << " derivative evaluations " << c.rhs_evaluations << ", events " << c.events << "\n";
        if (c.link) {
            const auto& l = *c.link;
            out << "    hardware link: " << l.exchanges << " frames, " << l.answered << " answered, " << l.misses
                << " missed, " << l.late << " late, " << l.malformed << " malformed\n";
            if (l.answered)
                out << "    latency ms: min " << l.latency_min * 1e3 << ", median " << l.latency_median * 1e3
                    << ", p95 " << l.latency_p95 * 1e3 << ", max " << l.latency_max * 1e3 << "\n";
        }
    }
}

}  // namespace cosim
