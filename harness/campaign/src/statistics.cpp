#include "statistics.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

#include "analysis/run_measures.hpp"

namespace campaign {

std::optional<double> percentile_of(const std::string& stat) {
    if (stat.size() < 2 || stat[0] != 'p') return std::nullopt;
    double p = 0.0;
    const auto [end, ec] = std::from_chars(stat.data() + 1, stat.data() + stat.size(), p);
    if (ec != std::errc() || end != stat.data() + stat.size() || !(p >= 0.0 && p <= 100.0)) return std::nullopt;
    return p;
}

double percentile(const std::vector<double>& sorted, double p) {
    if (sorted.empty()) return std::numeric_limits<double>::quiet_NaN();
    const double h = (static_cast<double>(sorted.size()) - 1.0) * p / 100.0;
    const auto lo = static_cast<std::size_t>(std::floor(h));
    const std::size_t hi = std::min(lo + 1, sorted.size() - 1);
    return sorted[lo] + (h - static_cast<double>(lo)) * (sorted[hi] - sorted[lo]);
}

double statistic(const std::string& stat, const std::vector<double>& values) {
    if (stat == "count") return static_cast<double>(values.size());
    if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
    if (stat == "final") return values.back();
    // A normalized error's: NEES per degree of freedom (3-dof samples) and the share (%) of samples within
    // chi2(3)'s 99 % point, 99 % for a consistent filter (analysis/run_measures.hpp).
    if (stat == "per_dof") return statistic("mean", values) / 3.0;
    if (stat == "chi2_99")
        return 100.0 *
               static_cast<double>(
                   std::count_if(values.begin(), values.end(), [](double x) { return x <= analysis::chi2_3dof_99; })) /
               static_cast<double>(values.size());
    if (stat == "min") return *std::min_element(values.begin(), values.end());
    if (stat == "max") return *std::max_element(values.begin(), values.end());
    if (stat == "mean" || stat == "rms") {
        double sum = 0.0;
        for (double x : values) sum += stat == "rms" ? x * x : x;
        const double mean = sum / static_cast<double>(values.size());
        return stat == "rms" ? std::sqrt(mean) : mean;
    }
    if (const auto p = percentile_of(stat)) {
        std::vector<double> sorted = values;
        std::sort(sorted.begin(), sorted.end());
        return percentile(sorted, *p);
    }
    return std::numeric_limits<double>::quiet_NaN();
}

double normal_mass(double mean, double sd, double lo, double hi) {
    // Phi(z) = erfc(-z / sqrt 2) / 2, exact in the tails where 1 - erfc would cancel.
    auto cdf = [&](double x) { return 0.5 * std::erfc(-(x - mean) / (sd * std::sqrt(2.0))); };
    return cdf(hi) - cdf(lo);
}

}  // namespace campaign
