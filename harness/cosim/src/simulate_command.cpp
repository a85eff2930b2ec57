#include "simulate_command.hpp"

#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "engine/cosim_error.hpp"
#include "engine/execution.hpp"
#include "engine/fmi3_instance.hpp"
#include "engine/import_cache.hpp"
#include "engine/interrupt.hpp"
#include "engine/name_hint.hpp"
#include "engine/output_file.hpp"
#include "engine/run_defaults.hpp"
#include "engine/value_text.hpp"

namespace cosim {

namespace {

// The table a person reads on a terminal: fixed-width columns, Reals to 8 significant digits.
class TableWriter : public Observer {
public:
    TableWriter(std::ostream& out, const System& system, const std::vector<std::string>& columns)
        : out_(out), columns_(output_columns(system, columns)) {}
    void sample(double t, System& system) override {
        if (!headed_) row("time", [&](const OutputColumn& c) { return c.variable->name; });
        headed_ = true;
        row(format_real(t), [&](const OutputColumn& c) {
            auto& instance = *system.components()[c.component].instance;
            if (c.variable->type != fmi_loader::VariableType::real) return instance.get_as_text(*c.variable);
            std::ostringstream cell;
            cell << std::setprecision(8) << instance.get_real(c.variable->value_reference);
            return cell.str();
        });
    }

private:
    template <class Cell>
    void row(const std::string& first, Cell&& cell) {
        out_ << std::left << std::setw(10) << first;
        for (const auto& c : columns_) out_ << std::setw(16) << cell(c);
        out_ << "\n";
        if (!out_) throw CosimError("writing standard output failed: " + io_reason());
    }
    std::ostream& out_;
    std::vector<OutputColumn> columns_;
    bool headed_ = false;  // the header goes out with the first row: a run refused at its start prints nothing
};

}  // namespace

void simulate(const SimulateOptions& options, std::ostream& out) {
    if (options.csv) refuse_overwriting_inputs("--output", *options.csv, {options.fmu});
    const auto fmu = import_fmu(options.fmu);  // the system below takes the same import
    const auto& md = fmu->description();
    if (md.is_fmi3()) refuse_unsupported_fmi3(md, options.fmu.string());  // names Scheduled Execution, clocks
    if (!md.co_simulation) throw CosimError(options.fmu.string() + " has no CoSimulation interface");
    const auto ex = md.default_experiment.value_or(fmi_loader::DefaultExperiment{});
    const double start = ex.start_time.value_or(0.0);
    const double stop = options.stop_time.value_or(ex.stop_time.value_or(start + 1.0));
    // The FMU's step when it fits the run, else a row every hundredth of it (the rule of cosim run).
    std::optional<double> shortened_from;
    const double h = options.output_interval.value_or(
        interval_within_span(ex.step_size.value_or((stop - start) / 500.0), stop - start, shortened_from));
    if (shortened_from)
        std::cerr << "cosim: the output interval " << format_real(*shortened_from) << " s of "
                  << options.fmu.filename().string() << " is longer than the run (" << format_real(stop - start)
                  << " s): a row every " << format_real(h) << " s instead (--output-interval to choose)\n";
    ExecutionOptions run;
    run.start_time = start;
    run.stop_time = stop;
    run.output_interval = h;
    check_run_span(run, std::nullopt, false);

    // A system of one component, named after its model (a name with a dot would read as component.variable).
    SystemDescription description;
    description.file = options.fmu;
    description.name = md.model_name;
    const std::string name = md.model_name.find('.') == std::string::npos ? md.model_name : "fmu";
    ComponentDescription component;
    component.name = name;
    component.source = std::filesystem::absolute(options.fmu).string();
    component.execution = ExecutionHint{true, h};
    description.components.push_back(std::move(component));
    SystemOptions system_options;
    system_options.tolerance = options.tolerance ? options.tolerance : ex.tolerance;
    system_options.fmi3_event_mode = options.fmi3_event_mode;
    for (const auto& setting : options.settings) system_options.settings.push_back(name + "." + setting);
    System system(description, system_options);
    std::vector<std::string> columns;
    for (const auto& c : options.columns) columns.push_back(name + "." + c);

    InterruptCheck interrupt;
    std::unique_ptr<Observer> writer;
    if (options.csv)
        writer = std::make_unique<CsvWriter>(*options.csv, system, columns, false);
    else
        writer = std::make_unique<TableWriter>(out, system, columns);
    Execution(system, run).run({&interrupt, writer.get()});
    if (auto* csv = dynamic_cast<CsvWriter*>(writer.get())) csv->close();
}

}  // namespace cosim
