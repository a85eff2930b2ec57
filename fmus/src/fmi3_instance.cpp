#include "fmi3_instance.hpp"

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <limits>

#include "fmi/vocabulary.hpp"
#include "fmu/description.hpp"
#include "fmu/errors.hpp"

namespace fmu::fmi3 {

namespace {

// The 2.0 instance logs through an FMI 2.0 callback; this one formats its message and hands it to the
// FMI 3.0 host's callback (the status values are the same numbers in both versions).
void forward_log(fmi2ComponentEnvironment environment, fmi2String, fmi2Status status, fmi2String category,
                 fmi2String format, ...) {
    const auto* self = static_cast<const Instance3*>(environment);
    va_list args;
    va_start(args, format);
    va_list copy;
    va_copy(copy, args);
    const int n = std::vsnprintf(nullptr, 0, format, copy);
    va_end(copy);
    std::string text(n > 0 ? static_cast<std::size_t>(n) : 0, '\0');
    if (n > 0) std::vsnprintf(text.data(), text.size() + 1, format, args);
    va_end(args);
    self->log(static_cast<fmi3Status>(status), category, text);
}

fmi2CallbackFunctions callbacks_for(Instance3* self) {
    return fmi2CallbackFunctions{forward_log, nullptr, nullptr, nullptr, self};
}

// "mag_body (Real)": a variable in a message.
std::string describe(const Variable& v) {
    return v.base_name + " (" + std::string(to_string(v.type)) + ")";
}

}  // namespace

Instance3::Instance3(std::string name, Kind kind, Options options, fmi3InstanceEnvironment environment,
                     fmi3LogMessageCallback logger, bool logging_on, std::unique_ptr<Model> model, std::string token)
    : name_(name),
      kind_(kind),
      options_(options),
      environment_(environment),
      logger_(logger),
      table_(model->table()),
      view_(model->table(), model->event_indicator_count()),
      inner_(std::move(name), kind, callbacks_for(this), logging_on, std::move(model), std::move(token)) {}

void Instance3::log(fmi3Status status, const char* category, const std::string& message) const {
    if (logger_) logger_(environment_, status, category, message.c_str());
}

void Instance3::require(Call call) const {
    if ((allowed_modes(call) & static_cast<std::uint32_t>(mode_)) == 0)
        throw Error(std::string(to_string(call)) + " is not allowed in " + std::string(to_string(mode_)));
}

void Instance3::require_kind(Kind kind, Call call) const {
    if (kind != kind_)
        throw Error(std::string(to_string(call)) + " is a " +
                    (kind == Kind::model_exchange ? "Model Exchange" : "Co-Simulation") +
                    " function, but this instance was instantiated for " +
                    (kind_ == Kind::model_exchange ? "Model Exchange" : "Co-Simulation"));
}

void Instance3::enter_error_mode() {
    mode_ = Mode::error;
    inner_.enter_error_mode();
}

void Instance3::enter_initialization_mode(bool tolerance_defined, double tolerance, double start_time,
                                          bool stop_defined, double stop_time) {
    inner_.setup_experiment(tolerance_defined, tolerance, start_time, stop_defined, stop_time);
    inner_.enter_initialization_mode();
    mode_ = Mode::initialization;
}

void Instance3::exit_initialization_mode() {
    inner_.exit_initialization_mode();
    // Model Exchange, and Co-Simulation with event mode, continue in Event Mode (the host's
    // fmi3UpdateDiscreteStates settles the start); Co-Simulation without it has settled the start
    // inside and steps.
    mode_ = kind_ == Kind::model_exchange || options_.event_mode_used ? Mode::event : Mode::step;
}

void Instance3::enter_event_mode() {
    if (kind_ == Kind::co_simulation && !options_.event_mode_used)
        throw Error("fmi3EnterEventMode: this Co-Simulation instance was instantiated with eventModeUsed = false");
    inner_.enter_event_mode();
    mode_ = Mode::event;
}

void Instance3::terminate() {
    inner_.terminate();
    mode_ = Mode::terminated;
}

void Instance3::reset() {
    inner_.reset();
    mode_ = Mode::instantiated;
}

const Fmi3Variable& Instance3::variable(fmi3ValueReference vr) const {
    const Fmi3Variable* v = view_.find(vr);
    if (!v) throw Error("unknown value reference " + std::to_string(vr));
    return *v;
}

std::span<const fmi3ValueReference> Instance3::expand(std::span<const fmi3ValueReference> vr, ValueType type,
                                                      std::size_t n_values, bool for_set) {
    if (!vr.empty() && !vr.data()) throw Error("null value-reference array with nValueReferences > 0");
    scratch_.clear();
    for (const fmi3ValueReference r : vr) {
        if (for_set && r == view_.time_reference())
            throw Error("time (value reference " + std::to_string(r) + ") is set with fmi3SetTime, not a setter");
        if (for_set && view_.event_indicator_count() > 0 && r == view_.event_indicators_reference())
            throw Error("event_indicators (value reference " + std::to_string(r) + ") cannot be set");
        const Fmi3Variable& v = variable(r);
        const Variable& first = table_.variables()[v.first];
        if (first.type != type)
            throw Error("value reference " + std::to_string(r) + " is " + describe(first) + ", not " +
                        std::string(fmi_vocabulary::spelling(fmi_vocabulary::types_fmi3, type)));
        const auto elements = view_.element_references(v);
        scratch_.insert(scratch_.end(), elements.begin(), elements.end());
    }
    if (scratch_.size() != n_values)
        throw Error("the value references name " + std::to_string(scratch_.size()) + " values, but nValues is " +
                    std::to_string(n_values));
    return scratch_;
}

void Instance3::get_float64(std::span<const fmi3ValueReference> vr, std::span<fmi3Float64> values) {
    if (!vr.empty() && (!vr.data() || !values.data())) throw Error("fmi3GetFloat64: null array");
    std::size_t at = 0;
    for (const fmi3ValueReference r : vr) {
        // Time and the event indicators are no table variables; the rest is read a variable at a time.
        const bool time = r == view_.time_reference();
        const bool indicators = !time && view_.event_indicator_count() > 0 && r == view_.event_indicators_reference();
        const Fmi3Variable* v = time || indicators ? nullptr : &variable(r);
        if (v && table_.variables()[v->first].type != ValueType::Real)
            throw Error("value reference " + std::to_string(r) + " is " + describe(table_.variables()[v->first]) +
                        ", not Float64");
        const std::size_t n = time ? 1 : indicators ? view_.event_indicator_count() : v->count;
        if (at + n > values.size())
            throw Error("fmi3GetFloat64: nValues = " + std::to_string(values.size()) +
                        " is fewer than the values named");
        if (time)
            values[at] = inner_.time();
        else if (indicators)
            inner_.get_event_indicators(values.subspan(at, n));
        else
            inner_.get_real(view_.element_references(*v), values.data() + at);
        at += n;
    }
    if (at != values.size())
        throw Error("fmi3GetFloat64: the value references name " + std::to_string(at) + " values, but nValues is " +
                    std::to_string(values.size()));
}

void Instance3::get_int32(std::span<const fmi3ValueReference> vr, std::span<fmi3Int32> values) {
    const auto elements = expand(vr, ValueType::Integer, values.size(), false);
    inner_.get_integer(elements, values.data());
}

void Instance3::get_int64(std::span<const fmi3ValueReference> vr, std::span<fmi3Int64> values) {
    const auto elements = expand(vr, ValueType::Enumeration, values.size(), false);
    std::vector<fmi2Integer> narrow(elements.size());
    inner_.get_integer(elements, narrow.data());
    std::copy(narrow.begin(), narrow.end(), values.begin());
}

void Instance3::get_boolean(std::span<const fmi3ValueReference> vr, std::span<fmi3Boolean> values) {
    const auto elements = expand(vr, ValueType::Boolean, values.size(), false);
    std::vector<fmi2Boolean> ints(elements.size());
    inner_.get_boolean(elements, ints.data());
    for (std::size_t i = 0; i < ints.size(); ++i) values[i] = ints[i] != fmi2False;
}

void Instance3::get_string(std::span<const fmi3ValueReference> vr, std::span<fmi3String> values) {
    const auto elements = expand(vr, ValueType::String, values.size(), false);
    inner_.get_string(elements, values.data());
}

void Instance3::set_float64(std::span<const fmi3ValueReference> vr, std::span<const fmi3Float64> values) {
    const auto elements = expand(vr, ValueType::Real, values.size(), true);
    inner_.set_real(elements, values.data());
}

void Instance3::set_int32(std::span<const fmi3ValueReference> vr, std::span<const fmi3Int32> values) {
    const auto elements = expand(vr, ValueType::Integer, values.size(), true);
    inner_.set_integer(elements, values.data());
}

void Instance3::set_int64(std::span<const fmi3ValueReference> vr, std::span<const fmi3Int64> values) {
    const auto elements = expand(vr, ValueType::Enumeration, values.size(), true);
    std::vector<fmi2Integer> narrow(elements.size());
    for (std::size_t i = 0; i < narrow.size(); ++i) {
        // An Enumeration's items are 32-bit here (the block's enum): a wider value is no item.
        if (values[i] < std::numeric_limits<fmi2Integer>::min() || values[i] > std::numeric_limits<fmi2Integer>::max())
            throw Error("fmi3SetInt64: " + std::to_string(values[i]) + " is no item of " +
                        table_.variables()[view_.owner(elements[i]).first].declared_type);
        narrow[i] = static_cast<fmi2Integer>(values[i]);
    }
    inner_.set_integer(elements, narrow.data());
}

void Instance3::set_boolean(std::span<const fmi3ValueReference> vr, std::span<const fmi3Boolean> values) {
    const auto elements = expand(vr, ValueType::Boolean, values.size(), true);
    std::vector<fmi2Boolean> ints(elements.size());
    for (std::size_t i = 0; i < ints.size(); ++i) ints[i] = values[i] ? fmi2True : fmi2False;
    inner_.set_boolean(elements, ints.data());
}

void Instance3::set_string(std::span<const fmi3ValueReference> vr, std::span<const fmi3String> values) {
    const auto elements = expand(vr, ValueType::String, values.size(), true);
    inner_.set_string(elements, values.data());
}

void Instance3::refuse_type(const char* function, std::span<const fmi3ValueReference> vr) const {
    if (vr.empty() || !vr.data()) throw Error(std::string(function) + ": this FMU has no variable of its type");
    if (vr[0] == view_.time_reference() ||
        (view_.event_indicator_count() > 0 && vr[0] == view_.event_indicators_reference()))
        throw Error(std::string(function) + ": value reference " + std::to_string(vr[0]) + " is a Float64");
    const Variable& first = table_.variables()[variable(vr[0]).first];
    throw Error(std::string(function) + ": value reference " + std::to_string(vr[0]) + " is " + describe(first) +
                "; this FMU has no variable of the type " + function + " accesses");
}

Snapshot* Instance3::get_state(Snapshot* reuse) {
    Snapshot* s = inner_.get_state(reuse);
    snapshot_modes_[s] = mode_;
    return s;
}

void Instance3::set_state(const Snapshot* state) {
    inner_.set_state(state);
    // Out of the error mode a restore continues in the mode the state was taken in (a deserialized
    // one: after initialization, in Event Mode for Model Exchange and Step Mode for Co-Simulation).
    if (mode_ == Mode::error) {
        const auto it = snapshot_modes_.find(state);
        mode_ = it != snapshot_modes_.end() ? it->second : (kind_ == Kind::model_exchange ? Mode::event : Mode::step);
    }
}

void Instance3::free_state(Snapshot* state) {
    inner_.free_state(state);
    snapshot_modes_.erase(state);
}

Snapshot* Instance3::deserialize(std::span<const fmi3Byte> bytes) {
    return inner_.deserialize(std::span<const fmi2Byte>(reinterpret_cast<const fmi2Byte*>(bytes.data()), bytes.size()));
}

Instance3::DiscreteUpdate Instance3::update_discrete_states() {
    fmi2EventInfo info{};
    inner_.new_discrete_states(info);
    DiscreteUpdate u;
    u.again = info.newDiscreteStatesNeeded != fmi2False;
    u.terminate = info.terminateSimulation != fmi2False;
    u.states_changed = info.valuesOfContinuousStatesChanged != fmi2False;
    u.next_defined = info.nextEventTimeDefined != fmi2False;
    u.next_time = info.nextEventTime;
    return u;
}

void Instance3::enter_continuous_time_mode() {
    inner_.enter_continuous_time_mode();
    mode_ = Mode::continuous_time;
}

void Instance3::enter_step_mode() {
    mode_ = Mode::step;
}

std::size_t Instance3::state_count() const {
    return table_.states().size();
}

Instance3::StepResult Instance3::do_step(double current_time, double step_size) {
    // With event mode the host runs the discrete updates: the step stops at an event inside it when the
    // host allows an early return, and leaves one due at its end in any case.
    // An intermediate-update callback decides at each event inside the step (canReturnEarly): the step
    // stops there when the host requests an early return, else the event is handled inside. The
    // step stops at the event's time whatever earlyReturnTime the host names: the event needs the
    // host's Event Mode there.
    // Named here with FMI 3.0's arguments (the 2.0 instance below words its refusals for fmi2DoStep).
    if (!std::isfinite(current_time))
        throw Error("fmi3DoStep: currentCommunicationPoint must be finite (got " + format_real(current_time) + ")");
    if (!std::isfinite(step_size) || step_size < 0.0)
        throw Error("fmi3DoStep: communicationStepSize must be finite and non-negative (got " + format_real(step_size) +
                    ")");
    using H = CsSolver::HostEvents;
    const bool ask = options_.event_mode_used && options_.early_return_allowed && options_.intermediate_update;
    H host_events = H::none;
    if (ask)
        host_events = H::ask;
    else if (options_.event_mode_used)
        host_events = options_.early_return_allowed ? H::all : H::at_end;
    std::function<bool(double)> host_wants;
    if (ask)
        host_wants = [this](double t) {
            fmi3Boolean requested = false;
            fmi3Float64 early_return_time = t;
            // The callback runs in Intermediate Update Mode: what the host calls from inside it is checked
            // against that mode's row of the call-rule table (fmi3DoStep there would be a step inside this one).
            mode_ = Mode::intermediate_update;
            in_callback_ = true;
            options_.intermediate_update(environment_, t, false, false, false, true, &requested, &early_return_time);
            in_callback_ = false;
            if (mode_ == Mode::error)
                throw Error("fmi3DoStep: a call from inside the intermediate-update callback at t = " + format_real(t) +
                            " was refused (its message came before): the step is abandoned");
            mode_ = Mode::step;
            return static_cast<bool>(requested);
        };
    StepResult r;
    bool event_pending = false;
    r.status =
        static_cast<fmi3Status>(inner_.do_step(current_time, step_size, host_events, &event_pending, host_wants));
    r.last_successful_time = inner_.time();
    r.event_handling_needed = event_pending;
    r.early_return = event_pending && !reached(r.last_successful_time, current_time + step_size);
    r.terminate = r.status == fmi3Discard;
    if (r.terminate) r.status = fmi3OK;  // FMI 3.0 says so with terminateSimulation, not a status
    return r;
}

}  // namespace fmu::fmi3
