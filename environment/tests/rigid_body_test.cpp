#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include "environment/attitude.hpp"
#include "environment/rigid_body.hpp"

namespace env = environment;

namespace {

// CVODE (Adams, fixed-point iteration: the torque-free body is not stiff) around RigidBody::derivative.
class CvodeIntegrator {
public:
    CvodeIntegrator(const env::RigidBody& body, const env::RigidBodyState& x0, double rtol, double atol) : body_(body) {
        if (SUNContext_Create(nullptr, &ctx_) != 0) throw std::runtime_error("SUNContext_Create");
        y_ = N_VNew_Serial(7, ctx_);
        if (y_ == nullptr) throw std::runtime_error("N_VNew_Serial");
        for (int i = 0; i < 7; ++i) NV_Ith_S(y_, i) = x0[i];
        mem_ = CVodeCreate(CV_ADAMS, ctx_);
        if (mem_ == nullptr) throw std::runtime_error("CVodeCreate");
        check(CVodeInit(mem_, &CvodeIntegrator::rhs, 0.0, y_), "CVodeInit");
        check(CVodeSetUserData(mem_, this), "CVodeSetUserData");
        check(CVodeSStolerances(mem_, rtol, atol), "CVodeSStolerances");
        check(CVodeSetMaxNumSteps(mem_, 1000000), "CVodeSetMaxNumSteps");
        nls_ = SUNNonlinSol_FixedPoint(y_, 0, ctx_);
        if (nls_ == nullptr) throw std::runtime_error("SUNNonlinSol_FixedPoint");
        check(CVodeSetNonlinearSolver(mem_, nls_), "CVodeSetNonlinearSolver");
    }
    ~CvodeIntegrator() {
        CVodeFree(&mem_);
        SUNNonlinSolFree(nls_);
        N_VDestroy(y_);
        SUNContext_Free(&ctx_);
    }
    CvodeIntegrator(const CvodeIntegrator&) = delete;
    CvodeIntegrator& operator=(const CvodeIntegrator&) = delete;

    env::RigidBodyState advance_to(double t) {
        double reached = 0.0;
        check(CVode(mem_, t, y_, &reached, CV_NORMAL), "CVode");
        env::RigidBodyState x{};
        for (int i = 0; i < 7; ++i) x[i] = NV_Ith_S(y_, i);
        return x;
    }

private:
    static int rhs(sunrealtype, N_Vector y, N_Vector ydot, void* user) {
        auto* self = static_cast<CvodeIntegrator*>(user);
        self->body_.derivative(N_VGetArrayPointer(y), N_VGetArrayPointer(ydot));
        return 0;
    }
    static void check(int flag, const char* what) {
        if (flag < 0) throw std::runtime_error(std::string(what) + " failed");
    }
    const env::RigidBody& body_;
    SUNContext ctx_ = nullptr;
    N_Vector y_ = nullptr;
    void* mem_ = nullptr;
    SUNNonlinearSolver nls_ = nullptr;
};

}  // namespace

TEST(EnvironmentCoreRigidBody, EnergyAndMomentumConservedOver10000s) {
    const env::RigidBodyParams p;  // default tumbling small satellite, |w| ~ 0.94 deg/s
    const env::RigidBody body(p);
    const env::RigidBodyState x0 = body.initial_state();
    const double e0 = body.kinetic_energy(x0.data());
    const double h0 = body.angular_momentum_body(x0.data()).norm();
    CvodeIntegrator cvode(body, x0, 1e-12, 1e-15);
    double worst_e = 0.0, worst_h = 0.0;
    for (double t = 500.0; t <= 10000.0; t += 500.0) {
        const env::RigidBodyState x = cvode.advance_to(t);
        worst_e = std::max(worst_e, std::abs(body.kinetic_energy(x.data()) / e0 - 1.0));
        worst_h = std::max(worst_h, std::abs(body.angular_momentum_body(x.data()).norm() / h0 - 1.0));
    }
    EXPECT_LT(worst_e, 1e-9);
    EXPECT_LT(worst_h, 1e-9);
    RecordProperty("energy_rel_drift", std::to_string(worst_e));
    RecordProperty("momentum_rel_drift", std::to_string(worst_h));
    std::printf("rigid body over 10000 s: max |dE/E| = %.3e, max |d|H|/|H|| = %.3e\n", worst_e, worst_h);
}

TEST(EnvironmentCoreRigidBody, InertialAngularMomentumIsFixed) {
    // Torque-free: H_eci = A^T J w is constant (a stronger check that also involves the kinematics).
    const env::RigidBody body(env::RigidBodyParams{});
    const env::RigidBodyState x0 = body.initial_state();
    auto h_eci = [&](const env::RigidBodyState& x) {
        return Eigen::Vector3d(env::attitude_matrix({x[0], x[1], x[2], x[3]}).transpose() *
                               body.angular_momentum_body(x.data()));
    };
    const Eigen::Vector3d h0 = h_eci(x0);
    CvodeIntegrator cvode(body, x0, 1e-12, 1e-15);
    env::RigidBodyState x = cvode.advance_to(10000.0);
    env::RigidBody::renormalize(x.data());
    EXPECT_LT((h_eci(x) - h0).norm() / h0.norm(), 1e-8);
}

TEST(EnvironmentCoreRigidBody, PrincipalAxisSpinMatchesClosedForm) {
    // Diagonal inertia, w = (0, 0, w0): the body turns at w0 about z; by hand A(t) = A(q0) rotated:
    // A(t) = Rz(-w0 t) A(0) with Rz active, i.e. q(t) = [0, 0, sin(w0 t/2), cos(w0 t/2)] from q0 = identity.
    env::RigidBodyParams p;
    p.inertia = {2.0, 0.0, 0.0, 0.0, 3.0, 0.0, 0.0, 0.0, 4.0};
    p.q0 = {0.0, 0.0, 0.0, 1.0};
    const double w0 = 0.02;
    p.omega0 = {0.0, 0.0, w0};
    const env::RigidBody body(p);
    CvodeIntegrator cvode(body, body.initial_state(), 1e-12, 1e-15);
    const double t = 10000.0;
    const env::RigidBodyState x = cvode.advance_to(t);
    EXPECT_NEAR(x[0], 0.0, 1e-12);
    EXPECT_NEAR(x[1], 0.0, 1e-12);
    EXPECT_NEAR(x[2], std::sin(w0 * t / 2.0), 1e-8);
    EXPECT_NEAR(x[3], std::cos(w0 * t / 2.0), 1e-8);
}

TEST(EnvironmentCoreRigidBody, KinematicsKeepAttitudeRateConsistent) {
    // q' from derivative() must satisfy dA/dt = -[w x] A (the attitude matrix maps inertial to body).
    const env::RigidBody body(env::RigidBodyParams{});
    const env::RigidBodyState x = body.initial_state();
    env::RigidBodyState dx{};
    body.derivative(x.data(), dx.data());
    const double h = 1e-3;
    env::Quaternion qp{}, qm{};
    for (int i = 0; i < 4; ++i) {
        qp[i] = x[i] + h * dx[i];
        qm[i] = x[i] - h * dx[i];
    }
    const Eigen::Matrix3d dA = (env::attitude_matrix(qp) - env::attitude_matrix(qm)) / (2.0 * h);
    const Eigen::Vector3d w(x[4], x[5], x[6]);
    const Eigen::Matrix3d expected = -env::cross_matrix(w) * env::attitude_matrix({x[0], x[1], x[2], x[3]});
    EXPECT_LT((dA - expected).cwiseAbs().maxCoeff(), 1e-10);
}

TEST(EnvironmentCoreRigidBody, RenormalizeRemovesNormDrift) {
    env::RigidBodyState x{0.2, 0.4, -0.1, 1.1, 0.01, 0.02, 0.03};
    env::RigidBody::renormalize(x.data());
    EXPECT_NEAR(x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + x[3] * x[3], 1.0, 1e-15);
    EXPECT_DOUBLE_EQ(x[4], 0.01);  // the rates are untouched
}

TEST(EnvironmentCoreRigidBody, RejectsUnphysicalInertia) {
    env::RigidBodyParams p;
    p.inertia = {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 3.0};  // 3 > 1 + 1: no real body
    EXPECT_THROW(env::RigidBody{p}, std::invalid_argument);
    p.inertia = {1.0, 0.5, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0};  // not symmetric
    EXPECT_THROW(env::RigidBody{p}, std::invalid_argument);
    p.inertia = {-1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0};
    EXPECT_THROW(env::RigidBody{p}, std::invalid_argument);
}

TEST(EnvironmentCoreRigidBody, RenormalizationStopsNormDriftOfACoarseIntegrator) {
    // Classical RK4 with a deliberately coarse 20 s step: without the projection |q| drifts; with
    // renormalize() after every step it stays 1 to rounding, while the rates are the same in both runs.
    const env::RigidBody body(env::RigidBodyParams{});
    auto rk4 = [&](env::RigidBodyState& x, double h) {
        env::RigidBodyState k1{}, k2{}, k3{}, k4{}, tmp{};
        body.derivative(x.data(), k1.data());
        for (int i = 0; i < 7; ++i) tmp[i] = x[i] + 0.5 * h * k1[i];
        body.derivative(tmp.data(), k2.data());
        for (int i = 0; i < 7; ++i) tmp[i] = x[i] + 0.5 * h * k2[i];
        body.derivative(tmp.data(), k3.data());
        for (int i = 0; i < 7; ++i) tmp[i] = x[i] + h * k3[i];
        body.derivative(tmp.data(), k4.data());
        for (int i = 0; i < 7; ++i) x[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    };
    env::RigidBodyState free_run = body.initial_state(), projected = body.initial_state();
    for (int step = 0; step < 500; ++step) {
        rk4(free_run, 20.0);
        rk4(projected, 20.0);
        env::RigidBody::renormalize(projected.data());
    }
    auto norm_error = [](const env::RigidBodyState& x) {
        return std::abs(std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + x[3] * x[3]) - 1.0);
    };
    EXPECT_GT(norm_error(free_run), 1e-9);
    EXPECT_LT(norm_error(projected), 1e-15);
    for (int i = 4; i < 7; ++i) EXPECT_DOUBLE_EQ(free_run[i], projected[i]);
    std::printf("RK4 20 s x 500: |q| drift without projection %.2e, with %.2e\n", norm_error(free_run),
                norm_error(projected));
}
