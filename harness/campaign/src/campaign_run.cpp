#include "campaign_run.hpp"

#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>

#include "aims.hpp"
#include "analysis/couplings.hpp"
#include "analysis/run_measures.hpp"
#include "campaign_error.hpp"
#include "draws.hpp"
#include "engine/cosim_error.hpp"
#include "engine/execution.hpp"
#include "engine/interrupt.hpp"
#include "engine/name_hint.hpp"
#include "engine/observer.hpp"
#include "engine/run_defaults.hpp"
#include "engine/setting.hpp"
#include "engine/value_text.hpp"
#include "metric_observer.hpp"

namespace campaign {

namespace {

// The variable a "component.variable=value" setting names (or the system parameter of "name=value").
std::string setting_variable(const std::string& setting) {
    const cosim::Setting s = cosim::parse_setting(setting, false);
    return s.variable;
}

void check_variable(const cosim::System& system, const std::string& name, const std::string& what) {
    if (system.is_system_parameter(name)) return;  // its name and value checked as the system was built
    const auto split = cosim::split_variable_name(name);
    if (!split) {
        // A name without a '.' is a system parameter of the .ssd (set as --set NAME=VALUE sets it).
        std::vector<std::string> names;
        for (const auto& p : system.description().parameters) names.push_back(p.name);
        throw CampaignError(what + ": '" + name + "' is no system parameter of " +
                            system.description().file.filename().string() + cosim::name_hint(name, names) +
                            (names.empty() ? " (it has none)" : "") +
                            "; a component's variable is named component.variable");
    }
    const std::size_t c = system.component_index(split->component);
    const auto* v = system.components()[c].description().find_variable(split->variable);
    if (!v)
        throw CampaignError(
            what + ": " +
            cosim::unknown_variable_message(system.components()[c].description(), split->component, split->variable) +
            " in " + system.description().file.string());
    using fmi_loader::Causality;
    if (v->causality == Causality::output || v->causality == Causality::calculated_parameter ||
        v->causality == Causality::independent)
        throw CampaignError(what + ": '" + name + "' is computed by its FMU and cannot be set");
}

// The value a setting gives must fit its variable's type (a Real where an Integer is, a text that is
// no item of an Enumeration): refused before any run instead of failing every run.
void check_value(const cosim::System& system, const std::string& setting, const std::string& what) {
    if (system.is_system_parameter(setting_variable(setting))) return;  // checked as the system was built
    const cosim::Setting s = cosim::parse_setting(setting, true);
    const auto& c = system.components()[system.component_index(s.component)];
    const auto* v = c.description().find_variable(s.variable);
    if (!v) return;  // check_variable names it
    try {
        cosim::typed_value(c.description(), *v, s, what);
    } catch (const std::exception& e) {
        throw CampaignError(what + ": " + e.what());
    }
}

// A system parameter's value as the run starts: as the .ssd, a parameter file or --set give it, else the
// start value of the first component parameter it feeds (a system parameter without a value feeds nothing).
std::optional<std::string> system_parameter_value(const cosim::System& system, const std::string& name) {
    const auto& parameters = system.description().parameters;
    for (std::size_t i = 0; i < parameters.size(); ++i)
        if (parameters[i].name == name && !system.system_parameter_values()[i].value.empty())
            return system.system_parameter_values()[i].value;
    for (const auto& f : system.description().feeds)
        if (f.parameter == name) return system.initial_value(system.component_index(f.component), f.variable);
    return std::nullopt;
}

}  // namespace

CampaignSetup prepare(CampaignSpec spec, const std::vector<std::filesystem::path>& fmu_dirs,
                      const std::vector<std::string>& extra_settings) {
    CampaignSetup s;
    s.description = cosim::read_system_description(spec.system);
    s.options.fmu_dirs = spec.fmu_dirs;
    s.options.fmu_dirs.insert(s.options.fmu_dirs.end(), fmu_dirs.begin(), fmu_dirs.end());
    s.options.parameter_files = spec.parameter_files;
    s.options.settings = spec.settings;
    for (const auto& setting : extra_settings) {
        for (const auto& d : spec.draws)
            for (const auto& v : drawn_variables(d))
                if (setting_variable(setting) == v)
                    throw CampaignError("--set " + setting + ": '" + v +
                                        "' is drawn by the spec; remove the draw or the --set");
        // A case's own settings and draws come after --set: they would silently win.
        for (const auto& c : spec.cases) {
            for (const auto& d : c.draws)
                for (const auto& v : drawn_variables(d))
                    if (setting_variable(setting) == v)
                        throw CampaignError("--set " + setting + ": '" + v + "' is drawn by case '" + c.name +
                                            "'; remove the draw or the --set");
            for (const auto& own : c.settings)
                if (setting_variable(setting) == setting_variable(own))
                    throw CampaignError("--set " + setting + ": '" + setting_variable(own) + "' is set by case '" +
                                        c.name + "'; change the case or drop the --set");
        }
        s.options.settings.push_back(setting);
    }
    s.options.tolerance = spec.tolerance;

    // The system checks every setting's name and value as it is built: said as the spec's [set] (or --set).
    const cosim::System system = [&] {
        try {
            return cosim::System(s.description, s.options);
        } catch (const cosim::SettingError& e) {
            throw CampaignError(std::string("[set] or --set: ") + e.what());
        }
    }();
    // The scenario's element set the epoch and orbit draws move or replace: as the system (and [set]) give it.
    read_scenario_base(spec, [&](const std::string& name) -> std::optional<std::string> {
        if (system.is_system_parameter(name)) return system_parameter_value(system, name);
        const auto split = cosim::split_variable_name(name);
        if (!split) return std::nullopt;
        // "tle_elements.tle_line1": the text set of a component the system parameter set feeds.
        if (system.is_system_parameter(split->component + "[1]")) {
            for (const auto& f : system.description().feeds)
                if (f.parameter == split->component + "[1]")
                    if (auto text = system.initial_value(system.component_index(f.component), split->variable);
                        text && !text->empty())
                        return text;
            return std::nullopt;
        }
        return system.initial_value(system.component_index(split->component), split->variable);
    });
    for (const auto& setting : s.options.settings) check_variable(system, setting_variable(setting), "[set]");
    for (const auto& d : spec.draws)
        for (const auto& v : drawn_variables(d)) check_variable(system, v, "draw of " + d.target);
    for (const auto& setting : s.options.settings) check_value(system, setting, "[set] " + setting);
    // Every value a list draws, and one run's draws of every other kind (their type does not vary).
    for (const auto& d : spec.draws)
        for (const auto& value : d.values) check_value(system, d.target + "=" + value.text, "draw of " + d.target);
    for (const auto& setting : draw_run(spec, 0).settings) check_value(system, setting, "draw " + setting);
    const MetricObserver check_metrics(spec.metrics, system);
    // Each case: its settings and draws (names and values, one run's worth), its onset and expectations.
    for (long k = 0; k < static_cast<long>(spec.cases.size()); ++k) {
        const Case& c = spec.cases[static_cast<std::size_t>(k)];
        const std::string what = "case '" + c.name + "'";
        for (const auto& setting : c.settings) check_variable(system, setting_variable(setting), what + " [case.set]");
        for (const auto& d : c.draws)
            for (const auto& v : drawn_variables(d)) check_variable(system, v, what + ": draw of " + d.target);
        for (const auto& d : c.draws)
            for (const auto& value : d.values)
                check_value(system, d.target + "=" + value.text, what + ": draw of " + d.target);
        for (const auto& setting : draw_run(spec, k).settings) check_value(system, setting, what);
        const MetricObserver check_case(spec.metrics, system, &c);
    }
    analysis::check_couplings(system, false, std::cerr);  // the blocks agree before any draw (each run checks its own)

    s.start_time = s.description.start_time.value_or(0.0);
    const auto stop = spec.stop_time ? spec.stop_time : analysis::default_stop_time(system);  // as `cosim run`
    if (!stop)
        throw CampaignError(spec.system.string() + " has no DefaultExperiment stopTime: give stop_time in the spec");
    s.stop_time = *stop;
    const cosim::RunDefaults defaults = cosim::run_defaults(system, s.start_time, s.stop_time);  // as `cosim run`
    s.output_interval = spec.output_interval.value_or(defaults.output_interval);
    cosim::ExecutionOptions run;
    run.start_time = s.start_time;
    run.stop_time = s.stop_time;
    run.output_interval = s.output_interval;
    cosim::check_run_span(run, std::nullopt, false);  // the checks of `cosim run`
    s.tolerance = spec.tolerance.value_or(defaults.tolerance);
    // Run k takes grid combination k mod the grid's size: fewer runs leave combinations out, a count that is
    // no multiple gives some combinations one run more. Said, not refused (a short trial is legitimate).
    if (const long grid = grid_size(spec); grid > 1 && spec.runs % grid != 0)
        std::cerr << "cosim campaign: warning: " << spec.runs << " runs do not cover the "
                  << (spec.cases.empty() ? "grid's " : "cases' and grid's ") << grid << " combinations evenly"
                  << (spec.runs < grid ? " (" + std::to_string(grid - spec.runs) + " combinations are never run)"
                                       : std::string(" (some run once more than others)"))
                  << "; give a multiple of " << grid << " in 'runs' or --runs\n";
    // What the system declares it reached: recorded in every run, beside the spec's metrics.
    if (s.description.measures) {
        analysis::check_measure_names(s.description.measures->report, spec.system.string());
        spec.measures = true;
        spec.measure_report = s.description.measures->report;
        spec.measures_converged_after = s.description.measures->converged_after;
    }
    check_aim_columns(spec);
    s.spec = std::move(spec);
    return s;
}

RunResult run_one(const CampaignSetup& setup, long index, const std::optional<std::filesystem::path>& full_csv) {
    const auto started = std::chrono::steady_clock::now();
    RunResult r;
    r.index = index;
    const RunDraws draws = draw_run(setup.spec, index);
    r.draw_cells = draws.cells;
    try {
        cosim::SystemOptions options = setup.options;
        options.settings.insert(options.settings.end(), draws.settings.begin(), draws.settings.end());
        cosim::System system(setup.description, options);
        analysis::check_couplings(system, false, std::cerr);  // a draw may make them disagree: this run fails
        const auto which = case_of(setup.spec, index);
        MetricObserver metrics(setup.spec.metrics, system, which ? &setup.spec.cases[*which] : nullptr);
        cosim::InterruptCheck interrupt;  // a signal ends the campaign, not just this run
        std::vector<cosim::Observer*> observers = {&interrupt, &metrics};
        std::unique_ptr<analysis::MeasureRecorder> measures;
        if (setup.spec.measures) {
            measures = std::make_unique<analysis::MeasureRecorder>(system);
            observers.push_back(measures.get());
        }
        std::unique_ptr<cosim::CsvWriter> csv;
        if (full_csv) {
            csv = std::make_unique<cosim::CsvWriter>(*full_csv, system, std::vector<std::string>{});
            observers.push_back(csv.get());
        }
        cosim::ExecutionOptions ex;
        ex.start_time = setup.start_time;
        ex.stop_time = setup.stop_time;
        ex.output_interval = setup.output_interval;
        ex.relative_tolerance = setup.tolerance;
        const auto stats = cosim::Execution(system, ex).run(observers);
        r.metric_cells = metrics.cells();
        if (measures) {
            analysis::MeasureOptions mo;
            mo.converged_after = setup.spec.measures_converged_after;
            // The same text as the metrics' cells: round-trip numbers, "nan" where the run has none.
            for (const double v :
                 analysis::measure_values(analysis::measure_run(measures->table(), mo), setup.spec.measure_report))
                r.metric_cells.push_back(cosim::format_real(v));
        }
        r.status = stats.terminated_early ? "stopped" : "ok";
        if (stats.terminated_early)
            r.message = "a component ended the run at t = " + std::to_string(stats.simulated_time) + " s";
    } catch (const cosim::Interrupted&) {
        throw;
    } catch (const std::exception& e) {
        if (cosim::interrupt_signal()) throw;  // a load cancelled by the signal is not the run's failure
        r.status = "failed";
        r.message = e.what();
        r.metric_cells.assign(metric_columns(setup.spec).size(), "");
    }
    r.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return r;
}

}  // namespace campaign
