// Drives attitude_estimator.fmu's block through the runtime's C++ layer (fmu::ModelRunner, fmu::CsSolver),
// without the FMI C API: what the block tests share.
#pragma once

#include <memory>

#include "attitude_estimator/estimator_block.hpp"
#include "fmu/cs_solver.hpp"
#include "fmu/model_runner.hpp"

namespace attitude_estimator::test {

struct Simulation {
    fmu::ModelRunner runner{std::make_unique<EstimatorBlock>()};
    std::unique_ptr<fmu::CsSolver> solver;

    EstimatorData& data() { return static_cast<EstimatorBlock&>(runner.model()).data(); }
    void start(double t0 = 0.0) {  // what setting up the experiment and leaving initialization mode do
        runner.set_time(t0);
        runner.set_initializing(true);
        runner.ensure_evaluated();
        runner.model().validate();
        runner.set_initializing(false);
        solver = std::make_unique<fmu::CsSolver>(runner, 1e-8);
        runner.event_iteration();
    }
    void inputs_changed() {
        runner.mark_changed();
        if (solver) solver->invalidate();
    }
    void advance_to(double t) {
        solver->invalidate();
        solver->advance(t);
        runner.ensure_evaluated();
    }
};

}  // namespace attitude_estimator::test
