// Statistics of a sample, per run (over the output points a metric sampled) and across runs (in the
// summary): the named statistics of the spec and percentiles by linear interpolation between order
// statistics (Hyndman & Fan 1996, definition 7: the default of R and NumPy).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace campaign {

// "p95" -> 95, "p99.9" -> 99.9; nullopt for anything that is not p followed by a number in [0, 100].
std::optional<double> percentile_of(const std::string& stat);

// The p-th percentile (0..100) of `sorted` (ascending, no NaN); NaN when empty.
double percentile(const std::vector<double>& sorted, double p);

// One named statistic (mean, rms, min, max, final, count, pNN) of `values` in sampling order; NaN
// when there are no values (count: 0).
double statistic(const std::string& stat, const std::vector<double>& values);

// Probability that a normal(mean, sd) deviate falls in [lo, hi] (infinite ends allowed).
double normal_mass(double mean, double sd, double lo, double hi);

}  // namespace campaign
