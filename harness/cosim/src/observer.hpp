// Passive watchers of a run, called at output points (and, on request, just before and after each
// event). The CSV writer is one; the run statistics are gathered by the execution itself.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "system.hpp"

namespace cosim {

class Observer {
public:
    virtual ~Observer() = default;
    virtual void sample(double t, System& system) = 0;
};

// Header `time` then `component.variable` for every output of every component (or the columns
// asked for), full round-trip precision, fields quoted per RFC 4180 where needed. Every write is
// checked: a full disk is a CosimError naming the file and the reason, never a short file and exit 0.
class CsvWriter : public Observer {
public:
    CsvWriter(const std::filesystem::path& file, const System& system, const std::vector<std::string>& columns);
    void sample(double t, System& system) override;
    // Flush and close, checked. Call it after the run (also after an interrupted one); the destructor
    // closes without a check.
    void close();
    std::size_t columns() const { return columns_.size() + 1; }
    long rows() const { return rows_; }
    const std::filesystem::path& path() const { return path_; }

private:
    void check();
    struct Column {
        std::size_t component;
        const fmi_loader::ScalarVariable* variable;
    };
    std::filesystem::path path_;
    std::ofstream out_;
    std::vector<Column> columns_;
    long rows_ = 0;
};

}  // namespace cosim
