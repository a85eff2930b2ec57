// cosim: the co-simulation master's command line. Every failure ends here as one clear line on
// stderr and a non-zero exit code.
#include <CLI/CLI.hpp>

#include <cerrno>
#include <iostream>

#include "analysis/result_figures.hpp"
#include "campaign_command.hpp"
#include "engine/cosim_error.hpp"
#include "engine/interrupt.hpp"
#include "engine/ssp_archive.hpp"
#include "fmi_loader/loader_error.hpp"
#include "info_command.hpp"
#include "run_command.hpp"
#include "simulate_command.hpp"
#include "system_diagram.hpp"

int main(int argc, char** argv) {
    CLI::App app{"cosim: FMI 2.0 co-simulation master"};
    app.set_version_flag("--version", std::string("cosim ") + PVATT_VERSION);  // project(VERSION) in CMake
    app.require_subcommand(1);

    std::string info_path;
    auto* info = app.add_subcommand(
        "info", "Print an FMU's interface (kinds, variables, causality, unit, start) or a system's components");
    info->add_option("fmu", info_path, "The .fmu file, or a system (.ssd, .ssp)")->required();
    std::string diagram_out;
    info->add_option("--diagram", diagram_out,
                     "A system's components and connections as a picture: writes OUT.dot and OUT.svg (Graphviz)");

    std::string pack_ssd, pack_out;
    std::vector<std::string> pack_fmu_dirs;
    auto* pack = app.add_subcommand("pack", "Pack a system (.ssd) and its FMUs into an SSP archive (.ssp)");
    pack->add_option("ssd", pack_ssd, "The system structure description")->required();
    pack->add_option("-o,--output", pack_out, "The .ssp to write")->required();
    pack->add_option("--fmu-dir", pack_fmu_dirs, "Where to look for FMUs not found beside the .ssd")
        ->default_val(std::vector<std::string>{PVATT_DEFAULT_FMU_DIR});
    cosim::PackOptions pack_options;
    pack->add_option("--oms-step", pack_options.oms_step,
                     "Fixed step written for OMSimulator's co-simulation master (default: the smallest "
                     "Co-Simulation communicationStep of the system, else the FMUs' smallest stepSize)")
        ->check(CLI::PositiveNumber);

    cosim::SimulateOptions sim;
    std::string fmu_path, csv_path;
    auto* simulate = app.add_subcommand("simulate", "Run one FMU alone in Co-Simulation and print or save its outputs");
    simulate->add_option("fmu", fmu_path, "The .fmu file")->required();
    simulate->add_option("--stop-time", sim.stop_time, "Stop time in s (default: the FMU's DefaultExperiment)");
    simulate->add_option("--output-interval", sim.output_interval, "Communication and output interval in s");
    simulate->add_option("--tolerance", sim.tolerance, "Relative tolerance of the FMU's integrator");
    simulate->add_option("--set", sim.settings, "name=value before initialization (repeatable)");
    simulate->add_option("--columns", sim.columns, "Variables to report (default: every output)")->delimiter(',');
    simulate->add_option("--output", csv_path, "Write CSV to this file instead of printing a table");
    simulate->add_flag("!--no-event-mode", sim.fmi3_event_mode,
                       "FMI 3.0 Co-Simulation: do not use event mode (the FMU handles its events inside fmi3DoStep)");

    cosim::RunOptions run_options;
    std::string ssd_path, run_csv;
    std::vector<std::string> fmu_dirs;
    auto* run = app.add_subcommand("run", "Run a system described in SSP (.ssd, or an .ssp archive)");
    run->add_option("ssd", ssd_path, "The system structure description (.ssd) or SSP archive (.ssp)")->required();
    run->add_option("--stop-time", run_options.stop_time, "Stop time in s (default: the .ssd's DefaultExperiment)");
    run->add_option("--output", run_csv, "CSV results file");
    run->add_option("--output-interval", run_options.output_interval,
                    "Output interval in s (default: the .ssd's, else the FMUs' smallest DefaultExperiment stepSize "
                    "but no finer than a thousandth of the run)");
    run->add_option(
        "--step", run_options.communication_step,
        "Communication step of every Co-Simulation component (default: the .ssd's, else the output interval)");
    run->add_option("--max-step", run_options.max_step,
                    "Longest step of the Model Exchange integrator in s (default: the .ssd's, else none)")
        ->check(CLI::PositiveNumber);
    run->add_option("--tolerance", run_options.tolerance, "Relative tolerance (default: the FMUs' smallest)");
    run->add_option("--set", run_options.system.settings,
                    "component.variable=value, or NAME=value for a system parameter (cosim info lists them), before "
                    "initialization (repeatable; after every --parameters file)");
    std::vector<std::string> run_parameters;
    run->add_option("--parameters", run_parameters,
                    "An SSP parameter set (.ssv): system parameters and component.variable values (repeatable, "
                    "later files win)")
        ->check(CLI::ExistingFile);
    run->add_option("--cs", run_options.system.co_simulation, "Run this component through its Co-Simulation interface");
    run->add_option("--fmu-dir", fmu_dirs, "Where to look for FMUs not found beside the .ssd")
        ->default_val(std::vector<std::string>{PVATT_DEFAULT_FMU_DIR});
    run->add_option("--columns", run_options.columns, "component.variable columns of the CSV (default: every output)")
        ->delimiter(',');
    run->add_option("--bridge-port", run_options.system.bridge_port,
                    "UDP port of every hardware-bridged component (replaces the .ssd's)")
        ->check(CLI::Range(0, 65535));
    run->add_option("--bridge-device", run_options.system.bridge_device,
                    "Serial device of every serial hardware bridge (replaces the .ssd's; scripts/pil.sh passes QEMU's "
                    "pseudo-terminal)");
    run->add_flag("!--no-event-mode", run_options.system.fmi3_event_mode,
                  "FMI 3.0 Co-Simulation components: do not use event mode");
    run->add_flag("--realtime", run_options.realtime, "Pace simulated time to the wall clock");
    run->add_option("--realtime-tolerance", run_options.realtime_tolerance,
                    "With --realtime: how far behind its wall time (s) an output point may be before it counts as late")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
    run->add_flag("--event-rows", run_options.event_rows, "Add CSV rows just before and after each event");
    run->add_flag("--reference", run_options.reference,
                  "The reference execution: every component as Model Exchange, every event through every component "
                  "with an integrator restart, every output point a stop (slow; to check the fast path against)");
    run->add_flag("--allow-mismatch", run_options.allow_mismatch,
                  "Run a system whose blocks disagree on a shared fact (the estimator's angular response or orbit "
                  "altitude against the plant's and the truth's), with a warning instead of a refusal");
    run->add_flag(
        "--force", run_options.force,
        "Run even with more than 1e8 output or communication points, or a CSV larger than the free disk space");

    std::string plot_csv, plot_dir = "figures";
    auto* plot = app.add_subcommand("plot", "Draw the standard figures of a results CSV as PNG files (gnuplot)");
    plot->add_option("csv", plot_csv, "Results CSV written by cosim run")->required();
    plot->add_option("--out-dir", plot_dir, "Folder for the PNG files")->capture_default_str();
    analysis::PlotOptions plot_options;
    plot->add_option("--format", plot_options.format, "png or svg")->capture_default_str();
    plot->add_option("--columns", plot_options.columns,
                     "Also draw these CSV columns against time in one figure (columns.png), e.g. est.q_filt[1]");
    plot->add_option("--derived", plot_options.derived,
                     "Write the derived signals (each estimate's attitude error: angle, roll, pitch, yaw; the "
                     "filter's normalized error; the sun vector error) to this CSV");

    campaign::CampaignOptions campaign_options;
    std::string spec_path, campaign_output;
    std::vector<std::string> campaign_fmu_dirs;
    auto* campaign =
        app.add_subcommand("campaign", "Run a Monte-Carlo campaign of a system (harness/campaign/README.md)");
    campaign->add_option("spec", spec_path, "The campaign spec (TOML)")->required();
    campaign->add_option("--runs", campaign_options.runs, "Number of runs (replaces the spec's)");
    campaign->add_option("--stop-time", campaign_options.stop_time, "Stop time in s (replaces the spec's)");
    campaign->add_option("--output", campaign_output, "Folder of the results table, summary and figures");
    campaign->add_option("--fmu-dir", campaign_fmu_dirs, "Where to look for FMUs not found beside the .ssd")
        ->default_val(std::vector<std::string>{PVATT_DEFAULT_FMU_DIR});
    campaign->add_option("--set", campaign_options.settings,
                         "component.variable=value, or NAME=value for a system parameter, for every run (repeatable)");
    campaign->add_option("--run", campaign_options.replay, "Replay this run alone, writing its full CSV");
    campaign->add_flag("--resume", campaign_options.resume,
                       "Continue the campaign of the results table in the output folder");
    campaign->add_flag("!--no-figures", campaign_options.figures, "Skip the PNG figures");
    campaign->add_flag("--progress", campaign_options.progress_lines,
                       "Progress as log lines every 10 s when stderr is not a terminal (mpirun, batch jobs)");

    CLI11_PARSE(app, argc, argv);
    cosim::install_interrupt_handlers();
    cosim::use_private_temp_directory();
    try {
        if (*info && !diagram_out.empty()) {
            for (const auto& f : cosim::write_system_diagram(info_path, diagram_out)) std::cout << f.string() << "\n";
        } else if (*info) {
            cosim::print_info(info_path, std::cout);
        }
        if (*pack) {
            pack_options.fmu_dirs.assign(pack_fmu_dirs.begin(), pack_fmu_dirs.end());
            cosim::pack_system(pack_ssd, pack_out, pack_options, std::cout);
        }
        if (*campaign) {
            campaign_options.spec = spec_path;
            if (!campaign_output.empty()) campaign_options.output = campaign_output;
            for (const auto& d : campaign_fmu_dirs) campaign_options.fmu_dirs.emplace_back(d);
            return campaign::run_campaign(campaign_options, std::cout);
        }
        if (*run) {
            run_options.ssd = ssd_path;
            if (!run_csv.empty()) run_options.csv = run_csv;
            for (const auto& d : fmu_dirs) run_options.system.fmu_dirs.emplace_back(d);
            for (const auto& f : run_parameters) run_options.system.parameter_files.emplace_back(f);
            cosim::run_system(run_options, std::cout);
        }
        if (*plot) {
            for (const auto& png : analysis::plot_results(plot_csv, plot_dir, std::cerr, plot_options))
                std::cout << png.string() << "\n";
        }
        if (*simulate) {
            sim.fmu = fmu_path;
            if (!csv_path.empty()) sim.csv = csv_path;
            cosim::simulate(sim, std::cout);
        }
        // Output to a pipe or a full disk fails at the latest here: exit 0 only when it all got out.
        errno = 0;
        std::cout.flush();
        if (!std::cout) {
            std::cerr << "cosim: writing standard output failed: " << cosim::io_reason() << "\n";
            return 1;
        }
        return 0;
    } catch (const cosim::Interrupted& e) {
        std::cout.flush();
        std::cerr << "cosim: " << e.what() << "\n";
        return 128 + e.signal();
    } catch (const fmi_loader::LoaderError& e) {
        if (e.code() == fmi_loader::LoaderErrc::cancelled && cosim::interrupt_signal()) {
            std::cerr << "cosim: " << cosim::Interrupted(cosim::interrupt_signal()).what() << " while loading\n";
            return 128 + cosim::interrupt_signal();
        }
        std::cerr << "cosim: " << e.what() << "\n";
        return 3;
    } catch (const std::exception& e) {
        std::cerr << "cosim: " << e.what() << "\n";
        return 1;
    }
}
