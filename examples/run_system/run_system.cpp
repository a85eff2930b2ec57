// A program outside the toolkit's tree that runs a system of FMUs on the installed engine (pvatt::engine):
// it reads an .ssd, runs it from its start to STOP_TIME and prints one variable's value at the end.
//
//   run_system SYSTEM.ssd STOP_TIME COMPONENT.VARIABLE [FMU_DIR]
#include <cstdio>
#include <exception>
#include <string>

#include "engine/execution.hpp"
#include "engine/system_description.hpp"

namespace {

// Keeps the newest value of one Real variable at each output point.
struct LastValue : cosim::Observer {
    cosim::OutputColumn column;
    double value = 0.0;
    explicit LastValue(const cosim::OutputColumn& c) : column(c) {}
    void sample(double, cosim::System& system) override {
        value = system.components()[column.component].instance->get_real(column.variable->value_reference);
    }
};

}  // namespace

int main(int argc, char** argv) {
    if (argc < 4 || argc > 5) {
        std::fprintf(stderr, "usage: %s SYSTEM.ssd STOP_TIME COMPONENT.VARIABLE [FMU_DIR]\n", argv[0]);
        return 2;
    }
    try {
        cosim::SystemOptions options;
        if (argc == 5) options.fmu_dirs.emplace_back(argv[4]);
        cosim::System system(cosim::read_system_description(argv[1]), options);
        LastValue last(cosim::output_columns(system, {argv[3]}).at(0));
        cosim::ExecutionOptions run;
        run.stop_time = std::stod(argv[2]);
        run.output_interval = run.stop_time / 100.0;
        cosim::Execution(system, run).run({&last});
        std::printf("%s = %.17g\n", argv[3], last.value);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "run_system: %s\n", e.what());
        return 1;
    }
}
