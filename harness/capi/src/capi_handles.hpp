// What the C API's opaque handles hold, and the pieces the run and the stepping share.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "capi_registry.hpp"
#include "engine/execution.hpp"
#include "engine/observer.hpp"
#include "engine/system.hpp"
#include "pvatt/cosim.h"

struct pvatt_system {
    cosim::SystemDescription description;
    cosim::SystemOptions options;  // FMU folders, Co-Simulation of a lone FMU without Model Exchange
    // Loaded once at open: the components' FMUs and descriptions for listing and checking (never run).
    std::unique_ptr<cosim::System> loaded;
    std::vector<std::pair<std::string, std::string>> settings;  // "comp.var", value; in the order given
    struct Replacement {
        double period;
        pvatt_step_callback callback;
        void* user_data;
        bool current_inputs = false;  // pvatt_system_replace_current_inputs
    };
    std::map<std::string, Replacement> replacements;  // by component name
    // The strings pvatt_system_variable hands out, built on first ask: [component][variable].
    struct VariableStrings {
        std::vector<std::string> items;
        std::vector<const char*> item_names;
        std::vector<int> item_values;
    };
    std::vector<std::vector<std::unique_ptr<VariableStrings>>> variable_strings;
    // Runs and simulations using it, and whether pvatt_system_close came (capi_registry.hpp): guarded by
    // the registry's lock.
    std::size_t users = 0;
    bool closed = false;
};

struct pvatt_result {
    std::vector<std::string> names;  // "time" first
    std::vector<double> data;        // row-major
    std::size_t rows() const { return names.empty() ? 0 : data.size() / names.size(); }
};

namespace pvatt_capi {

// A variable of a loaded system by its "component.variable" name; InvalidArgument when unknown.
struct VariableRef {
    std::size_t component;
    const fmi_loader::ScalarVariable* variable;
};
VariableRef find_variable(const cosim::System& system, const std::string& name);

// The columns a run records: the named ones (Strings refused), or every output of every component.
// Rows are appended to a result at each output point, with an interrupt check as `cosim run` has.
class Recorder : public cosim::Observer {
public:
    Recorder(const cosim::System& system, const char* const* columns, std::size_t count, pvatt_result& result);
    void sample(double t, cosim::System& system) override;
    double last_time() const { return last_time_; }

private:
    std::vector<VariableRef> columns_;
    pvatt_result& result_;
    double last_time_ = 0.0;
};

// A fresh System for one run: the description, the settings in order, the callback components in
// place of their FMUs.
std::unique_ptr<cosim::System> build_system(const pvatt_system& handle, bool reference);

// The execution options of a run as `cosim run` chooses them (start, stop, output interval, tolerance).
cosim::ExecutionOptions execution_options(const pvatt_system& handle, const cosim::System& system,
                                          const pvatt_run_options* options);

// A run or a simulation using a system while alive (acquire / release in capi_registry.hpp).
class SystemUse {
public:
    explicit SystemUse(pvatt_system* s) : system_(s) { acquire(s); }
    ~SystemUse() { release(system_); }
    SystemUse(const SystemUse&) = delete;
    SystemUse& operator=(const SystemUse&) = delete;

private:
    pvatt_system* system_;
};

// While alive (and pvatt_catch_sigint is on), SIGINT sets the interrupt flag; the previous action is
// restored after. The interrupt flag is cleared when it starts and when it ends. A SIGINT that came too late to stop the
// call (the run ended first, or on another thread just before it did) is raised again once the previous
// action is back, so the caller's own handler still sees it; one the call reported as PVATT_INTERRUPTED
// (reported()) is not.
class BlockingCall {
public:
    BlockingCall();
    ~BlockingCall();
    BlockingCall(const BlockingCall&) = delete;
    BlockingCall& operator=(const BlockingCall&) = delete;
    void reported() { reported_ = true; }

private:
    bool installed_ = false;
    bool reported_ = false;
};

}  // namespace pvatt_capi
