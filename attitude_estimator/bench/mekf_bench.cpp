// Time of one 20 Hz filter update (propagation and the sun and field updates, with and without the
// face update for the panel scale and Euler propagation), float and double. Measurements are drawn once
// from a tumbling truth and cycled through; the filter runs on them as it would on board.
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "attitude_estimator/attitude_matrix.hpp"
#include "attitude_estimator/mekf.hpp"
#include "attitude_estimator/vec3_math.hpp"

namespace ae = attitude_estimator;

namespace {

constexpr std::size_t kSamples = 1024;

template <class T>
std::vector<ae::MekfSampleInputs<T>> make_samples(const panel_response::Response<T>* response) {
    std::mt19937_64 g(3);
    std::normal_distribution<double> n(0.0, 1.0);
    std::vector<ae::MekfSampleInputs<T>> out(kSamples);
    const double w[3] = {0.02, -0.015, 0.012};  // rad/s
    for (std::size_t k = 0; k < kSamples; ++k) {
        const double t = 0.05 * static_cast<double>(k);
        const double angle = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]) * t;
        const double s = std::sin(angle / 2) / (angle > 0 ? angle / t : 1.0);
        const ae::Quaternion<T> q{T(w[0] * s), T(w[1] * s), T(w[2] * s), T(std::cos(angle / 2))};
        const auto a = ae::attitude_matrix(q);
        auto& in = out[k];
        in.t = T(t);
        in.attitude_valid = in.sun_valid = in.mag_valid = true;
        in.q_single = q;
        in.sun_ref = {T(0.6), T(0.0), T(0.8)};
        in.mag_ref = {T(10e-6), T(-20e-6), T(30e-6)};
        in.sun_body = ae::multiply(a, in.sun_ref);
        in.mag_body = ae::multiply(a, in.mag_ref);
        for (auto& c : in.sun_body) c += T(0.01 * n(g));
        for (auto& c : in.mag_body) c += T(0.2e-6 * n(g));
        for (int f = 0; f < 6; ++f) {
            const T c = (f % 2 == 0 ? T(1) : T(-1)) * in.sun_body[static_cast<std::size_t>(f / 2)];
            in.face_r[static_cast<std::size_t>(f)] = c > T(0) ? c : T(0);
            if (c > T(0.45)) in.face_use |= static_cast<std::uint8_t>(1u << f);
        }
        in.response = response;
    }
    return out;
}

template <class T, bool Scale, bool Euler>
void mekf_update(benchmark::State& state) {
    const auto kelly = panel_response::kelly<T>();
    const auto samples = make_samples<T>(&kelly);
    ae::MekfConfig<T> config;
    config.estimate_scale = Scale;
    if (Euler) config.inertia = {T(3.2), T(0.05), T(-0.02), T(0.05), T(2.9), T(0.03), T(-0.02), T(0.03), T(3.6)};
    ae::MekfState<T> s;
    // Started (two samples) outside the timing.
    ae::mekf_sample(s, samples[0], config);
    ae::mekf_sample(s, samples[1], config);
    std::size_t i = 2;
    T offset = T(0);  // time keeps increasing across the cycles of the sample list
    for (auto _ : state) {
        auto in = samples[i % kSamples];
        in.t += offset;
        if (++i % kSamples == 0) offset += T(0.05 * kSamples);
        auto r = ae::mekf_sample(s, in, config);
        benchmark::DoNotOptimize(r);
    }
}

}  // namespace

BENCHMARK(mekf_update<float, false, false>)->Name("mekf/sun+field/float");
BENCHMARK(mekf_update<double, false, false>)->Name("mekf/sun+field/double");
BENCHMARK(mekf_update<float, true, true>)->Name("mekf/sun+field+faces+euler/float");
BENCHMARK(mekf_update<double, true, true>)->Name("mekf/sun+field+faces+euler/double");
