// Driving one FMU instance from the tests: the callbacks with a log recorder, typed get/set by
// variable, the experiment window, and running a risky call in a child process.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fmi_loader/fmu.hpp"

namespace conformance {

struct LogRecord {
    fmi2Status status;
    std::string category, message;
};

// Receives the FMU's log callback; one per instance (it is the componentEnvironment).
struct LogSink {
    std::vector<LogRecord> records;
    // Whether a message of at least `min_status` arrived after records[mark].
    bool has_since(std::size_t mark, fmi2Status min_status) const;
    std::string dump() const;
};

const char* status_name(fmi2Status s);

class Instance {
public:
    // Instantiates with logging on; check ok() (fmi2Instantiate may legitimately return NULL).
    Instance(fmi_loader::Fmu& fmu, fmi_loader::FmuKind kind, const std::string& name = "conformance",
             std::optional<std::string> guid = std::nullopt);
    ~Instance();
    Instance(const Instance&) = delete;
    Instance& operator=(const Instance&) = delete;

    bool ok() const noexcept { return c_ != nullptr; }
    fmi2Component c() const noexcept { return c_; }
    const fmi_loader::Fmi2Functions& f() const noexcept { return *f_; }
    const fmi_loader::ModelDescription& md() const noexcept { return *md_; }
    LogSink& log() noexcept { return *sink_; }
    std::size_t log_mark() const noexcept { return sink_->records.size(); }
    // Frees now (a test of the sequence wants to see it happen); idempotent.
    void free();

    // Setup + enter + exit initialization with the experiment window; returns the first bad status.
    fmi2Status initialize(double start_time, std::optional<double> stop_time);

    fmi2Status set_start(const fmi_loader::ScalarVariable& v);  // sets the variable to its start value
    fmi2Status set_real(std::uint32_t vr, double value);
    fmi2Status set_integer(std::uint32_t vr, int value);
    // Reads any variable; the value comes back as text ("1.5", "3", "true", "abc").
    fmi2Status get_text(const fmi_loader::ScalarVariable& v, std::string& text);
    fmi2Status get_real(std::uint32_t vr, double& value);

private:
    const fmi_loader::Fmi2Functions* f_;
    const fmi_loader::ModelDescription* md_;
    std::unique_ptr<LogSink> sink_;
    std::unique_ptr<fmi2CallbackFunctions> callbacks_;  // the FMU may keep the pointer (section 2.1.5)
    fmi2Component c_ = nullptr;
};

// The window the runs cover: the DefaultExperiment, cut to at most `max_seconds`.
struct Experiment {
    double start = 0.0, stop = 1.0, step = 0.01;
    std::size_t steps() const;
};
Experiment experiment_of(const fmi_loader::ModelDescription& md, double max_seconds = 3.0,
                         std::size_t max_steps = 1000);

// Value of every Real output, as bits: "bit-identical" comparisons are exact by construction.
std::vector<std::uint64_t> real_output_bits(Instance& inst);

// Runs `call` in a forked child so a crash is a test failure and not the end of the suite.
struct IsolatedResult {
    bool completed = false;      // the child returned normally
    std::string crash;           // why not, if it did not
    fmi2Status status = fmi2OK;  // what the checked call returned
    bool logged = false;         // whether the logger saw a message of at least fmi2Error (or the returned status)
    std::string log;
};
IsolatedResult run_isolated(const std::function<fmi2Status(bool& logged, std::string& log)>& call);

}  // namespace conformance
