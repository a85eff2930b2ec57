// Speed of the calls an integrator makes most: the right-hand side (six implicit panel solves),
// the outputs (eighteen), and one panel solve.
#include <benchmark/benchmark.h>

#include "ssr_plant/plant.hpp"

namespace {

using namespace ssr_plant;

Inputs oblique_sun() {
    Inputs u;
    u.sun_body = {0.48, -0.6, 0.64};
    return u;
}

void BM_Derivatives(benchmark::State& state) {
    Parameters p;
    p.fidelity = static_cast<Fidelity>(state.range(0));
    const Model m = make_model(p);
    const Inputs u = oblique_sun();
    State x{15.27, 0.9};
    const DiscreteState d = initialize(m, u, 0.0, x);
    for (auto _ : state) {
        x[state_v_bus] += 1e-9;  // defeat caching of a constant argument
        benchmark::DoNotOptimize(derivatives(m, u, d, 0.0, x));
    }
}
BENCHMARK(BM_Derivatives)->Arg(0)->Arg(1);

void BM_Outputs(benchmark::State& state) {
    const Model m = make_model(Parameters{});
    const Inputs u = oblique_sun();
    const State x{15.27, 0.9};
    const DiscreteState d = initialize(m, u, 0.0, x);
    for (auto _ : state) benchmark::DoNotOptimize(outputs(m, u, d, 0.0, x));
}
BENCHMARK(BM_Outputs);

void BM_PanelCurrent(benchmark::State& state) {
    const DiodeModel dm = fit_diode_model(PanelDatasheet{});
    double v = 15.9;
    for (auto _ : state) {
        v += 1e-9;
        benchmark::DoNotOptimize(panel_current(dm, 0.85, v, 0.05));
    }
}
BENCHMARK(BM_PanelCurrent);

void BM_MakeModel(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(make_model(Parameters{}));
}
BENCHMARK(BM_MakeModel);

}  // namespace

BENCHMARK_MAIN();
