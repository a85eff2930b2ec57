// Drives one block as the FMU's Co-Simulation instance does, without the C API: the same
// initialization path (ModelRunner::enter_initialization / exit_initialization), the same solver and
// the same event iteration at the start. Every block's tests use it, so a test cannot pass on a path
// the real FMU never takes.
//
// Parameters and inputs are written through data(); say so with parameters_changed() (the block
// reconfigures) or inputs_changed() after start().
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "fmu/cs_solver.hpp"
#include "fmu/errors.hpp"
#include "fmu/model_runner.hpp"
#include "fmu/value_access.hpp"

namespace fmu::testing {

template <class BlockT>
class BlockDriver {
public:
    using Data = typename BlockT::Data;

    explicit BlockDriver(double tolerance = 1e-8) : tolerance_(tolerance) {}

    ModelRunner runner{std::make_unique<BlockT>()};
    std::unique_ptr<CsSolver> solver;

    BlockT& block() { return static_cast<BlockT&>(runner.model()); }
    Data& data() { return block().data(); }

    // fmi2SetupExperiment, fmi2EnterInitializationMode, fmi2ExitInitializationMode, as a Co-Simulation
    // instance: the discrete state settled at t0, outputs current.
    void start(double t0 = 0.0) {
        enter_initialization(t0);
        exit_initialization();
    }
    // The two halves, for tests that set or read values in initialization mode.
    void enter_initialization(double t0 = 0.0) {
        runner.set_time(t0);
        runner.enter_initialization();
    }
    void exit_initialization() {
        runner.exit_initialization();
        solver = std::make_unique<CsSolver>(runner, tolerance_);
        runner.event_iteration();
        runner.ensure_evaluated();
    }

    // A choice set by its item name, as a host does (throws fmu::Error for a name that is no item).
    void set_choice(std::string_view name, std::string_view item) {
        const Variable& v = runner.table().by_name(name);
        const EnumerationItem* found = v.type == ValueType::Enumeration ? v.item_named(item) : nullptr;
        if (!found) throw Error(std::string(name) + " has no item '" + std::string(item) + "'");
        write_integer(runner.model().bytes(), v, found->value);
        parameters_changed();
    }

    void inputs_changed() {
        runner.mark_changed();
        if (solver) solver->invalidate();
    }
    void parameters_changed() {
        runner.parameters_changed();
        if (solver) solver->invalidate();
    }
    // One communication step to t (inputs may have changed at its start), outputs current.
    void advance_to(double t) {
        inputs_changed();
        solver->advance(t);
        runner.ensure_evaluated();
    }

private:
    double tolerance_;
};

}  // namespace fmu::testing
