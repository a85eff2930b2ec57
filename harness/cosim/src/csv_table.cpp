#include "csv_table.hpp"

#include <charconv>
#include <fstream>
#include <limits>
#include <sstream>

#include "cosim_error.hpp"

namespace cosim {

std::optional<std::size_t> CsvTable::find(const std::string& name) const {
    for (std::size_t i = 0; i < names.size(); ++i) {
        const auto& n = names[i];
        if (n == name || (n.size() > name.size() && n.ends_with(name) && n[n.size() - name.size() - 1] == '.'))
            return i;
    }
    return std::nullopt;
}

CsvTable read_csv(const std::filesystem::path& file) {
    std::ifstream in(file);
    if (!in) throw CosimError("cannot read " + file.string());
    CsvTable table;
    std::string line;
    if (!std::getline(in, line)) throw CosimError(file.string() + ": empty");
    std::stringstream header(line);
    for (std::string cell; std::getline(header, cell, ',');) table.names.push_back(cell);
    table.columns.resize(table.names.size());
    std::size_t row = 1;
    while (std::getline(in, line)) {
        ++row;
        std::stringstream cells(line);
        std::size_t i = 0;
        for (std::string cell; std::getline(cells, cell, ','); ++i) {
            if (i >= table.columns.size()) throw CosimError(file.string() + ": row " + std::to_string(row) + " has too many cells");
            double x = std::numeric_limits<double>::quiet_NaN();
            std::from_chars(cell.data(), cell.data() + cell.size(), x);
            table.columns[i].push_back(x);
        }
        if (i != table.columns.size()) throw CosimError(file.string() + ": row " + std::to_string(row) + " is short");
    }
    return table;
}

}  // namespace cosim
