#include "fmu/instant_clock.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "fmu/errors.hpp"
#include "fmu/model.hpp"

namespace fmu {

std::int64_t next_instant_index(double t, double origin, double period, std::int64_t at_least, std::string_view what) {
    if (!std::isfinite(t)) throw Error(std::string(what) + ": time " + std::to_string(t) + " is not finite");
    if (!(period > 0.0) || !std::isfinite(period) || !std::isfinite(origin))
        throw Error(std::string(what) + ": the period must be positive and finite");
    const auto beyond = [&] {
        return Error(std::string(what) + ": t = " + std::to_string(t) + " s is more than " +
                     std::to_string(max_instant_index) + " periods of " + std::to_string(period) +
                     " s after the origin " + std::to_string(origin) + " s (the limit of an instant count)");
    };
    // Computed in double first: the quotient can be far beyond any integer type.
    const double periods = std::floor((t - origin) / period);
    if (!(periods < static_cast<double>(max_instant_index))) throw beyond();
    std::int64_t k = std::max(at_least, static_cast<std::int64_t>(std::max(periods, 0.0)));
    // The floor leaves at most a few instants reached (rounding, and reached()'s tolerance, which is
    // below 0.1 period while k <= max_instant_index): bounded steps, not a loop on the input.
    for (int step = 0; step < 4 && reached(t, origin + static_cast<double>(k) * period); ++step) ++k;
    if (k > max_instant_index || reached(t, origin + static_cast<double>(k) * period)) throw beyond();
    return k;
}

}  // namespace fmu
