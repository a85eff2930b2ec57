// A results CSV read back into columns (for plotting and for tests that check a run's output).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cosim {

struct CsvTable {
    std::vector<std::string> names;
    std::vector<std::vector<double>> columns;  // columns[i][row]

    // The column whose name is `name` or ends with ".name" (component prefix left open).
    std::optional<std::size_t> find(const std::string& name) const;
    std::size_t rows() const { return columns.empty() ? 0 : columns.front().size(); }
};

// Non-numeric cells (e.g. a String output) read as NaN. Fields may be quoted as RFC 4180 has it
// (a quoted field may hold commas and doubled quotes; line breaks inside one are refused).
CsvTable read_csv(const std::filesystem::path& file);

// One field as RFC 4180 writes it: quoted when it holds a comma, a double quote, CR or LF (quotes
// doubled inside), as is otherwise. Variable names may hold any of these; the header stays one line
// per column whatever they are.
std::string csv_field(std::string_view text);

}  // namespace cosim
