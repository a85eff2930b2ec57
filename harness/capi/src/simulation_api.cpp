// pvatt_start, pvatt_advance_to, pvatt_simulation_*: a run that pauses at output points.
//
// The engine's execution runs a system from start to stop in one call. Stepping keeps that one code
// path (so a stepped run computes exactly what a whole run does): the execution runs on a thread of its
// own and waits inside its output-point observer until the caller asks for a later time. Only one of
// the two threads touches the system at any moment: the caller while the run waits, the run otherwise.
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "capi_error.hpp"
#include "capi_handles.hpp"
#include "engine/cosim_error.hpp"
#include "engine/fmi2_instance.hpp"
#include "engine/fmi3_instance.hpp"
#include "engine/interrupt.hpp"
#include "engine/setting.hpp"
#include "engine/value_text.hpp"

using namespace pvatt_capi;

namespace {

// Thrown inside the run's thread when the caller frees a paused simulation: unwinds the execution.
struct Cancelled {};

}  // namespace

struct pvatt_simulation {
    // First, so released last: the system stays allocated while the run's thread may use it, also when
    // pvatt_system_close comes first.
    std::unique_ptr<SystemUse> use;
    pvatt_system* owner = nullptr;
    std::unique_ptr<cosim::System> system;
    cosim::ExecutionOptions ex;
    pvatt_result result;
    std::unique_ptr<Recorder> recorder;

    mutable std::mutex mutex;
    std::condition_variable changed;
    double target = 0.0;  // the output point to pause at
    double time = 0.0;    // where the run is (paused or finished)
    bool running = false, finished = false, cancel = false;
    std::exception_ptr error;
    std::thread thread;

    // The observer the execution calls at every output point: records the row, then waits there when
    // it is the point asked for.
    struct Gate : cosim::Observer {
        pvatt_simulation& sim;
        explicit Gate(pvatt_simulation& s) : sim(s) {}
        void sample(double t, cosim::System& system) override {
            sim.recorder->sample(t, system);
            const double tiny = 1e-12 * std::max(1.0, std::abs(sim.ex.stop_time));
            if (t < sim.target - tiny || t >= sim.ex.stop_time - tiny) return;
            std::unique_lock lock(sim.mutex);
            sim.time = t;
            sim.running = false;
            sim.changed.notify_all();
            sim.changed.wait(lock, [&] { return sim.running || sim.cancel; });
            if (sim.cancel) throw Cancelled{};
        }
    } gate{*this};

    void body() {
        try {
            cosim::Execution(*system, ex).run({&gate});
            std::lock_guard lock(mutex);
            time = recorder->last_time();
        } catch (const Cancelled&) {
        } catch (...) {
            std::lock_guard lock(mutex);
            error = std::current_exception();
            time = recorder->last_time();
        }
        std::lock_guard lock(mutex);
        finished = true;
        running = false;
        changed.notify_all();
    }

    // Lets the run go on to `target` and waits until it pauses there, finishes or fails.
    void go() {
        BlockingCall blocking;
        std::unique_lock lock(mutex);
        running = true;
        if (!thread.joinable())
            thread = std::thread([this] { body(); });
        else
            changed.notify_all();
        changed.wait(lock, [&] { return !running; });
        if (!error) return;
        try {
            std::rethrow_exception(std::exchange(error, nullptr));
        } catch (const cosim::Interrupted&) {
            blocking.reported();
            throw;
        }
    }

    ~pvatt_simulation() {
        if (!thread.joinable()) return;
        {
            std::lock_guard lock(mutex);
            cancel = true;
            changed.notify_all();
        }
        thread.join();
    }
};

namespace {

// An open simulation whose run is not running now: the run's thread and the caller never touch it at
// once (a callback of the run itself, or another thread during pvatt_advance_to, is refused).
pvatt_simulation& paused(const pvatt_simulation* s, const char* function) {
    auto& sim = open_simulation(s);
    std::lock_guard lock(sim.mutex);
    if (sim.running)
        throw WrongState(std::string(function) +
                         ": the simulation is running (called from its own callback component, or from another "
                         "thread during pvatt_advance_to); call it once pvatt_advance_to has returned");
    return sim;
}

bool usable(const pvatt_simulation* s) {
    return guarded([&] { open_simulation(s); }) == PVATT_OK;
}

// What a paused run may be given (checked before the FMU sees it, which would otherwise enter its error
// state and never step again): an input or a tunable parameter, with a value of its type and range.
void check_settable_while_paused(const cosim::Component& c, const fmi_loader::ScalarVariable& v,
                                 const std::string& name, const std::string& text) {
    using fmi_loader::Causality;
    const bool input = v.causality == Causality::input;
    const bool tunable = v.causality == Causality::parameter && v.variability == fmi_loader::Variability::tunable;
    if (!input && !tunable)
        throw InvalidArgument(name + " is a " + std::string(fmi_loader::to_string(v.variability)) + " " +
                              std::string(fmi_loader::to_string(v.causality)) +
                              ": while a run is paused only inputs and tunable parameters can be set");
    // A Model Exchange FMU is paused in Continuous-Time Mode, where FMI (2.0 and 3.0) lets a host set only
    // continuous inputs: a discrete input or a tunable parameter needs Event Mode, which a paused run is
    // not in.
    const bool fmu = dynamic_cast<const cosim::Fmi2Instance*>(c.instance.get()) ||
                     dynamic_cast<const cosim::Fmi3Instance*>(c.instance.get());
    if (fmu && c.interface == cosim::Interface::model_exchange &&
        !(input && v.variability == fmi_loader::Variability::continuous))
        throw InvalidArgument(name + " is a " + std::string(fmi_loader::to_string(v.variability)) + " " +
                              std::string(fmi_loader::to_string(v.causality)) + " of " + c.name +
                              ", which runs as Model Exchange: paused, it is in Continuous-Time Mode, where only "
                              "continuous inputs can be set (set it before the run, with pvatt_system_set)");
    try {
        const auto x = cosim::typed_value(c.description(), v, {c.name, v.name, text, ""}, name);
        if (const auto* r = std::get_if<double>(&x)) cosim::check_value(c.description(), v, *r, name);
        if (const auto* i = std::get_if<fmi2Integer>(&x)) cosim::check_value(c.description(), v, *i, name);
    } catch (const cosim::CosimError& e) {
        throw InvalidArgument(e.what());
    }
}

}  // namespace

extern "C" {

pvatt_status pvatt_start(pvatt_system* system, const pvatt_run_options* options, const char* const* columns,
                         size_t column_count, pvatt_simulation** out) {
    return guarded([&] {
        required(out, "out");
        *out = nullptr;
        open_system(system);
        refuse_in_callback("pvatt_start");
        auto sim = std::make_unique<pvatt_simulation>();
        sim->use = std::make_unique<SystemUse>(system);
        sim->owner = system;
        sim->system = build_system(*system, options && options->reference);
        sim->ex = execution_options(*system, *sim->system, options);
        sim->recorder = std::make_unique<Recorder>(*sim->system, columns, column_count, sim->result);
        sim->target = sim->time = sim->ex.start_time;
        sim->go();
        register_handle(sim.get());
        *out = sim.release();
    });
}

pvatt_status pvatt_advance_to(pvatt_simulation* simulation, double t) {
    return guarded([&] {
        refuse_in_callback("pvatt_advance_to");
        auto& sim = paused(simulation, "pvatt_advance_to");
        if (!std::isfinite(t)) throw InvalidArgument("advance_to: the time must be finite");
        const double start = sim.ex.start_time, h = sim.ex.output_interval, stop = sim.ex.stop_time;
        const double k = std::round((t - start) / h);
        const double target = std::min(start + k * h, stop);
        const double tiny = 1e-12 * std::max(1.0, std::abs(stop));
        if (target < sim.time - tiny)
            throw WrongState("advance_to(" + cosim::format_real(t) +
                             "): the simulation is at t = " + cosim::format_real(sim.time) + " s and does not go back");
        if (target <= sim.time + tiny) return;
        if (sim.finished) throw WrongState("the simulation has finished at t = " + cosim::format_real(sim.time) + " s");
        sim.target = target;
        sim.go();
    });
}

double pvatt_simulation_time(const pvatt_simulation* simulation) {
    if (!usable(simulation)) return NAN;
    std::lock_guard lock(simulation->mutex);
    return simulation->time;
}

int pvatt_simulation_finished(const pvatt_simulation* simulation) {
    if (!usable(simulation)) return 0;
    std::lock_guard lock(simulation->mutex);
    return simulation->finished ? 1 : 0;
}

pvatt_status pvatt_simulation_get_real(pvatt_simulation* simulation, const char* name, double* value) {
    return guarded([&] {
        auto& sim = paused(simulation, "pvatt_simulation_get_real");
        required(value, "value");
        const auto ref = find_variable(*sim.system, required(name, "name"));
        auto& instance = *sim.system->components()[ref.component].instance;
        const auto vr = ref.variable->value_reference;
        switch (ref.variable->type) {
            case fmi_loader::VariableType::real:
                *value = instance.get_real(vr);
                return;
            case fmi_loader::VariableType::integer:
            case fmi_loader::VariableType::enumeration:
                *value = instance.get_integer(vr);
                return;
            case fmi_loader::VariableType::boolean:
                *value = instance.get_boolean(vr) ? 1.0 : 0.0;
                return;
            case fmi_loader::VariableType::string:
                throw InvalidArgument(std::string(name) + " is a String: read it as text");
        }
    });
}

pvatt_status pvatt_simulation_set_real(pvatt_simulation* simulation, const char* name, double value) {
    return pvatt_simulation_set_text(simulation, name, cosim::format_real(value).c_str());
}

pvatt_status pvatt_simulation_get_text(pvatt_simulation* simulation, const char* name, char* buffer, size_t size,
                                       size_t* needed) {
    return guarded([&] {
        auto& sim = paused(simulation, "pvatt_simulation_get_text");
        const auto ref = find_variable(*sim.system, required(name, "name"));
        auto& c = sim.system->components()[ref.component];
        std::string text = c.instance->get_as_text(*ref.variable);
        // A choice by its name, as it is set.
        if (const auto* type = c.description().find_type(ref.variable->declared_type);
            type && ref.variable->type == fmi_loader::VariableType::enumeration)
            for (const auto& item : type->items)
                if (std::to_string(item.value) == text) text = item.name;
        copy_text(text, buffer, size, needed);
    });
}

pvatt_status pvatt_simulation_set_text(pvatt_simulation* simulation, const char* name, const char* value) {
    return guarded([&] {
        auto& sim = paused(simulation, "pvatt_simulation_set_text");
        if (sim.finished) throw WrongState("the simulation has finished");
        const std::string n(required(name, "name"));
        const auto ref = find_variable(*sim.system, n);
        auto& c = sim.system->components()[ref.component];
        const std::string text(required(value, "value"));
        check_settable_while_paused(c, *ref.variable, n, text);
        c.instance->apply({c.name, ref.variable->name, text, ""});
    });
}

pvatt_status pvatt_simulation_result(const pvatt_simulation* simulation, pvatt_result** out) {
    return guarded([&] {
        required(out, "out");
        *out = nullptr;
        const auto& sim = paused(simulation, "pvatt_simulation_result");
        auto copy = std::make_unique<pvatt_result>(sim.result);
        register_handle(copy.get());
        *out = copy.release();
    });
}

void pvatt_simulation_free(pvatt_simulation* simulation) {
    if (!simulation) return;
    // Refused (the handle stays open, the last error says why) while its run is running: from its own
    // callback that would join the thread it is on.
    const pvatt_status status = guarded([&] {
        paused(simulation, "pvatt_simulation_free");
        if (!unregister_handle(simulation)) throw InvalidArgument("simulation is not open");
    });
    if (status == PVATT_OK) delete simulation;
}

}  // extern "C"
