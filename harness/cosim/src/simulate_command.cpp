#include "simulate_command.hpp"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "engine/cosim_error.hpp"
#include "engine/csv_table.hpp"
#include "engine/fmi2_instance.hpp"
#include "engine/interrupt.hpp"
#include "engine/name_hint.hpp"
#include "engine/output_file.hpp"
#include "engine/value_text.hpp"

namespace cosim {

void simulate(const SimulateOptions& options, std::ostream& out) {
    if (options.csv) refuse_overwriting_inputs("--output", *options.csv, {options.fmu});
    fmi_loader::Fmu fmu(options.fmu);
    const auto& md = fmu.description();
    if (!md.co_simulation) throw CosimError(options.fmu.string() + " has no CoSimulation interface");
    const auto ex = md.default_experiment.value_or(fmi_loader::DefaultExperiment{});
    const double start = ex.start_time.value_or(0.0);
    const double stop = options.stop_time.value_or(ex.stop_time.value_or(start + 1.0));
    const double h = options.output_interval.value_or(ex.step_size.value_or((stop - start) / 500.0));
    if (!std::isfinite(start) || !std::isfinite(stop) || !(stop > start) || !std::isfinite(h) || !(h > 0.0))
        throw CosimError(
            "the stop time must be finite and exceed the start time, and the interval be positive and finite");
    if (h > stop - start)
        throw CosimError("--output-interval " + format_real(h) + " s is longer than the run (" +
                         format_real(stop - start) + " s)");
    if ((stop - start) / h > 1e8)
        throw CosimError("--output-interval " + format_real(h) + " s makes more than the limit of 1e8 rows");

    std::vector<const fmi_loader::ScalarVariable*> columns;
    if (options.columns.empty()) {
        for (const auto& v : md.model_variables)
            if (v.causality == fmi_loader::Causality::output) columns.push_back(&v);
    } else {
        for (const auto& name : options.columns) {
            const auto* v = md.find_variable(name);
            if (!v) throw CosimError(unknown_variable_message(md, options.fmu.string(), name));
            columns.push_back(v);
        }
    }

    Fmi2Instance instance(fmu, fmi_loader::FmuKind::co_simulation, md.model_name);
    instance.setup_experiment(start, stop, options.tolerance ? options.tolerance : ex.tolerance);
    for (const auto& setting : options.settings) instance.apply(parse_setting(setting, false));
    instance.enter_initialization_mode();
    instance.exit_initialization_mode();

    std::ofstream csv_file;
    if (options.csv) {
        csv_file.open(*options.csv);
        if (!csv_file) throw CosimError("cannot write " + options.csv->string() + ": " + io_reason());
    }
    const bool as_csv = options.csv.has_value();
    std::ostream& sink = as_csv ? csv_file : out;
    const int width = 16;
    auto row = [&](const std::string& first, auto&& cell) {
        if (as_csv) {
            sink << first;
            for (std::size_t i = 0; i < columns.size(); ++i) sink << "," << csv_field(cell(i));
        } else {
            sink << std::left << std::setw(10) << first;
            for (std::size_t i = 0; i < columns.size(); ++i) sink << std::setw(width) << cell(i);
        }
        sink << "\n";
        if (!sink)
            throw CosimError("writing " + (as_csv ? options.csv->string() : std::string("standard output")) +
                             " failed: " + io_reason());
        throw_if_interrupted();
    };
    row("time", [&](std::size_t i) { return columns[i]->name; });
    const auto steps = static_cast<long>(std::llround((stop - start) / h));
    for (long k = 0;; ++k) {
        const double t = start + k * h;  // from the step count, so that times never drift
        row(format_real(t), [&](std::size_t i) {
            const auto& v = *columns[i];
            if (as_csv || v.type != fmi_loader::VariableType::real) return instance.get_as_text(v);
            std::ostringstream cell;  // a table is read by a person: 8 significant digits
            cell << std::setprecision(8) << instance.get_real(v.value_reference);
            return cell.str();
        });
        if (k >= steps) break;
        instance.do_step(t, std::min(h, stop - t));
    }
    instance.terminate();
    if (as_csv) {
        csv_file.close();
        if (csv_file.fail()) throw CosimError("closing " + options.csv->string() + " failed: " + io_reason());
    }
}

}  // namespace cosim
