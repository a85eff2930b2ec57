// Cost of one full environment evaluation (orbit, sun, eclipse, attitude, IGRF-14 degree 13, albedo).
#include <benchmark/benchmark.h>

#include "environment/environment.hpp"

namespace {

void BM_EnvironmentFullEvaluation(benchmark::State& state) {
    environment::EnvironmentParams p;  // spin mode, IGRF-14, albedo 24 x 48
    const environment::Environment env(p);
    double t = 100.0;  // sunlit part of the default orbit start
    for (auto _ : state) {
        benchmark::DoNotOptimize(env.evaluate(t));
        t += 1e-3;
    }
}
BENCHMARK(BM_EnvironmentFullEvaluation);

void BM_EnvironmentWithoutAlbedo(benchmark::State& state) {
    environment::EnvironmentParams p;
    p.albedo.enabled = false;
    const environment::Environment env(p);
    double t = 100.0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(env.evaluate(t));
        t += 1e-3;
    }
}
BENCHMARK(BM_EnvironmentWithoutAlbedo);

void BM_EnvironmentDipoleNoAlbedo(benchmark::State& state) {
    environment::EnvironmentParams p;
    p.albedo.enabled = false;
    p.field_model = environment::FieldModel::dipole;
    const environment::Environment env(p);
    double t = 100.0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(env.evaluate(t));
        t += 1e-3;
    }
}
BENCHMARK(BM_EnvironmentDipoleNoAlbedo);

// The same as BM_EnvironmentWithoutAlbedo with the orbit from the bundled TLE (SGP4 + TEME -> J2000).
void BM_EnvironmentTleOrbitWithoutAlbedo(benchmark::State& state) {
    environment::EnvironmentParams p;
    p.albedo.enabled = false;
    p.orbit_model = environment::OrbitModel::tle;
    p.tle = orbit::parse_tle("1 90001U          26079.00000000  .00002000  00000-0  15000-3 0  9995",
                             "2 90001  64.9000   0.0000 0012000  90.0000 270.0000 14.98524078  1001");
    const environment::Environment env(p);
    double t = 100.0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(env.evaluate(t));
        t += 1e-3;
    }
}
BENCHMARK(BM_EnvironmentTleOrbitWithoutAlbedo);

}  // namespace

BENCHMARK_MAIN();
