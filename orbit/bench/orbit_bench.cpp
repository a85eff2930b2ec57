// Cost of the orbit library's pieces: one SGP4 propagation, the TEME -> J2000 rotation with the full and
// the truncated nutation series, in double and float (host figures; the firmware's are counted on target).
#include <benchmark/benchmark.h>

#include "orbit/frames.hpp"
#include "orbit/tle.hpp"

namespace {

const orbit::Tle& bundled_tle() {
    static const orbit::Tle tle =
        orbit::parse_tle("1 90001U          26079.00000000  .00002000  00000-0  15000-3 0  9995",
                         "2 90001  64.9000   0.0000 0012000  90.0000 270.0000 14.98524078  1001");
    return tle;
}

template <typename T>
void BM_Sgp4Propagate(benchmark::State& state) {
    orbit::Sgp4<T> sgp4;
    sgp4.initialize(bundled_tle().mean_elements<T>());
    orbit::OrbitState<T> s;
    T minutes = T(10);
    for (auto _ : state) {
        benchmark::DoNotOptimize(sgp4.propagate(minutes, s));
        benchmark::DoNotOptimize(s);
        minutes += T(0.01);
    }
}
BENCHMARK(BM_Sgp4Propagate<double>);
BENCHMARK(BM_Sgp4Propagate<float>);

template <typename T>
void BM_J2000FromTeme(benchmark::State& state) {
    const int terms = static_cast<int>(state.range(0));
    T t = static_cast<T>(0.262);
    for (auto _ : state) {
        benchmark::DoNotOptimize(orbit::j2000_from_teme(t, terms));
        t += static_cast<T>(1e-9);
    }
}
BENCHMARK(BM_J2000FromTeme<double>)->Arg(106)->Arg(4);
BENCHMARK(BM_J2000FromTeme<float>)->Arg(106)->Arg(4);

}  // namespace

BENCHMARK_MAIN();
