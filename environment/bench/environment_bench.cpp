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

// The rigid body's right-hand side, torque-free and under the four disturbance torques (which need the orbit,
// the sun, the eclipse and the field at t: the cost a solver pays per derivative), and the four torques' own
// closed forms given the geometry (box faces, no quadrature). Read the ratios: torques on / off, and
// torque formulas / right-hand side with torques.
void rigid_body_rhs(benchmark::State& state, bool torques) {
    environment::EnvironmentParams p;
    p.attitude_mode = environment::AttitudeMode::rigid_body;
    p.albedo.enabled = false;
    p.disturbance_torques = torques;
    p.body.dipole_moment = {0.0, 0.0, 0.05};
    const environment::Environment env(p);
    const environment::RigidBodyState x = env.initial_state();
    environment::RigidBodyState dx{};
    double t = 100.0;
    for (auto _ : state) {
        env.derivative(t, x.data(), dx.data());
        benchmark::DoNotOptimize(dx.data());
        t += 1e-3;
    }
}
void BM_RigidBodyRhsTorqueFree(benchmark::State& state) {
    rigid_body_rhs(state, false);
}
void BM_RigidBodyRhsWithTorques(benchmark::State& state) {
    rigid_body_rhs(state, true);
}
BENCHMARK(BM_RigidBodyRhsTorqueFree);
BENCHMARK(BM_RigidBodyRhsWithTorques);

void BM_TorqueFormulasAlone(benchmark::State& state) {
    const environment::SpacecraftBody body;
    const auto faces = environment::box_faces(body);
    const Eigen::Matrix3d J = Eigen::Vector3d(0.0405, 0.0398, 0.0072).asDiagonal();
    Eigen::Vector3d r(6.9e6, 1.0e5, -2.0e5), b(2e-5, -1e-5, 3e-5), v(10.0, 7600.0, -30.0), s(0.6, 0.0, 0.8);
    for (auto _ : state) {
        Eigen::Vector3d tau = environment::gravity_gradient_torque(J, r) +
                              environment::magnetic_torque({0.0, 0.0, 0.05}, b) +
                              environment::aerodynamic_torque(faces, 2.2, 2.3e-13, v) +
                              environment::solar_pressure_torque(faces, 0.05, 0.05, 1361.0, s);
        benchmark::DoNotOptimize(tau);
        r.x() += 1.0;
    }
}
BENCHMARK(BM_TorqueFormulasAlone);

}  // namespace

BENCHMARK_MAIN();
