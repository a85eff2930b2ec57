// The four disturbance torques against closed forms worked by hand, the atmosphere against its table, and
// the rigid body under them: H_eci(T) - H_eci(0) = ∫ A^T τ dt and E(T) - E(0) = ∫ ω·τ dt (dH/dt = τ).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include "environment/atmosphere.hpp"
#include "environment/attitude.hpp"
#include "environment/constants.hpp"
#include "environment/disturbance_torques.hpp"
#include "environment/environment.hpp"

namespace env = environment;

namespace {

Eigen::Vector3d v3(const std::array<double, 3>& a) {
    return {a[0], a[1], a[2]};
}

env::SpacecraftBody box_with_centre_of_mass(double x, double y, double z) {
    env::SpacecraftBody b;
    b.centre_of_mass = {x, y, z};
    return b;
}

}  // namespace

TEST(EnvironmentCoreTorques, GravityGradientOfAKnownAttitude) {
    // Principal axes, the Earth's direction at angle θ from body x in the x-y plane: by hand
    // r_b × J r_b = R² (cos θ, sin θ, 0) × (a cos θ, b sin θ, 0) = R² (b − a) sin θ cos θ e_z, so
    // τ = 3μ/R³ (b − a) sin θ cos θ e_z.
    const double a = 0.0405, b = 0.0398, c = 0.0072, R = 6948137.0;
    const Eigen::Matrix3d J = Eigen::Vector3d(a, b, c).asDiagonal();
    for (double theta : {0.0, 0.3, 0.7853981633974483, 2.0}) {
        const Eigen::Vector3d r(R * std::cos(theta), R * std::sin(theta), 0.0);
        const Eigen::Vector3d tau = env::gravity_gradient_torque(J, r);
        const double expected = 3.0 * 3.986004418e14 / (R * R * R) * (b - a) * std::sin(theta) * std::cos(theta);
        EXPECT_NEAR(tau.z(), expected, 1e-12 * 3.0 * 3.986004418e14 / (R * R * R) * a);
        EXPECT_NEAR(tau.x(), 0.0, 1e-22);
        EXPECT_NEAR(tau.y(), 0.0, 1e-22);
    }
    // The long axis (smallest moment) 45° from the local vertical in the y-z plane: the torque turns it toward
    // the vertical, τ_x = 3μ/R³ (c − b) sin 45° cos 45° < 0 for the Earth along (0, cos 45°, sin 45°).
    const Eigen::Vector3d r(0.0, R * std::sqrt(0.5), R * std::sqrt(0.5));
    const Eigen::Vector3d tau = env::gravity_gradient_torque(J, r);
    EXPECT_NEAR(tau.x(), 3.0 * 3.986004418e14 / (R * R * R) * (c - b) * 0.5, 1e-20);
    EXPECT_LT(tau.x(), 0.0);
    // 5.9e-8 N m at most for this body at 570 km (the size the docs quote): 3μ/R³ (a − c) / 2.
    EXPECT_NEAR(3.0 * 3.986004418e14 / (R * R * R) * (a - c) * 0.5, 5.9e-8, 0.1e-8);
}

TEST(EnvironmentCoreTorques, MagneticTorqueIsTheDipoleCrossTheField) {
    // m = 0.05 A m² along z, B = (20, 5, −30) µT: m × B = (m_y B_z − m_z B_y, m_z B_x − m_x B_z, m_x B_y − m_y B_x)
    // = (−0.05 · 5e-6, 0.05 · 20e-6, 0).
    const Eigen::Vector3d tau = env::magnetic_torque({0.0, 0.0, 0.05}, {20e-6, 5e-6, -30e-6});
    EXPECT_NEAR(tau.x(), -2.5e-7, 1e-21);
    EXPECT_NEAR(tau.y(), 1.0e-6, 1e-21);
    EXPECT_NEAR(tau.z(), 0.0, 1e-21);
}

TEST(EnvironmentCoreTorques, FlatPlateInAKnownWind) {
    // Flow along +x (the body moves along +x): only the +x face (0.1 × 0.34 m) meets it, F = −½ρ C_D A v² e_x at
    // its centroid (0.05, 0, 0) less the centre of mass (0, 0, −0.01): lever (0.05, 0, 0.01), τ = lever × F =
    // (0, −0.01 F0, 0) with F0 = ½ρ C_D A v².
    const env::SpacecraftBody body = box_with_centre_of_mass(0.0, 0.0, -0.01);
    const double rho = 2.0e-13, v = 7600.0;
    const double f0 = 0.5 * rho * 2.2 * 0.034 * v * v;
    const Eigen::Vector3d tau = env::aerodynamic_torque(env::box_faces(body), 2.2, rho, {v, 0.0, 0.0});
    EXPECT_NEAR(tau.x(), 0.0, 1e-24);
    EXPECT_NEAR(tau.y(), -0.01 * f0, 1e-12 * f0);
    EXPECT_NEAR(tau.z(), 0.0, 1e-24);
    // At 45° in the x-y plane the +x and +y faces each meet it at cos 45°: F_k = −F0' cos 45° v̂ with
    // F0' = ½ρ C_D A v² (A = 0.034 for both); both levers have z = +0.01, so τ = Σ (l_k × F_k), whose z
    // component is (l_x F_y − l_y F_x) summed: +x face l = (0.05, 0, 0.01), +y face l = (0, 0.05, 0.01),
    // F = −F0' c (c, c, 0) with c = cos 45°: τ_z = −F0' c² (0.05 − 0.05) = 0, τ_x = −l_z F_y = 0.01 F0' c²·2,
    // τ_y = l_z F_x = −0.01 F0' c² · 2.
    const double c = std::sqrt(0.5);
    const Eigen::Vector3d tau45 = env::aerodynamic_torque(env::box_faces(body), 2.2, rho, {v * c, v * c, 0.0});
    EXPECT_NEAR(tau45.x(), 0.01 * f0 * c * c * 2.0, 1e-12 * f0);
    EXPECT_NEAR(tau45.y(), -0.01 * f0 * c * c * 2.0, 1e-12 * f0);
    EXPECT_NEAR(tau45.z(), 0.0, 1e-12 * f0);
}

TEST(EnvironmentCoreTorques, ABoxAboutItsCentreFeelsNoAerodynamicTorqueInAnyWind) {
    // Each axis' exposed face gives (V/2) v_i along its normal: Σ c_k × F_k ∝ v̂ × v̂ = 0 (header).
    const env::SpacecraftBody centred = box_with_centre_of_mass(0.0, 0.0, 0.0);
    const double f0 = 0.5 * 2e-13 * 2.2 * 0.034 * 7600.0 * 7600.0;
    for (const Eigen::Vector3d& w :
         {Eigen::Vector3d(1.0, 2.0, 3.0), Eigen::Vector3d(-0.3, 0.1, -2.0), Eigen::Vector3d(0.0, -1.0, 0.2)}) {
        const Eigen::Vector3d tau =
            env::aerodynamic_torque(env::box_faces(centred), 2.2, 2e-13, 7600.0 * w.normalized());
        EXPECT_LT(tau.norm(), 1e-13 * f0 * 0.17);
    }
}

TEST(EnvironmentCoreTorques, FlatPlateInTheSunAndInTheUmbra) {
    // Sun along +z: only the +z face (0.1 × 0.1 m) is lit, cos θ = 1, F = −(E/c) A (1 + ρ_s + 2ρ_d/3) e_z at
    // (0, 0, 0.17) less the centre of mass (0.01, 0, 0): lever (−0.01, 0, 0.17), τ = lever × F = (0, −0.01 F, 0).
    const env::SpacecraftBody body = box_with_centre_of_mass(0.01, 0.0, 0.0);
    const double E = 1361.0, rs = 0.05, rd = 0.05;
    const double f = E / 299792458.0 * 0.01 * (1.0 + rs + 2.0 * rd / 3.0);
    const auto faces = env::box_faces(body);
    const Eigen::Vector3d tau = env::solar_pressure_torque(faces, rs, rd, E, {0.0, 0.0, 1.0});
    EXPECT_NEAR(tau.x(), 0.0, 1e-12 * f);
    EXPECT_NEAR(tau.y(), -0.01 * f, 1e-12 * f);
    EXPECT_NEAR(tau.z(), 0.0, 1e-12 * f);
    // A black plate (ρ_s = ρ_d = 0) tilted: the sun at 60° from +z in the x-z plane lights +x and +z; the force
    // on each is −(E/c) A cos θ ŝ (absorption only), so τ = −(E/c) Σ A_k cos θ_k (c_k × ŝ).
    const Eigen::Vector3d s(std::sin(1.0471975511965976), 0.0, std::cos(1.0471975511965976));
    const double p = E / 299792458.0;
    const Eigen::Vector3d lever_x(0.05 - 0.01, 0.0, 0.0), lever_z(-0.01, 0.0, 0.17);
    const Eigen::Vector3d expected = -p * (0.034 * s.x() * lever_x.cross(s) + 0.01 * s.z() * lever_z.cross(s));
    EXPECT_LT((env::solar_pressure_torque(faces, 0.0, 0.0, E, s) - expected).norm(), 1e-12 * expected.norm());
    // In the umbra the irradiance is 0 and so is the torque; in the penumbra it scales with the lit fraction.
    EXPECT_EQ(env::solar_pressure_torque(faces, rs, rd, 0.0, {0.0, 0.0, 1.0}).norm(), 0.0);
    EXPECT_NEAR(env::solar_pressure_torque(faces, rs, rd, 0.25 * E, {0.0, 0.0, 1.0}).y(), -0.0025 * f, 1e-12 * f);
}

TEST(EnvironmentCoreTorques, ExponentialAtmosphereFollowsItsTable) {
    // Vallado (2013) table 8-4: the base densities, and 570 km = 6.967e-13 exp(−70 / 63.822).
    EXPECT_DOUBLE_EQ(env::atmosphere_density(0.0), 1.225);
    EXPECT_DOUBLE_EQ(env::atmosphere_density(500e3), 6.967e-13);
    EXPECT_DOUBLE_EQ(env::atmosphere_density(600e3), 1.454e-13);
    EXPECT_NEAR(env::atmosphere_density(570e3), 6.967e-13 * std::exp(-70.0 / 63.822), 1e-27);
    EXPECT_NEAR(env::atmosphere_density(1200e3), 3.019e-15 * std::exp(-200.0 / 268.0), 1e-30);
    double previous = 2.0;
    for (double h = 0.0; h <= 1500e3; h += 5e3) {
        const double rho = env::atmosphere_density(h);
        EXPECT_LT(rho, previous) << h;
        previous = rho;
    }
    EXPECT_THROW((void)env::atmosphere_density(-1.0), std::invalid_argument);
    // The ellipsoid: exact at the equator and the poles (polar radius a(1 − f) = 6356752.3 m).
    EXPECT_NEAR(env::ellipsoid_altitude({env::kEarthRadius + 570e3, 0.0, 0.0}), 570e3, 1e-6);
    EXPECT_NEAR(env::ellipsoid_altitude({0.0, 0.0, 6356752.314 + 570e3}), 570e3, 1e-2);
}

TEST(EnvironmentCoreTorques, RefusesABodyThatCannotBe) {
    env::EnvironmentParams p;
    p.body.centre_of_mass = {0.0, 0.0, 0.2};  // outside the 0.34 m box
    EXPECT_THROW(env::Environment{p}, std::invalid_argument);
    p = env::EnvironmentParams{};
    p.body.specular_reflectivity = 0.7;
    p.body.diffuse_reflectivity = 0.5;
    EXPECT_THROW(env::Environment{p}, std::invalid_argument);
    p = env::EnvironmentParams{};
    p.body.size = {0.1, 0.0, 0.34};
    EXPECT_THROW(env::Environment{p}, std::invalid_argument);
}

namespace {

env::EnvironmentParams pushed_3u() {
    env::EnvironmentParams p;
    p.attitude_mode = env::AttitudeMode::rigid_body;
    p.albedo.enabled = false;
    p.body.dipole_moment = {0.0, 0.0, 0.05};
    return p;
}

}  // namespace

TEST(EnvironmentCoreTorques, OutputsAreTheClosedFormsAtTheTruthsGeometry) {
    // Recomputed here from the environment's own r, q, field and sun outputs: the wiring (frames, which
    // inertia, which dipole) is what is checked; the formulas are checked above.
    const env::Environment e(pushed_3u());
    const env::RigidBodyState x = e.initial_state();
    for (double t : {0.0, 1000.0, 2500.0}) {
        const env::EnvironmentOutputs o = e.evaluate(t, &x);
        const Eigen::Matrix3d A = env::attitude_matrix(o.q_true);
        const Eigen::Vector3d rb = A * v3(o.r_eci);
        const double r = rb.norm();
        const Eigen::Matrix3d J =
            Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(e.params().rigid_body.inertia.data());
        const Eigen::Vector3d gg = 3.0 * env::kEarthGravitationalParameter / std::pow(r, 5) * rb.cross(J * rb);
        EXPECT_LT((v3(o.torque_gravity_gradient) - gg).norm(), 1e-12 * gg.norm() + 1e-25);
        const Eigen::Vector3d mb = Eigen::Vector3d(0.0, 0.0, 0.05).cross(v3(o.mag_body));
        EXPECT_LT((v3(o.torque_magnetic) - mb).norm(), 1e-12 * mb.norm());
        // Sizes at 570 km: |m × B| up to 0.05 A m² × 50 µT, gravity gradient below 6e-8 N m, drag and pressure
        // on centimetre levers below 1e-8 N m.
        EXPECT_LT(v3(o.torque_magnetic).norm(), 2.5e-6);
        EXPECT_LT(v3(o.torque_gravity_gradient).norm(), 6e-8);
        EXPECT_LT(v3(o.torque_aerodynamic).norm(), 1e-8);
        EXPECT_LT(v3(o.torque_solar_pressure).norm(), 1e-8);
        if (o.sunlight_fraction == 0.0) {
            EXPECT_EQ(v3(o.torque_solar_pressure).norm(), 0.0);
        }
        // The state derivative is Euler's equations under their sum.
        env::RigidBodyState dx{}, dx_free{};
        e.derivative(t, x.data(), dx.data());
        const env::RigidBody free_body(e.params().rigid_body);
        free_body.derivative(x.data(), dx_free.data());
        const Eigen::Vector3d tau = v3(o.torque_gravity_gradient) + v3(o.torque_magnetic) + v3(o.torque_aerodynamic) +
                                    v3(o.torque_solar_pressure);
        const Eigen::Vector3d jdw = J * Eigen::Vector3d(dx[4] - dx_free[4], dx[5] - dx_free[5], dx[6] - dx_free[6]);
        EXPECT_LT((jdw - tau).norm(), 1e-9 * tau.norm());
    }
    // Off: the torque-free body, torque outputs zero.
    env::EnvironmentParams off = pushed_3u();
    off.disturbance_torques = false;
    const env::Environment e_off(off);
    const env::EnvironmentOutputs o = e_off.evaluate(100.0, &x);
    EXPECT_EQ(v3(o.torque_magnetic).norm() + v3(o.torque_gravity_gradient).norm(), 0.0);
    env::RigidBodyState dx{}, dx_free{};
    e_off.derivative(100.0, x.data(), dx.data());
    env::RigidBody(off.rigid_body).derivative(x.data(), dx_free.data());
    EXPECT_EQ(dx, dx_free);
}

namespace {

// CVODE (Adams) over the environment's derivative, with four quadrature states appended: ∫ A^T τ dt (3) and
// ∫ ω·τ dt, τ the torques the environment reports at the same t and x.
class PushedBody {
public:
    PushedBody(const env::Environment& e, const env::RigidBodyState& x0) : e_(e) {
        if (SUNContext_Create(nullptr, &ctx_) != 0) throw std::runtime_error("SUNContext_Create");
        y_ = N_VNew_Serial(11, ctx_);
        for (int i = 0; i < 11; ++i) NV_Ith_S(y_, i) = i < 7 ? x0[i] : 0.0;
        mem_ = CVodeCreate(CV_ADAMS, ctx_);
        check(CVodeInit(mem_, &PushedBody::rhs, 0.0, y_), "CVodeInit");
        check(CVodeSetUserData(mem_, this), "CVodeSetUserData");
        check(CVodeSStolerances(mem_, 1e-11, 1e-14), "CVodeSStolerances");
        check(CVodeSetMaxNumSteps(mem_, 1000000), "CVodeSetMaxNumSteps");
        nls_ = SUNNonlinSol_FixedPoint(y_, 0, ctx_);
        check(CVodeSetNonlinearSolver(mem_, nls_), "CVodeSetNonlinearSolver");
    }
    ~PushedBody() {
        CVodeFree(&mem_);
        SUNNonlinSolFree(nls_);
        N_VDestroy(y_);
        SUNContext_Free(&ctx_);
    }
    PushedBody(const PushedBody&) = delete;
    PushedBody& operator=(const PushedBody&) = delete;
    std::vector<double> advance_to(double t) {
        double reached = 0.0;
        check(CVode(mem_, t, y_, &reached, CV_NORMAL), "CVode");
        return std::vector<double>(N_VGetArrayPointer(y_), N_VGetArrayPointer(y_) + 11);
    }

private:
    static int rhs(sunrealtype t, N_Vector y, N_Vector ydot, void* user) {
        const auto* self = static_cast<PushedBody*>(user);
        const double* x = N_VGetArrayPointer(y);
        double* dx = N_VGetArrayPointer(ydot);
        self->e_.derivative(t, x, dx);
        env::RigidBodyState s{};
        for (int i = 0; i < 7; ++i) s[i] = x[i];
        const env::EnvironmentOutputs o = self->e_.evaluate(t, &s);
        const Eigen::Vector3d tau = v3(o.torque_gravity_gradient) + v3(o.torque_magnetic) + v3(o.torque_aerodynamic) +
                                    v3(o.torque_solar_pressure);
        const Eigen::Vector3d tau_eci = env::attitude_matrix(o.q_true).transpose() * tau;
        for (int i = 0; i < 3; ++i) dx[7 + i] = tau_eci(i);
        dx[10] = v3(o.omega_body).dot(tau);
        return 0;
    }
    static void check(int flag, const char* what) {
        if (flag < 0) throw std::runtime_error(std::string(what) + " failed");
    }
    const env::Environment& e_;
    SUNContext ctx_ = nullptr;
    N_Vector y_ = nullptr;
    void* mem_ = nullptr;
    SUNNonlinearSolver nls_ = nullptr;
};

}  // namespace

TEST(EnvironmentCoreTorques, AngularMomentumAndEnergyChangeByWhatTheTorquesDo) {
    // dH_eci/dt = A^T τ and dE/dt = ω·τ: over 1200 s of the pushed 3U the inertial angular momentum moves by
    // the integrated torque (5.2e-4 N m s against |H0| = 5.2e-4: the dipole's torque dominates), not by zero.
    const env::Environment e(pushed_3u());
    const env::RigidBodyState x0 = e.initial_state();
    const env::RigidBody body(e.params().rigid_body);
    auto h_eci = [&](const double* x) {
        return Eigen::Vector3d(env::attitude_matrix({x[0], x[1], x[2], x[3]}).transpose() *
                               body.angular_momentum_body(x));
    };
    const Eigen::Vector3d h0 = h_eci(x0.data());
    const double e0 = body.kinetic_energy(x0.data());
    PushedBody run(e, x0);
    const std::vector<double> y = run.advance_to(1200.0);
    std::vector<double> x(y.begin(), y.begin() + 7);
    env::RigidBody::renormalize(x.data());
    const Eigen::Vector3d dh = h_eci(x.data()) - h0;
    const Eigen::Vector3d impulse(y[7], y[8], y[9]);
    const double de = body.kinetic_energy(x.data()) - e0;
    std::printf("1200 s pushed 3U: |H0| %.3e, |dH| %.3e, |dH - impulse| %.3e; E0 %.3e, dE %.3e, dE - work %.3e\n",
                h0.norm(), dh.norm(), (dh - impulse).norm(), e0, de, de - y[10]);
    EXPECT_GT(dh.norm(), 0.5 * h0.norm());  // the torques really act
    EXPECT_LT((dh - impulse).norm(), 1e-6 * dh.norm());
    EXPECT_GT(std::abs(de), 0.01 * e0);
    EXPECT_LT(std::abs(de - y[10]), 1e-6 * std::abs(de) + 1e-6 * e0);
}
