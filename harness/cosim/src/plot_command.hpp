// `cosim plot results.csv`: the figures a person looks at after a run, as PNG files drawn by gnuplot:
// the real and the acquired sun vector components (seed 000 fig. 8), the bus voltage (fig. 9), the
// attitude error of the estimate against the truth in degrees, the battery state of charge. A
// figure whose columns the CSV lacks is skipped with a note.
#pragma once

#include <filesystem>
#include <ostream>
#include <vector>

namespace cosim {

// Returns the files written.
std::vector<std::filesystem::path> plot_results(const std::filesystem::path& csv, const std::filesystem::path& out_dir,
                                                std::ostream& notes);

// Angle in degrees between two attitudes given as scalar-last unit quaternions.
double attitude_error_degrees(const double q_a[4], const double q_b[4]);

}  // namespace cosim
