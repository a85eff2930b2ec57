#include "engine/run_defaults.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cosim {

RunDefaults run_defaults(const System& system, double start, double stop) {
    RunDefaults d{std::numeric_limits<double>::infinity(), 1e-6};
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
    return d;
}

}  // namespace cosim
