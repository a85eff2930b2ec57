#include "engine/csv_table.hpp"

#include <charconv>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>

#include "engine/cosim_error.hpp"

namespace cosim {

std::optional<std::size_t> CsvTable::find(const std::string& name) const {
    for (std::size_t i = 0; i < names.size(); ++i) {
        const auto& n = names[i];
        if (n == name || (n.size() > name.size() && n.ends_with(name) && n[n.size() - name.size() - 1] == '.'))
            return i;
    }
    return std::nullopt;
}

std::string csv_field(std::string_view text) {
    if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
    std::string out = "\"";
    for (const char c : text) {
        if (c == '"') out += '"';
        out += c;
    }
    return out + "\"";
}

namespace {

// The fields of one line, RFC 4180 quoting undone.
std::vector<std::string> split_fields(const std::string& line, const std::filesystem::path& file, std::size_t row) {
    std::vector<std::string> fields;
    std::string field;
    bool quoted = false, was_quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted) {
            if (c != '"')
                field += c;
            else if (i + 1 < line.size() && line[i + 1] == '"')
                field += line[++i];
            else
                quoted = false;
        } else if (c == '"' && field.empty() && !was_quoted) {
            quoted = was_quoted = true;
        } else if (c == ',') {
            fields.push_back(std::move(field));
            field.clear();
            was_quoted = false;
        } else {
            field += c;
        }
    }
    if (quoted) throw CosimError(file.string() + ": row " + std::to_string(row) + " has an unterminated quoted field");
    fields.push_back(std::move(field));
    return fields;
}

}  // namespace

CsvTable read_csv(const std::filesystem::path& file) {
    std::ifstream in(file);
    if (!in) throw CosimError("cannot read " + file.string());
    CsvTable table;
    std::string line;
    if (!std::getline(in, line)) throw CosimError(file.string() + ": empty");
    if (!line.empty() && line.back() == '\r') line.pop_back();
    table.names = split_fields(line, file, 1);
    table.columns.resize(table.names.size());
    std::size_t row = 1;
    while (std::getline(in, line)) {
        ++row;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        const auto cells = split_fields(line, file, row);
        if (cells.size() > table.columns.size())
            throw CosimError(file.string() + ": row " + std::to_string(row) + " has too many cells");
        if (cells.size() < table.columns.size())
            throw CosimError(file.string() + ": row " + std::to_string(row) + " is short");
        for (std::size_t i = 0; i < cells.size(); ++i) {
            double x = std::numeric_limits<double>::quiet_NaN();
            // Blanks around a number are allowed (other tools pad their cells: OMSimulator writes " 13").
            std::string_view cell = cells[i];
            while (!cell.empty() && (cell.front() == ' ' || cell.front() == '\t')) cell.remove_prefix(1);
            while (!cell.empty() && (cell.back() == ' ' || cell.back() == '\t')) cell.remove_suffix(1);
            std::from_chars(cell.data(), cell.data() + cell.size(), x);
            table.columns[i].push_back(x);
        }
    }
    return table;
}

}  // namespace cosim
