// Locating a state event of a system without continuous states: its event indicators can still change
// sign between two times (they depend on time and inputs), and with no integrator to do root finding the
// crossing is found by bisection on time. Shared by the FMU's own Co-Simulation (fmu::CsSolver) and the
// master's Model Exchange execution, which meet the same case.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <vector>

namespace integrator {

// `indicators(t, z)` writes the m indicators at time t into z. Returns the earliest time in (t_lo, t_hi]
// found just past a sign change of any indicator relative to its value at t_lo (as CVODE's root finding
// reports a root: the indicators there have the new sign), to 1e-13 relative; nullopt when none of them
// differs in sign at t_hi. Sign means z > 0 versus z <= 0.
template <class Indicators>
std::optional<double> bisect_indicator_crossing(double t_lo, double t_hi, std::size_t m, Indicators&& indicators) {
    std::vector<double> z0(m), z(m);
    indicators(t_lo, std::span<double>(z0));
    auto crossed = [&](double t) {
        indicators(t, std::span<double>(z));
        for (std::size_t i = 0; i < m; ++i)
            if ((z0[i] > 0) != (z[i] > 0)) return true;
        return false;
    };
    if (!crossed(t_hi)) return std::nullopt;
    double lo = t_lo, hi = t_hi;
    for (int i = 0; i < 60 && hi - lo > 1e-13 * std::max(1.0, std::abs(hi)); ++i) {
        const double mid = 0.5 * (lo + hi);
        (crossed(mid) ? hi : lo) = mid;
    }
    return hi;
}

}  // namespace integrator
