// Passive watchers of a run, called at output points (and, on request, just before and after each
// event). The CSV writer is one; the run statistics are gathered by the execution itself.
#pragma once

#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "engine/output_file.hpp"
#include "engine/system.hpp"

namespace cosim {

class Observer {
public:
    virtual ~Observer() = default;
    virtual void sample(double t, System& system) = 0;
    // Called between integrator steps and events (often, cheaply): a chance to flush what is buffered.
    virtual void between_steps() {}
};

// Put first: notices a signal (install_interrupt_handlers) at an output point, the one place a run may
// stop cleanly, by throwing Interrupted; remembers the last point passed.
struct InterruptCheck : Observer {
    double last_time = 0.0;
    void sample(double t, System& system) override;
};

// A value a run reports: a variable of a component. The columns named (`component.variable`), or
// every output of every component when none are.
struct OutputColumn {
    std::size_t component;
    const fmi_loader::ScalarVariable* variable;
};
std::vector<OutputColumn> output_columns(const System& system, const std::vector<std::string>& names);

// Header `time` then `component.variable` (or the variable's name alone: `qualified` false, for a
// one-component run) for every output of every component (or the columns asked for), full round-trip precision, fields quoted per RFC 4180 where needed. Every write is
// checked: a full disk is a CosimError naming the file and the reason, never a short file and exit 0.
// The columns are checked before anything is written; the file is written under a temporary name and
// takes its own name at the first row (the run has started: an existing file is never lost to a run
// refused before it); a row is on disk within csv_flush_interval of wall time plus one integrator
// step or event (between_steps), so a SIGKILL loses at most the rows of the last second or so.
inline constexpr std::chrono::seconds csv_flush_interval{1};

class CsvWriter : public Observer {
public:
    CsvWriter(const std::filesystem::path& file, const System& system, const std::vector<std::string>& columns,
              bool qualified = true);
    void sample(double t, System& system) override;
    void between_steps() override;
    // Flush and close, checked. Call it after the run (also after an interrupted one); the destructor
    // closes without a check.
    void close();
    std::size_t columns() const { return columns_.size() + 1; }
    long rows() const { return rows_; }
    const std::filesystem::path& path() const { return path_; }

private:
    void check();
    std::filesystem::path path_;
    std::unique_ptr<PendingFile> pending_;
    std::ofstream out_;
    std::chrono::steady_clock::time_point last_flush_;
    bool unflushed_ = false;
    std::vector<OutputColumn> columns_;
    long rows_ = 0;
};

}  // namespace cosim
