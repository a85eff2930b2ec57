// The standard figures of a results CSV of the bundled systems (`cosim plot results.csv`), the ones a
// person looks at after a run, as PNG files drawn by gnuplot: per axis the acquired sun vector (the estimator's samples) on the real one (seed 000 fig. 8), the sun
// vector and attitude errors at the estimator's samples while valid (median and 95th percentile in the
// legend), the bus voltage (fig. 9), the battery state of charge; from a CSV sampled finer than 50 us the
// bus ripple over its last millisecond instead. A figure whose columns the CSV lacks is skipped with a
// note. Writes index.html in the folder: every figure there, the error statistics, and
// run_statistics.txt when present.
#pragma once

#include <filesystem>
#include <ostream>
#include <vector>

namespace analysis {

// Returns the files written.
std::vector<std::filesystem::path> plot_results(const std::filesystem::path& csv, const std::filesystem::path& out_dir,
                                                std::ostream& notes);

}  // namespace analysis
