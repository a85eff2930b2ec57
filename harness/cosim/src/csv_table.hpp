// A results CSV read back into columns (for plotting and for tests that check a run's output).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace cosim {

struct CsvTable {
    std::vector<std::string> names;
    std::vector<std::vector<double>> columns;  // columns[i][row]

    // The column whose name is `name` or ends with ".name" (component prefix left open).
    std::optional<std::size_t> find(const std::string& name) const;
    std::size_t rows() const { return columns.empty() ? 0 : columns.front().size(); }
};

// Non-numeric cells (e.g. a String output) read as NaN.
CsvTable read_csv(const std::filesystem::path& file);

}  // namespace cosim
