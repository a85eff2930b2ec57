#include "fmu/cs_solver.hpp"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <utility>
#include <vector>

#include "fmu/errors.hpp"

namespace fmu {

namespace {

template <class T, auto Free>
struct Deleter {
    void operator()(T* p) const { Free(p); }
};

void free_cvode(void* mem) { CVodeFree(&mem); }
void free_context(SUNContext ctx) { SUNContext_Free(&ctx); }

}  // namespace

struct CsSolver::Cvode {
    // Declared in creation order; destroyed in reverse, as SUNDIALS requires.
    std::unique_ptr<std::remove_pointer_t<SUNContext>, Deleter<std::remove_pointer_t<SUNContext>, free_context>> ctx;
    std::unique_ptr<std::remove_pointer_t<N_Vector>, Deleter<std::remove_pointer_t<N_Vector>, N_VDestroy>> y;
    std::unique_ptr<std::remove_pointer_t<N_Vector>, Deleter<std::remove_pointer_t<N_Vector>, N_VDestroy>> abstol;
    std::unique_ptr<std::remove_pointer_t<SUNMatrix>, Deleter<std::remove_pointer_t<SUNMatrix>, SUNMatDestroy>> matrix;
    std::unique_ptr<std::remove_pointer_t<SUNLinearSolver>,
                    Deleter<std::remove_pointer_t<SUNLinearSolver>, SUNLinSolFree>>
        solver;
    std::unique_ptr<void, Deleter<void, free_cvode>> mem;

    ModelRunner* runner = nullptr;
    std::exception_ptr failure;  // an exception from a callback, rethrown after CVode returns
    std::string message;         // CVODE's own error text
    std::vector<double> scratch;
};

namespace {

void check(int flag, const char* what, const std::string& detail = {}) {
    if (flag < 0) throw Error(std::string("CVODE ") + what + " failed (flag " + std::to_string(flag) + ")" +
                              (detail.empty() ? "" : ": " + detail));
}

// Callbacks never let an exception through: they store it and return -1 (unrecoverable).
int rhs(sunrealtype t, N_Vector y, N_Vector ydot, void* user) {
    auto& c = *static_cast<CsSolver::Cvode*>(user);
    try {
        const auto n = static_cast<std::size_t>(N_VGetLength(y));
        c.runner->set_time(t);
        c.runner->set_states({N_VGetArrayPointer(y), n});
        c.runner->get_derivatives({N_VGetArrayPointer(ydot), n});
        return 0;
    } catch (...) {
        c.failure = std::current_exception();
        return -1;
    }
}

int roots(sunrealtype t, N_Vector y, sunrealtype* g, void* user) {
    auto& c = *static_cast<CsSolver::Cvode*>(user);
    try {
        const auto n = static_cast<std::size_t>(N_VGetLength(y));
        c.runner->set_time(t);
        c.runner->set_states({N_VGetArrayPointer(y), n});
        c.runner->get_indicators({g, c.runner->indicator_count()});
        return 0;
    } catch (...) {
        c.failure = std::current_exception();
        return -1;
    }
}

void error_handler(int, const char* module, const char* function, char* msg, void* user) {
    auto& c = *static_cast<CsSolver::Cvode*>(user);
    c.message = std::string(module ? module : "") + "/" + (function ? function : "") + ": " + (msg ? msg : "");
}

}  // namespace

CsSolver::CsSolver(ModelRunner& runner, double relative_tolerance) : runner_(runner) {
    const auto n = static_cast<sunindextype>(runner_.state_count());
    if (n == 0) return;  // nothing to integrate; events are located by bisection
    cvode_ = std::make_unique<Cvode>();
    auto& c = *cvode_;
    c.runner = &runner_;
    SUNContext ctx = nullptr;
    check(SUNContext_Create(nullptr, &ctx), "SUNContext_Create");
    c.ctx.reset(ctx);
    c.y.reset(N_VNew_Serial(n, ctx));
    c.abstol.reset(N_VNew_Serial(n, ctx));
    if (!c.y || !c.abstol) throw Error("CVODE: cannot allocate vectors");
    runner_.get_states({N_VGetArrayPointer(c.y.get()), static_cast<std::size_t>(n)});
    // Absolute tolerance of each state from its nominal magnitude: reltol × nominal.
    std::vector<double> nominal(static_cast<std::size_t>(n));
    runner_.get_nominals(nominal);
    for (sunindextype i = 0; i < n; ++i)
        N_VGetArrayPointer(c.abstol.get())[i] = relative_tolerance * nominal[static_cast<std::size_t>(i)];

    c.mem.reset(CVodeCreate(CV_BDF, ctx));
    if (!c.mem) throw Error("CVodeCreate failed");
    void* mem = c.mem.get();
    check(CVodeSetErrHandlerFn(mem, error_handler, &c), "CVodeSetErrHandlerFn");
    check(CVodeInit(mem, rhs, runner_.time(), c.y.get()), "CVodeInit");
    check(CVodeSetUserData(mem, &c), "CVodeSetUserData");
    check(CVodeSVtolerances(mem, relative_tolerance, c.abstol.get()), "CVodeSVtolerances");
    if (runner_.indicator_count() > 0)
        check(CVodeRootInit(mem, static_cast<int>(runner_.indicator_count()), roots), "CVodeRootInit");
    c.matrix.reset(SUNDenseMatrix(n, n, ctx));
    c.solver.reset(SUNLinSol_Dense(c.y.get(), c.matrix.get(), ctx));
    if (!c.matrix || !c.solver) throw Error("CVODE: cannot allocate the dense linear solver");
    check(CVodeSetLinearSolver(mem, c.solver.get(), c.matrix.get()), "CVodeSetLinearSolver");
    check(CVodeSetMaxNumSteps(mem, 1000000), "CVodeSetMaxNumSteps");
}

CsSolver::~CsSolver() = default;

bool CsSolver::integrate_to(double t_stop) {
    auto& c = *cvode_;
    void* mem = c.mem.get();
    auto* y = c.y.get();
    const auto n = static_cast<std::size_t>(N_VGetLength(y));
    if (restart_needed_) {
        runner_.get_states({N_VGetArrayPointer(y), n});
        check(CVodeReInit(mem, runner_.time(), y), "CVodeReInit");
        restart_needed_ = false;
        ++stats_.restarts;
    }
    check(CVodeSetStopTime(mem, t_stop), "CVodeSetStopTime");
    sunrealtype t_reached = runner_.time();
    long steps_before = 0, rhs_before = 0, steps_after = 0, rhs_after = 0;
    CVodeGetNumSteps(mem, &steps_before);
    CVodeGetNumRhsEvals(mem, &rhs_before);
    const int flag = CVode(mem, t_stop, y, &t_reached, CV_NORMAL);
    CVodeGetNumSteps(mem, &steps_after);
    CVodeGetNumRhsEvals(mem, &rhs_after);
    stats_.steps += steps_after - steps_before;
    stats_.rhs_evaluations += rhs_after - rhs_before;
    if (c.failure) {
        auto failure = std::exchange(c.failure, nullptr);
        restart_needed_ = true;
        std::rethrow_exception(failure);
    }
    if (flag < 0) {
        restart_needed_ = true;
        check(flag, "integration", c.message);
    }
    // The state at the point CVODE returned (callbacks may have left trial values behind).
    runner_.set_time(flag == CV_TSTOP_RETURN ? t_stop : t_reached);
    runner_.set_states({N_VGetArrayPointer(y), n});
    return flag == CV_ROOT_RETURN;
}

bool CsSolver::locate_without_states(double t_stop) {
    const std::size_t m = runner_.indicator_count();
    if (m == 0) {
        runner_.set_time(t_stop);
        return false;
    }
    std::vector<double> z0(m), z(m);
    runner_.get_indicators(z0);
    auto crossed = [&](double t) {
        runner_.set_time(t);
        runner_.get_indicators(z);
        for (std::size_t i = 0; i < m; ++i)
            if ((z0[i] > 0) != (z[i] > 0)) return true;
        return false;
    };
    double lo = runner_.time(), hi = t_stop;
    if (!crossed(hi)) return false;
    for (int i = 0; i < 60 && hi - lo > 1e-13 * std::max(1.0, std::abs(hi)); ++i) {
        const double mid = 0.5 * (lo + hi);
        (crossed(mid) ? hi : lo) = mid;
    }
    runner_.set_time(hi);  // just past the crossing, as CVODE's root finding reports
    return true;
}

CsSolver::Outcome CsSolver::advance(double t_end) {
    const double tiny = 1e-12 * std::max(1.0, std::abs(t_end));
    for (;;) {
        if (runner_.time_event_due()) {
            ++stats_.time_events;
            const EventUpdate r = runner_.event_iteration();
            restart_needed_ = true;  // any discrete change may make the right-hand side jump
            if (r.terminate) return Outcome::terminated;
            if (runner_.time_event_due())
                throw Error("the block did not move its time event past t = " + std::to_string(runner_.time()));
            continue;
        }
        if (runner_.time() >= t_end - tiny) {
            runner_.set_time(std::max(runner_.time(), t_end));
            return Outcome::reached;
        }
        const double t_stop = std::min(t_end, runner_.next_time_event());
        const bool state_event = cvode_ ? integrate_to(t_stop) : locate_without_states(t_stop);
        if (state_event) {
            ++stats_.state_events;
            const EventUpdate r = runner_.event_iteration();
            restart_needed_ = true;
            if (r.terminate) return Outcome::terminated;
        }
    }
}

}  // namespace fmu
