#include "engine/run_defaults.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "engine/cosim_error.hpp"
#include "engine/value_text.hpp"

namespace cosim {

RunDefaults run_defaults(const System& system, double start, double stop) {
    RunDefaults d{std::numeric_limits<double>::infinity(), 1e-6, std::nullopt};
    for (const auto& c : system.components()) {
        const auto& ex = c.description().default_experiment;
        if (!ex) continue;
        if (ex->step_size && *ex->step_size > 0) d.output_interval = std::min(d.output_interval, *ex->step_size);
        if (ex->tolerance && *ex->tolerance > 0) d.tolerance = std::min(d.tolerance, *ex->tolerance);
    }
    // The .ssd's own output interval, else no finer than a thousandth of the run: an orbit at the FMUs'
    // 1 ms default would write millions of rows.
    const double span = stop - start;
    if (system.description().output_interval)
        d.output_interval = *system.description().output_interval;
    else if (!std::isfinite(d.output_interval) || d.output_interval < span / 1000.0)
        d.output_interval = span / 1000.0;
    d.output_interval = interval_within_span(d.output_interval, span, d.shortened_from);
    return d;
}

double interval_within_span(double interval, double span, std::optional<double>& shortened_from) {
    shortened_from.reset();
    if (!(span > 0.0) || !std::isfinite(span) || !(interval > span)) return interval;
    shortened_from = interval;
    return span / 100.0;
}

namespace {

void check_time(const char* what, double value) {
    if (!std::isfinite(value)) throw CosimError(std::string(what) + " must be finite, got " + std::to_string(value));
}

}  // namespace

void check_run_span(const ExecutionOptions& ex, std::optional<double> communication_step, bool force) {
    check_time("the start time", ex.start_time);
    check_time("--stop-time", ex.stop_time);
    const double span = ex.stop_time - ex.start_time;
    if (!(span > 0.0))
        throw CosimError("--stop-time " + format_real(ex.stop_time) + " s is not after the start time " +
                         format_real(ex.start_time) + " s: nothing to simulate");
    auto check_interval = [&](const char* what, double h) {
        if (!std::isfinite(h) || !(h > 0.0))
            throw CosimError(std::string(what) + " must be positive and finite, got " + format_real(h));
        if (h > span)
            throw CosimError(std::string(what) + " " + format_real(h) + " s is longer than the run (" +
                             format_real(span) + " s): no point after the start");
        const double points = span / h;
        if (points > max_run_points && !force)
            throw CosimError(std::string(what) + " " + format_real(h) + " s over " + format_real(span) + " s makes " +
                             format_real(points) + " points, more than the limit of " + format_real(max_run_points) +
                             " (give --force to run it anyway)");
    };
    check_interval("--output-interval", ex.output_interval);
    if (communication_step) check_interval("--step", *communication_step);
}

}  // namespace cosim
