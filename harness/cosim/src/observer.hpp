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
// asked for), full round-trip precision.
class CsvWriter : public Observer {
public:
    CsvWriter(const std::filesystem::path& file, const System& system, const std::vector<std::string>& columns);
    void sample(double t, System& system) override;

private:
    struct Column {
        std::size_t component;
        const fmi_loader::ScalarVariable* variable;
    };
    std::ofstream out_;
    std::vector<Column> columns_;
};

}  // namespace cosim
