// Cost of the rate estimators per call: one SpinSpectrum push, one full analysis (three FFTs of N, peak
// search, identification), one MeanAngularRate push.
#include <benchmark/benchmark.h>

#include <cmath>

#include "attitude_estimator/angular_rate.hpp"
#include "attitude_estimator/spin_spectrum.hpp"

namespace ae = attitude_estimator;

namespace {

ae::Vec3<double> seed_sun(double t) {
    const double phi = 1.26 * t, theta = 6.28 * t;
    return {std::sin(phi) * std::sin(theta), std::cos(phi) * std::sin(theta), std::cos(theta)};
}

void BM_SpinSpectrumPush(benchmark::State& state) {
    ae::SpinSpectrum spec(0.05, 512);
    double t = 0.0;
    for (auto _ : state) {
        spec.push(seed_sun(t));
        t += 0.05;
    }
}
BENCHMARK(BM_SpinSpectrumPush);

void BM_SpinSpectrumAnalyze(benchmark::State& state) {
    const auto n = static_cast<std::size_t>(state.range(0));
    ae::SpinSpectrum spec(0.05, n);
    for (std::size_t i = 0; i < n; ++i) spec.push(seed_sun(0.05 * static_cast<double>(i)));
    for (auto _ : state) benchmark::DoNotOptimize(spec.analyze().theta_dot);
}
BENCHMARK(BM_SpinSpectrumAnalyze)->Arg(256)->Arg(500)->Arg(512)->Arg(1024);

template <class T>
void BM_MeanAngularRatePush(benchmark::State& state) {
    ae::MeanAngularRate<T> est({.measure = ae::RateMeasure::attitude_angle, .window = 10});
    T t = 0;
    for (auto _ : state) {
        t += T(0.05);
        est.push(t, ae::Quaternion<T>{T(0), T(0), std::sin(T(0.01) * t), std::cos(T(0.01) * t)});
        benchmark::DoNotOptimize(est.result().rate);
    }
}
BENCHMARK_TEMPLATE(BM_MeanAngularRatePush, float);
BENCHMARK_TEMPLATE(BM_MeanAngularRatePush, double);

}  // namespace

BENCHMARK_MAIN();
