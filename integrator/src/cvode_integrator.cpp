#include "integrator/cvode_integrator.hpp"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <exception>
#include <string>
#include <type_traits>
#include <utility>

namespace integrator {

namespace {

template <class T, auto Free>
struct Deleter {
    void operator()(T* p) const { Free(p); }
};
void free_cvode(void* mem) {
    CVodeFree(&mem);
}
void free_context(SUNContext ctx) {
    SUNContext_Free(&ctx);
}

template <class Handle, auto Free>
using Owned = std::unique_ptr<std::remove_pointer_t<Handle>, Deleter<std::remove_pointer_t<Handle>, Free>>;

}  // namespace

struct CvodeIntegrator::Handles {
    // Declared in creation order, so destroyed in reverse as SUNDIALS requires.
    Owned<SUNContext, free_context> ctx;
    Owned<N_Vector, N_VDestroy> y;
    Owned<N_Vector, N_VDestroy> abstol;
    Owned<SUNMatrix, SUNMatDestroy> matrix;
    Owned<SUNLinearSolver, SUNLinSolFree> solver;
    std::unique_ptr<void, Deleter<void, free_cvode>> mem;

    Rhs rhs;
    Roots roots;
    std::size_t n = 0, m = 0;
    std::exception_ptr failure;
    std::string message;
};

namespace {

void check(int flag, const char* what, const std::string& detail = {}) {
    if (flag < 0)
        throw Error(std::string("CVODE ") + what + " failed (flag " + std::to_string(flag) + ")" +
                    (detail.empty() ? "" : ": " + detail));
}

int rhs_callback(sunrealtype t, N_Vector y, N_Vector ydot, void* user) {
    auto& h = *static_cast<CvodeIntegrator::Handles*>(user);
    try {
        h.rhs(t, {N_VGetArrayPointer(y), h.n}, {N_VGetArrayPointer(ydot), h.n});
        return 0;
    } catch (...) {
        h.failure = std::current_exception();
        return -1;
    }
}

int roots_callback(sunrealtype t, N_Vector y, sunrealtype* g, void* user) {
    auto& h = *static_cast<CvodeIntegrator::Handles*>(user);
    try {
        h.roots(t, {N_VGetArrayPointer(y), h.n}, {g, h.m});
        return 0;
    } catch (...) {
        h.failure = std::current_exception();
        return -1;
    }
}

void error_handler(int, const char* module, const char* function, char* msg, void* user) {
    auto& h = *static_cast<CvodeIntegrator::Handles*>(user);
    h.message = std::string(module ? module : "") + "/" + (function ? function : "") + ": " + (msg ? msg : "");
}

}  // namespace

CvodeIntegrator::CvodeIntegrator(std::size_t n, std::size_t m, Rhs rhs, Roots roots, double relative_tolerance,
                                 std::span<const double> absolute_tolerance)
    : h_(std::make_unique<Handles>()), root_info_(m, 0) {
    if (n == 0) throw Error("CVODE needs at least one state");
    auto& h = *h_;
    h.rhs = std::move(rhs);
    h.roots = std::move(roots);
    h.n = n;
    h.m = m;
    const auto len = static_cast<sunindextype>(n);
    SUNContext ctx = nullptr;
    check(SUNContext_Create(nullptr, &ctx), "SUNContext_Create");
    h.ctx.reset(ctx);
    h.y.reset(N_VNew_Serial(len, ctx));
    h.abstol.reset(N_VNew_Serial(len, ctx));
    if (!h.y || !h.abstol) throw Error("CVODE: cannot allocate vectors");
    std::fill_n(N_VGetArrayPointer(h.y.get()), n, 0.0);
    std::copy_n(absolute_tolerance.begin(), n, N_VGetArrayPointer(h.abstol.get()));
    h.mem.reset(CVodeCreate(CV_BDF, ctx));
    if (!h.mem) throw Error("CVodeCreate failed");
    void* mem = h.mem.get();
    check(CVodeSetErrHandlerFn(mem, error_handler, &h), "CVodeSetErrHandlerFn");
    check(CVodeInit(mem, rhs_callback, 0.0, h.y.get()), "CVodeInit");
    check(CVodeSetUserData(mem, &h), "CVodeSetUserData");
    check(CVodeSVtolerances(mem, relative_tolerance, h.abstol.get()), "CVodeSVtolerances");
    if (m > 0) check(CVodeRootInit(mem, static_cast<int>(m), roots_callback), "CVodeRootInit");
    h.matrix.reset(SUNDenseMatrix(len, len, ctx));
    h.solver.reset(SUNLinSol_Dense(h.y.get(), h.matrix.get(), ctx));
    if (!h.matrix || !h.solver) throw Error("CVODE: cannot allocate the dense linear solver");
    check(CVodeSetLinearSolver(mem, h.solver.get(), h.matrix.get()), "CVodeSetLinearSolver");
    check(CVodeSetMaxNumSteps(mem, 1000000), "CVodeSetMaxNumSteps");
}

CvodeIntegrator::~CvodeIntegrator() = default;

void CvodeIntegrator::set_max_step(double h) {
    check(CVodeSetMaxStep(h_->mem.get(), h), "CVodeSetMaxStep");
}

void CvodeIntegrator::restart(double t, std::span<const double> x) {
    std::copy_n(x.begin(), h_->n, N_VGetArrayPointer(h_->y.get()));
    restart_from_y(t);
}

void CvodeIntegrator::restart_from_y(double t) {
    steps_before_restart_ = steps();
    rhs_before_restart_ = rhs_evaluations();
    check(CVodeReInit(h_->mem.get(), t, h_->y.get()), "CVodeReInit");
}

CvodeIntegrator::Stop CvodeIntegrator::advance(double t_out, double t_stop, double& t, std::span<double> x) {
    auto& h = *h_;
    void* mem = h.mem.get();
    t_out = std::min(t_out, t_stop);
    check(CVodeSetStopTime(mem, t_stop), "CVodeSetStopTime");
    sunrealtype t_reached = t;
    int flag = CVode(mem, t_out, h.y.get(), &t_reached, CV_NORMAL);
    if (h.failure) std::rethrow_exception(std::exchange(h.failure, nullptr));
    // A kink of the right-hand side that no indicator marks (a diode starting to conduct into a stiff bus) can
    // make CVODE's error test or Newton iteration fail repeatedly at one step: its history (order, step size,
    // Jacobian) belongs to the other side of the kink. On such a failure CVODE leaves y at its last successful
    // step (t_reached); starting afresh there, at order 1 with a new Jacobian, goes through. Only while each
    // restart makes progress, and at most kMaxFailureRestarts times in a row: a failure that persists is reported.
    for (int tries = 0;
         (flag == CV_ERR_FAILURE || flag == CV_CONV_FAILURE) && tries < kMaxFailureRestarts && t_reached > t_failure_;
         ++tries) {
        t_failure_ = t_reached;
        ++failure_restarts_;
        restart_from_y(t_reached);
        flag = CVode(mem, t_out, h.y.get(), &t_reached, CV_NORMAL);
        if (h.failure) std::rethrow_exception(std::exchange(h.failure, nullptr));
    }
    check(flag, "integration", h.message);
    t = flag == CV_TSTOP_RETURN ? t_stop : t_reached;
    std::copy_n(N_VGetArrayPointer(h.y.get()), h.n, x.begin());
    if (flag != CV_ROOT_RETURN) return Stop::reached;
    check(CVodeGetRootInfo(mem, root_info_.data()), "CVodeGetRootInfo");
    return Stop::root;
}

long CvodeIntegrator::steps() const {
    long n = 0;
    CVodeGetNumSteps(h_->mem.get(), &n);
    return steps_before_restart_ + n;
}

long CvodeIntegrator::rhs_evaluations() const {
    long n = 0;
    CVodeGetNumRhsEvals(h_->mem.get(), &n);
    return rhs_before_restart_ + n;
}

}  // namespace integrator
