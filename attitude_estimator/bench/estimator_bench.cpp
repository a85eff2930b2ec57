// Per-solution time of each Wahba solver (2 and 6 observations), of each sun method on six face currents,
// and of one whole sample, float and double.
// Problems are drawn once (noisy observations of random rotations) and cycled through, so the branch
// predictor cannot learn a single problem.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "attitude_estimator/attitude_matrix.hpp"
#include "attitude_estimator/estimator.hpp"
#include "attitude_estimator/fast_solver.hpp"
#include "attitude_estimator/q_method.hpp"
#include "attitude_estimator/sun_methods.hpp"
#include "attitude_estimator/vec3_math.hpp"

namespace ae = attitude_estimator;

namespace {

constexpr std::size_t kProblems = 256;

template <class T>
ae::Vec3<T> random_unit(std::mt19937_64& g) {
    std::normal_distribution<double> n(0.0, 1.0);
    double v[3] = {n(g), n(g), n(g)};
    const double s = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return {T(v[0] / s), T(v[1] / s), T(v[2] / s)};
}

// Rotation angles uniform in [0, max_angle]: π for arbitrary attitudes; a small max_angle keeps the
// branch of Shepperd's method (which of w, x, y, z is largest) the same, as on a slowly turning satellite.
template <class T>
std::vector<ae::ObservationSet<T>> make_problems(std::size_t n, double max_angle = M_PI) {
    std::mt19937_64 g(7);
    std::normal_distribution<double> noise(0.0, 1e-3);
    std::vector<ae::ObservationSet<T>> out(kProblems);
    for (auto& set : out) {
        const ae::Vec3<T> axis = random_unit<T>(g);
        const T half = T(std::uniform_real_distribution<double>(0.0, max_angle)(g) / 2);
        const ae::Quaternion<T> q{axis[0] * std::sin(half), axis[1] * std::sin(half), axis[2] * std::sin(half),
                                  std::cos(half)};
        const auto a = ae::attitude_matrix(q);
        for (std::size_t i = 0; i < n; ++i) {
            const ae::Vec3<T> v = random_unit<T>(g);
            ae::Vec3<T> w = ae::multiply(a, v);
            for (auto& c : w) c += T(noise(g));
            set.add(v, w, T(1));
        }
    }
    return out;
}

template <class T, ae::SolverKind Kind, std::size_t N, bool Steady = false>
void solver(benchmark::State& state) {
    const auto problems = make_problems<T>(N, Steady ? 1.0 : M_PI);
    std::size_t i = 0;
    for (auto _ : state) {
        const auto& p = problems[i++ % kProblems];
        auto s = Kind == ae::SolverKind::qmethod ? ae::solve_q_method(p) : ae::solve_fast(p);
        benchmark::DoNotOptimize(s);
    }
}

template <class T, ae::SolverKind Kind>
void whole_sample(benchmark::State& state) {
    std::mt19937_64 g(9);
    std::vector<ae::SampleInputs<T>> inputs(kProblems);
    for (auto& in : inputs) {
        const ae::Vec3<T> s = random_unit<T>(g);
        const ae::Vec3<T> b = random_unit<T>(g);
        for (int k = 0; k < 3; ++k) {
            in.i_sh[k] = s[k];
            in.v_mag[k] = T(2.5) + T(0.45) * b[k];
        }
        in.sun_ref = random_unit<T>(g);
        in.mag_ref = random_unit<T>(g);
    }
    ae::EstimatorConfig<T> config;
    config.solver = Kind;
    std::size_t i = 0;
    for (auto _ : state) {
        auto r = ae::estimate_sample(inputs[i++ % kProblems], config);
        benchmark::DoNotOptimize(r);
    }
}

// Face currents of Kelly panels for random sun directions, with a crude albedo (a random nadir half-space at
// up to 15 % of full sun, falling with the face's angle to nadir): timing only, the physics is in
// tests/montecarlo.
template <class T, ae::SunMethod Method>
void sun_method(benchmark::State& state) {
    std::mt19937_64 g(11);
    std::uniform_real_distribution<double> level(0.0, 0.15);
    const auto kelly = panel_response::kelly<T>();
    std::vector<std::array<T, 6>> faces(kProblems);
    for (auto& f : faces) {
        const ae::Vec3<T> s = random_unit<T>(g);
        const ae::Vec3<T> e = random_unit<T>(g);
        const double a = level(g);
        for (int k = 0; k < 6; ++k) {
            const T sign = k % 2 == 0 ? T(1) : T(-1);
            const double albedo = a * std::max(0.0, 0.3 + 0.7 * static_cast<double>(sign * e[k / 2]));
            f[k] = T(0.84754) * (panel_response::response_from_cos(kelly, sign * s[k / 2]) + T(albedo));
        }
    }
    ae::SunMethodConfig<T> config;
    config.method = Method;
    config.response = kelly;
    ae::SunMethodState<T> memory;
    std::size_t i = 0;
    for (auto _ : state) {
        auto r = ae::sun_from_faces(faces[i++ % kProblems], config, memory);
        benchmark::DoNotOptimize(r);
    }
}

}  // namespace

BENCHMARK(sun_method<double, ae::SunMethod::difference>)->Name("sun/difference/double");
BENCHMARK(sun_method<double, ae::SunMethod::inverse_response>)->Name("sun/inverse_response/double");
BENCHMARK(sun_method<double, ae::SunMethod::cones>)->Name("sun/cones/double");
BENCHMARK(sun_method<float, ae::SunMethod::cones>)->Name("sun/cones/float");
BENCHMARK(sun_method<double, ae::SunMethod::three_faces>)->Name("sun/three_faces/double");
BENCHMARK(solver<float, ae::SolverKind::fast, 2>)->Name("fast/2obs/float");
BENCHMARK(solver<double, ae::SolverKind::fast, 2>)->Name("fast/2obs/double");
BENCHMARK(solver<float, ae::SolverKind::fast, 2, true>)->Name("fast/2obs/float/angles<1rad");
BENCHMARK(solver<double, ae::SolverKind::fast, 2, true>)->Name("fast/2obs/double/angles<1rad");
BENCHMARK(solver<float, ae::SolverKind::fast, 6>)->Name("fast/6obs/float");
BENCHMARK(solver<double, ae::SolverKind::fast, 6>)->Name("fast/6obs/double");
BENCHMARK(solver<float, ae::SolverKind::qmethod, 2>)->Name("qmethod/2obs/float");
BENCHMARK(solver<double, ae::SolverKind::qmethod, 2>)->Name("qmethod/2obs/double");
BENCHMARK(solver<float, ae::SolverKind::qmethod, 6>)->Name("qmethod/6obs/float");
BENCHMARK(solver<double, ae::SolverKind::qmethod, 6>)->Name("qmethod/6obs/double");
BENCHMARK(whole_sample<float, ae::SolverKind::fast>)->Name("sample/fast/float");
BENCHMARK(whole_sample<double, ae::SolverKind::fast>)->Name("sample/fast/double");
BENCHMARK(whole_sample<float, ae::SolverKind::qmethod>)->Name("sample/qmethod/float");
BENCHMARK(whole_sample<double, ae::SolverKind::qmethod>)->Name("sample/qmethod/double");

BENCHMARK_MAIN();
