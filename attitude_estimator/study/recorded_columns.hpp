// The columns of a run the master recorded (`cosim run --output`, a CSV with one header line), read for
// the study programs of this folder without linking the master (a block's folder stands below harness/:
// tests/layering). Fields quoted as RFC 4180 has them are unquoted; a cell that is no number reads NaN.
#pragma once

#include <charconv>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace attitude_estimator::study {

class RecordedColumns {
public:
    explicit RecordedColumns(const std::string& file) : file_(file) {
        std::ifstream in(file);
        std::string line;
        if (!in || !std::getline(in, line)) throw std::runtime_error("cannot read a header line from " + file);
        names_ = fields(line);
        columns_.resize(names_.size());
        for (std::size_t row = 2; std::getline(in, line); ++row) {
            const auto cells = fields(line);
            if (cells.size() != names_.size())
                throw std::runtime_error(file + ": row " + std::to_string(row) + " has " +
                                         std::to_string(cells.size()) + " cells, the header " +
                                         std::to_string(names_.size()));
            for (std::size_t i = 0; i < cells.size(); ++i) {
                double x = std::numeric_limits<double>::quiet_NaN();
                std::from_chars(cells[i].data(), cells[i].data() + cells[i].size(), x);
                columns_[i].push_back(x);
            }
        }
    }

    bool has(std::string_view name) const { return index(name) < names_.size(); }
    // The column named `name` exactly ("est.valid"); throws naming the file when there is none.
    const std::vector<double>& operator()(std::string_view name) const {
        const std::size_t i = index(name);
        if (i == names_.size()) throw std::runtime_error("column " + std::string(name) + " missing from " + file_);
        return columns_[i];
    }

private:
    std::size_t index(std::string_view name) const {
        std::size_t i = 0;
        while (i < names_.size() && names_[i] != name) ++i;
        return i;
    }
    static std::vector<std::string> fields(std::string line) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::vector<std::string> out(1);
        bool quoted = false;
        for (std::size_t i = 0; i < line.size(); ++i) {
            const char c = line[i];
            if (c == '"' && quoted && i + 1 < line.size() && line[i + 1] == '"')
                out.back() += line[++i];
            else if (c == '"')
                quoted = !quoted;
            else if (c == ',' && !quoted)
                out.emplace_back();
            else
                out.back() += c;
        }
        return out;
    }

    std::string file_;
    std::vector<std::string> names_;
    std::vector<std::vector<double>> columns_;
};

}  // namespace attitude_estimator::study
