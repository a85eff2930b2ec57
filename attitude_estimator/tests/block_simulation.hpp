// Drives attitude_estimator.fmu's block through the runtime's C++ layer (fmu::ModelRunner, fmu::CsSolver),
// without the FMI C API: what the block tests share.
#pragma once

#include <memory>

#include "attitude_estimator/estimator_block.hpp"
#include "fmu/cs_solver.hpp"
#include "fmu/model_runner.hpp"
#include "fmu/testing/block_driver.hpp"

namespace attitude_estimator::test {

// The runtime's shared driver (the FMU's initialization path) at the tolerance these tests use.
using Simulation = fmu::testing::BlockDriver<EstimatorBlock>;

}  // namespace attitude_estimator::test
