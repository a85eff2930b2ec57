// The plant under SUNDIALS CVODE (BDF, dense Newton), driven the way an FMI Model Exchange master
// drives it: stop time at every time event, event indicators as root functions, event_update at each
// event, CVodeReInit after it. Expected values come from an independent integration of the same model
// (the fixed-step RK4 of test_integrator.hpp) and from the hand bounds of scenario_test.cpp.
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "earlier_reading.hpp"
#include "ssr_plant/plant.hpp"
#include "test_integrator.hpp"

namespace {

using namespace ssr_plant;

struct CvodeRun {
    double v_mean = 0.0;
    double v_min = 1e9, v_max = -1e9;
    State x_end{};
    long switchings = 0;
    long steps = 0;
};

struct Ctx {
    const Model* m;
    const ssr_plant_test::InputsAt* u;
    DiscreteState d;
};

int rhs(sunrealtype t, N_Vector y, N_Vector ydot, void* user) {
    try {
        auto* c = static_cast<Ctx*>(user);
        const State x{NV_Ith_S(y, 0), NV_Ith_S(y, 1)};
        const State dx = derivatives(*c->m, (*c->u)(t), c->d, t, x);
        NV_Ith_S(ydot, 0) = dx[0];
        NV_Ith_S(ydot, 1) = dx[1];
        return 0;
    } catch (...) {
        return -1;  // unrecoverable: never let an exception through C
    }
}

int roots(sunrealtype t, N_Vector y, sunrealtype* g, void* user) {
    try {
        auto* c = static_cast<Ctx*>(user);
        const State x{NV_Ith_S(y, 0), NV_Ith_S(y, 1)};
        const auto z = event_indicators(*c->m, (*c->u)(t), c->d, t, x);
        for (std::size_t i = 0; i < z.size(); ++i) g[i] = z[i];
        return 0;
    } catch (...) {
        return -1;
    }
}

CvodeRun run_cvode(const Model& m, const ssr_plant_test::InputsAt& u, State x0, double t1, double settle) {
    struct CtxFree {
        void operator()(SUNContext c) const { SUNContext_Free(&c); }
    };
    SUNContext sunctx = nullptr;
    if (SUNContext_Create(nullptr, &sunctx) != 0) throw std::runtime_error("SUNContext_Create");
    std::unique_ptr<std::remove_pointer_t<SUNContext>, CtxFree> ctx(sunctx);  // freed last
    struct VecFree {
        void operator()(N_Vector v) const { N_VDestroy(v); }
    };
    struct MemFree {
        void operator()(void* p) const { CVodeFree(&p); }
    };
    struct MatFree {
        void operator()(SUNMatrix a) const { SUNMatDestroy(a); }
    };
    struct LsFree {
        void operator()(SUNLinearSolver s) const { SUNLinSolFree(s); }
    };

    std::unique_ptr<std::remove_pointer_t<N_Vector>, VecFree> y(N_VNew_Serial(2, ctx.get()));
    std::unique_ptr<std::remove_pointer_t<N_Vector>, VecFree> atol(N_VNew_Serial(2, ctx.get()));
    NV_Ith_S(y.get(), 0) = x0[0];
    NV_Ith_S(y.get(), 1) = x0[1];
    const double rtol = 1e-8;
    NV_Ith_S(atol.get(), 0) = rtol * 15.0;  // reltol × nominal
    NV_Ith_S(atol.get(), 1) = rtol * 1.0;

    Ctx c{&m, &u, initialize(m, u(0.0), 0.0, x0)};
    std::unique_ptr<void, MemFree> mem(CVodeCreate(CV_BDF, ctx.get()));
    auto check = [](int flag, const char* what) {
        if (flag < 0) throw std::runtime_error(std::string(what) + " failed: " + std::to_string(flag));
    };
    check(CVodeInit(mem.get(), rhs, 0.0, y.get()), "CVodeInit");
    check(CVodeSVtolerances(mem.get(), rtol, atol.get()), "CVodeSVtolerances");
    check(CVodeSetUserData(mem.get(), &c), "CVodeSetUserData");
    check(CVodeRootInit(mem.get(), static_cast<int>(indicator_count), roots), "CVodeRootInit");
    std::unique_ptr<std::remove_pointer_t<SUNMatrix>, MatFree> A(SUNDenseMatrix(2, 2, ctx.get()));
    std::unique_ptr<std::remove_pointer_t<SUNLinearSolver>, LsFree> ls(SUNLinSol_Dense(y.get(), A.get(), ctx.get()));
    check(CVodeSetLinearSolver(mem.get(), ls.get(), A.get()), "CVodeSetLinearSolver");
    check(CVodeSetMaxNumSteps(mem.get(), 100000), "CVodeSetMaxNumSteps");

    CvodeRun r;
    long n = 0;
    double t = 0.0;
    const double out_dt = 50e-6;
    long out_k = 1;
    while (t < t1) {
        const double t_event = next_time_event(m, c.d);
        const double t_out = out_k * out_dt;
        const double t_stop = std::min({t_event, t_out, t1});
        check(CVodeSetStopTime(mem.get(), t_stop), "CVodeSetStopTime");
        double tret = t;
        const int flag = CVode(mem.get(), t_stop, y.get(), &tret, CV_NORMAL);
        check(flag, "CVode");
        t = tret;
        const State x{NV_Ith_S(y.get(), 0), NV_Ith_S(y.get(), 1)};
        if (t >= settle) {
            r.v_min = std::min(r.v_min, x[0]);
            r.v_max = std::max(r.v_max, x[0]);
        }
        if (t >= t_out) {  // CVODE may report reaching tout as CV_SUCCESS or CV_TSTOP_RETURN
            if (t >= settle) {
                r.v_mean += x[0];
                ++n;
            }
            ++out_k;
        }
        if (flag == CV_ROOT_RETURN || t >= t_event) {
            const auto res = event_update(m, u(t), c.d, t, x);
            if (res.discrete.charge_connected != c.d.charge_connected) ++r.switchings;
            c.d = res.discrete;
            long nst = 0;
            CVodeGetNumSteps(mem.get(), &nst);  // the counter restarts at every re-initialization
            r.steps += nst;
            check(CVodeReInit(mem.get(), t, y.get()), "CVodeReInit");
        }
    }
    long nst = 0;
    CVodeGetNumSteps(mem.get(), &nst);
    r.steps += nst;
    r.v_mean /= static_cast<double>(std::max(n, 1L));
    r.x_end = {NV_Ith_S(y.get(), 0), NV_Ith_S(y.get(), 1)};
    return r;
}

std::array<double, 3> spin_sun(double t) {
    const double phi = 1.26 * t, theta = 6.28 * t;
    return {std::sin(phi) * std::sin(theta), std::cos(phi) * std::sin(theta), std::cos(theta)};
}

TEST(SsrCoreCvode, SeedScenarioAgreesWithFixedStepRun) {
    for (Fidelity f : {Fidelity::switching, Fidelity::averaged}) {
        Parameters p = earlier_reading();
        p.fidelity = f;
        const Model m = make_model(p);
        ssr_plant_test::InputsAt u = [](double t) {
            Inputs in;
            in.sun_body = spin_sun(t);
            return in;
        };
        const double t1 = 0.1, settle = 0.02;
        const auto cv = run_cvode(m, u, State{15.0, 0.9}, t1, settle);
        State x{15.0, 0.9};
        double sum = 0.0;
        long n = 0;
        ssr_plant_test::simulate(m, u, x, 0.0, t1, 20e-6, 50e-6,
                                 [&](double t, const State& xs, const DiscreteState&, bool out) {
                                     if (out && t >= settle) {
                                         sum += xs[0];
                                         ++n;
                                     }
                                 });
        const double rk_mean = sum / static_cast<double>(n);
        std::cout << "[cvode " << (f == Fidelity::switching ? "switching" : "averaged") << "] v_bus mean " << cv.v_mean
                  << " (RK4 " << rk_mean << "), min " << cv.v_min << ", max " << cv.v_max << ", CVODE steps "
                  << cv.steps << "\n";
        EXPECT_NEAR(cv.v_mean, rk_mean, 1e-4);
        EXPECT_NEAR(cv.x_end[0], x[0], 1e-4);
        EXPECT_GT(cv.v_min, 15.0 - 0.196);  // hand bounds, see scenario_test.cpp
        EXPECT_LT(cv.v_max, 15.0 + 1.0 / 3.0 + 0.196);
    }
}

TEST(SsrCoreCvode, HysteresisUnderRootFinding) {
    // Same eclipse-then-sun cycle as SsrCorePlant.HysteresisRun…: exactly two switchings, soc ends full.
    Parameters p = earlier_reading();
    p.fidelity = Fidelity::averaged;
    p.battery.capacity = 1.0;
    const Model m = make_model(p);
    ssr_plant_test::InputsAt u = [](double t) {
        Inputs in;
        const double c = 1 / std::sqrt(3.0);
        in.sun_body = {c, c, c};
        in.irradiance = t < 0.5 ? 0.0 : 1367.0;
        return in;
    };
    const auto cv = run_cvode(m, u, State{15.0, 0.82}, 1.2, 0.0);
    EXPECT_EQ(cv.switchings, 2);
    EXPECT_NEAR(cv.x_end[1], 1.0, 1e-6);
    EXPECT_LE(cv.x_end[1], 1.0 + 1e-7);
}

}  // namespace
