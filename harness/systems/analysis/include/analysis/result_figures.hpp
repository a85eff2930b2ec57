// The standard figures of a results CSV of the bundled systems (`cosim plot results.csv`), the ones a
// person looks at after a run, as PNG (or SVG) files drawn by gnuplot: per axis the acquired sun vector
// (the estimator's samples) on the real one (seed 000 fig. 8), the sun vector error and the attitude error
// of every estimate the CSV holds (single-frame q_est, filter q_filt) at its samples while valid (median
// and 95th percentile in the legend), the bus voltage (fig. 9), the battery state of charge; from a CSV sampled finer than 50 us the
// bus ripple over its last millisecond instead. A figure whose columns the CSV lacks is skipped with a
// note. Writes index.html in the folder: every figure there, the error statistics, what the run reached
// (analysis/run_measures.hpp: per phase, after convergence, the filter's chi2(3) coverage, the faults
// declared, each also a red line on the figures), and run_statistics.txt when present.
#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace analysis {

struct PlotOptions {
    std::string format = "png";                    // "png" (pngcairo) or "svg"
    std::vector<std::string> columns;              // also draw these columns against time, one figure ("columns")
    std::optional<std::filesystem::path> derived;  // write the derived signals here as CSV columns
};

// Returns the files written. Where the CSV has an irradiance column, the eclipse (irradiance 0) is shaded.
std::vector<std::filesystem::path> plot_results(const std::filesystem::path& csv, const std::filesystem::path& out_dir,
                                                std::ostream& notes, const PlotOptions& options = {});

}  // namespace analysis
