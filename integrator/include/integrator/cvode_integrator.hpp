// SUNDIALS CVODE (BDF, dense Newton) behind a small C++ interface with root finding and stop times,
// shared by the Co-Simulation solver inside each FMU and by the master's Model Exchange solver.
// Every handle is owned (freed in reverse order of creation); an exception thrown by a callback is
// stored, CVODE is told to stop (return -1), and the exception is rethrown after CVode() returns.
#pragma once

#include <functional>
#include <limits>
#include <memory>
#include <span>
#include <stdexcept>
#include <vector>

namespace integrator {

// CVODE refused or failed (a flag, an allocation); the FMU runtime and the master report it as theirs.
struct Error : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class CvodeIntegrator {
public:
    using Rhs = std::function<void(double t, std::span<const double> x, std::span<double> dx)>;
    using Roots = std::function<void(double t, std::span<const double> x, std::span<double> g)>;

    // n states (n > 0), m root functions; absolute tolerance per state.
    CvodeIntegrator(std::size_t n, std::size_t m, Rhs rhs, Roots roots, double relative_tolerance,
                    std::span<const double> absolute_tolerance);
    ~CvodeIntegrator();
    CvodeIntegrator(const CvodeIntegrator&) = delete;
    CvodeIntegrator& operator=(const CvodeIntegrator&) = delete;

    // The longest step CVODE may take (0: no limit).
    void set_max_step(double h);

    // Start afresh from (t, x): after every discontinuity.
    void restart(double t, std::span<const double> x);

    enum class Stop { reached, root };
    // Integrate towards t_stop (never past it). On return t and x hold the point reached: t_stop, or
    // the first root of any root function, with root_info() telling which.
    Stop advance(double t_stop, double& t, std::span<double> x) { return advance(t_stop, t_stop, t, x); }
    // The same, returning at t_out <= t_stop with x(t_out) from CVODE's interpolating polynomial:
    // the integrator may have stepped beyond t_out (never beyond t_stop) and goes on from there at the
    // next call, so output points and events that change nothing continuous do not cut its steps.
    Stop advance(double t_out, double t_stop, double& t, std::span<double> x);
    // For each root function: +1 / −1 when it crossed upwards / downwards at the last root, else 0.
    const std::vector<int>& root_info() const { return root_info_; }

    // Totals over the whole life of the integrator (CVODE itself counts from the last restart).
    long steps() const;
    long rhs_evaluations() const;
    // Restarts at the last successful step after CVODE's error test or Newton iteration failed repeatedly (advance).
    long failure_restarts() const { return failure_restarts_; }
    // Restarts in a row without progress before such a failure is reported.
    static constexpr int kMaxFailureRestarts = 3;

    struct Handles;  // public only so the C callbacks can name it

private:
    // restart() from the state CVODE holds (its y): the totals kept across the restart.
    void restart_from_y(double t);

    std::unique_ptr<Handles> h_;
    std::vector<int> root_info_;
    long steps_before_restart_ = 0, rhs_before_restart_ = 0;
    long failure_restarts_ = 0;
    double t_failure_ = -std::numeric_limits<double>::infinity();  // where the last failure restart started
};

}  // namespace integrator
