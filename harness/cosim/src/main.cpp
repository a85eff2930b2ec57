// cosim: the co-simulation master's command line. Every failure ends here as one clear line on
// stderr and a non-zero exit code.
#include <CLI/CLI.hpp>

#include <iostream>

#include "cosim_error.hpp"
#include "fmi_loader/loader_error.hpp"
#include "info_command.hpp"
#include "simulate_command.hpp"

int main(int argc, char** argv) {
    CLI::App app{"cosim: FMI 2.0 co-simulation master"};
    app.require_subcommand(1);

    std::string info_path;
    auto* info = app.add_subcommand("info", "Print an FMU's interface: kinds, variables, causality, unit, start");
    info->add_option("fmu", info_path, "The .fmu file")->required();

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

    CLI11_PARSE(app, argc, argv);
    try {
        if (*info) cosim::print_info(info_path, std::cout);
        if (*simulate) {
            sim.fmu = fmu_path;
            if (!csv_path.empty()) sim.csv = csv_path;
            cosim::simulate(sim, std::cout);
        }
        return 0;
    } catch (const fmi_loader::LoaderError& e) {
        std::cerr << "cosim: " << e.what() << "\n";
        return 3;
    } catch (const std::exception& e) {
        std::cerr << "cosim: " << e.what() << "\n";
        return 1;
    }
}
