// Cost of the FMU layer: one block evaluation through the runtime's ModelRunner (what every
// fmi2GetDerivatives / output read after a change costs), against the bare core, and the cost of
// building the core's Environment that the block's parameter-keyed cache saves on each evaluation.
#include <benchmark/benchmark.h>

#include <memory>
#include <string_view>
#include <vector>

#include "environment/environment_block.hpp"
#include "fmu/model_runner.hpp"

namespace {

void run_block(benchmark::State& state, environment::AttitudeMode mode, bool albedo) {
    fmu::ModelRunner runner{std::make_unique<environment::EnvironmentBlock>()};
    auto& d = static_cast<environment::EnvironmentBlock&>(runner.model()).data();
    d.attitude_mode = mode;
    d.albedo_enabled = albedo;
    runner.enter_initialization();
    runner.exit_initialization();
    std::vector<double> x(runner.state_count()), dx(x.size());
    runner.get_states(x);
    double t = 100.0;
    for (auto _ : state) {
        runner.set_time(t);  // marks the outputs stale: the next read evaluates
        runner.get_derivatives(dx);
        benchmark::DoNotOptimize(dx.data());
        t += 1e-3;
    }
}

void BM_BlockSpinWithAlbedo(benchmark::State& state) {
    run_block(state, environment::AttitudeMode::spin, true);
}
void BM_BlockSpinNoAlbedo(benchmark::State& state) {
    run_block(state, environment::AttitudeMode::spin, false);
}
void BM_BlockRigidBodyWithAlbedo(benchmark::State& state) {
    run_block(state, environment::AttitudeMode::rigid_body, true);
}
void BM_BlockRigidBodyNoAlbedo(benchmark::State& state) {
    run_block(state, environment::AttitudeMode::rigid_body, false);
}
BENCHMARK(BM_BlockSpinWithAlbedo);
BENCHMARK(BM_BlockSpinNoAlbedo);
BENCHMARK(BM_BlockRigidBodyWithAlbedo);
BENCHMARK(BM_BlockRigidBodyNoAlbedo);

void BM_CoreConstruction(benchmark::State& state) {
    const environment::EnvironmentParams p = environment::environment_params(environment::EnvironmentData{});
    for (auto _ : state) {
        environment::Environment env(p);
        benchmark::DoNotOptimize(&env);
    }
}
BENCHMARK(BM_CoreConstruction);

}  // namespace

BENCHMARK_MAIN();
