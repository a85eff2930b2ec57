// What a run of a system takes when its request leaves it open, and the checks of what it asks for:
// shared by every front end (cosim run, simulate, campaign) so that they agree.
#pragma once

#include <optional>

#include "engine/execution.hpp"
#include "engine/system.hpp"

namespace cosim {

// Output or communication points a run may have without --force: 1e8 points is hours of run and
// gigabytes of CSV; more is a typo (--output-interval 1e-300) far more often than a wish.
inline constexpr double max_run_points = 1e8;

// The defaults for a system run from start to stop: the .ssd's output interval, else the FMUs'
// smallest DefaultExperiment step but no finer than a thousandth of the run; the FMUs' smallest
// tolerance (1e-6 when none is smaller). A default interval longer than the run (the system's 10 s for a
// run of 1 s) gives a row every hundredth of the run instead, and says so in shortened_from: one rule for
// cosim run, cosim simulate, campaigns, the C API and pvatt (issue 40).
struct RunDefaults {
    double output_interval, tolerance;
    std::optional<double> shortened_from;  // the interval the system gave, when it was longer than the run
};
RunDefaults run_defaults(const System& system, double start, double stop);

// `interval`, or span / 100 when it is longer than a positive, finite `span` (then shortened_from is it).
double interval_within_span(double interval, double span, std::optional<double>& shortened_from);

// A run must have something to do and an end: finite times, a stop after the start, an output interval
// (and a communication step) positive, finite, not longer than the run and giving at most
// max_run_points points unless `force`. Throws CosimError naming the option at fault.
void check_run_span(const ExecutionOptions& run, std::optional<double> communication_step, bool force);

}  // namespace cosim
