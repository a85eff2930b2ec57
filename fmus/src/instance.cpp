#include "instance.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

#include "fmu/description.hpp"
#include "fmu/errors.hpp"
#include "fmu/state_check.hpp"
#include "fmu/value_access.hpp"
#include "fmu/value_check.hpp"

namespace fmu {

namespace {

// Version 2 of the layout: header, block bytes, then an FNV-1a 64 checksum over everything before it
// (catches a truncated, corrupted or edited payload; the invariant checks catch the rest).
constexpr char serial_magic[8] = {'P', 'V', 'A', 'T', 'F', 'M', 'U', '2'};
constexpr std::size_t serial_guid_bytes = 40;
constexpr std::size_t serial_header = sizeof serial_magic + 8 + 8 + 8 + 1 + serial_guid_bytes;
constexpr std::size_t serial_checksum = 8;

constexpr std::size_t category_index(std::string_view name) {
    for (std::size_t i = 0; i < std::size(log_categories); ++i)
        if (name == log_categories[i]) return i;
    return std::size(log_categories);
}

// Looked up once: category_on runs on every FMI call (log_call), and the lookup compares C strings.
constexpr std::size_t kLogAll = category_index("logAll");
static_assert(kLogAll + 1 == std::size(log_categories), "Instance::logs_calls() reads the last category");

std::string format_time(double t) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", t);
    return buf;
}

}  // namespace

Instance::Instance(std::string name, Kind kind, const fmi2CallbackFunctions& callbacks, bool logging_on,
                   std::unique_ptr<Model> model, std::string guid)
    : name_(std::move(name)),
      guid_(std::move(guid)),
      kind_(kind),
      logger_(callbacks.logger),
      environment_(callbacks.componentEnvironment),
      category_enabled_(std::size(log_categories), logging_on),
      runner_(std::move(model)),
      access_(access_of(runner_.table().variables())),
      tolerance_(runner_.model().info().default_experiment.tolerance) {
    runner_.set_time(runner_.model().info().default_experiment.start_time);
    start_time_ = runner_.time();
    const auto bytes = runner_.model().bytes();
    defaults_.assign(bytes.begin(), bytes.end());
}

Instance::~Instance() {
    for (const Snapshot* s : snapshots_) delete s;
}

bool Instance::category_on(const char* category) const {
    if (category_enabled_[kLogAll]) return true;
    const auto i = category_index(category);
    return i < category_enabled_.size() && category_enabled_[i];
}

void Instance::log(fmi2Status status, const char* category, const std::string& message) const {
    if (!logger_) return;
    if (status < fmi2Warning && !category_on(category)) return;
    // The message goes through "%s": a '%' in it must not be read as a format directive.
    logger_(environment_, name_.c_str(), status, category, "%s", message.c_str());
}

void Instance::log_call(std::string_view function) const {
    if (logger_ && category_enabled_[kLogAll]) log(fmi2OK, "logAll", std::string(function));
}

void Instance::set_debug_logging(bool on, std::span<const fmi2String> categories) {
    if (categories.empty()) {
        std::fill(category_enabled_.begin(), category_enabled_.end(), on);
        return;
    }
    std::vector<std::size_t> indices;
    for (fmi2String c : categories) {
        if (!c) throw Error("fmi2SetDebugLogging: a category is a null pointer");
        const auto i = category_index(c);
        if (i >= category_enabled_.size())
            throw Error(std::string("fmi2SetDebugLogging: unknown category '") + c + "'");
        indices.push_back(i);
    }
    for (auto i : indices) category_enabled_[i] = on;
}

void Instance::require(Call call) const {
    if ((allowed_modes(call) & static_cast<std::uint32_t>(mode_)) == 0)
        throw Error(std::string(to_string(call)) + " is not allowed in mode " + std::string(to_string(mode_)));
}

void Instance::require_kind(Kind kind, Call call) const {
    if (kind != kind_)
        throw Error(std::string(to_string(call)) + " is a " +
                    (kind == Kind::model_exchange ? "Model Exchange" : "Co-Simulation") +
                    " function, but this instance was instantiated for " +
                    (kind_ == Kind::model_exchange ? "Model Exchange" : "Co-Simulation"));
}

void Instance::setup_experiment(bool tolerance_defined, double tolerance, double start_time, bool, double) {
    if (!std::isfinite(start_time)) throw Error("fmi2SetupExperiment: start time is not finite");
    if (tolerance_defined) {
        if (!(tolerance > 0.0 && tolerance < 1.0)) throw Error("fmi2SetupExperiment: tolerance must be in (0, 1)");
        tolerance_ = tolerance;
    }
    start_time_ = start_time;
    runner_.set_time(start_time);
}

void Instance::enter_initialization_mode() {
    runner_.enter_initialization();
    mode_ = Mode::initialization;
}

void Instance::exit_initialization_mode() {
    runner_.exit_initialization();
    // Legal settings a person most likely did not mean: said once, as warnings, when the parameters are final.
    for (const auto& note : setting_notes(runner_.table().variables(), runner_.model().bytes(), defaults_))
        log(fmi2Warning, "logStatusWarning", note);
    if (kind_ == Kind::model_exchange) {
        mode_ = Mode::event;
        return;
    }
    cs_solver_ = std::make_unique<CsSolver>(runner_, tolerance_);
    // A Co-Simulation host has no event mode: settle the discrete state at the start time here.
    const EventUpdate r = runner_.event_iteration();
    terminate_requested_ = r.terminate;
    last_successful_time_ = runner_.time();
    mode_ = Mode::step_complete;
}

void Instance::terminate() {
    if (cs_solver_) {
        const auto s = cs_solver_->statistics();
        log(fmi2OK, "logStatistics",
            "steps " + std::to_string(s.steps) + ", right-hand sides " + std::to_string(s.rhs_evaluations) +
                ", time events " + std::to_string(s.time_events) + ", state events " + std::to_string(s.state_events) +
                ", integrator restarts " + std::to_string(s.restarts) + ", spans the block stepped itself " +
                std::to_string(s.block_spans));
    }
    mode_ = Mode::terminated;
}

void Instance::reset() {
    cs_solver_.reset();
    runner_.reset(runner_.model().info().default_experiment.start_time);
    start_time_ = runner_.time();
    tolerance_ = runner_.model().info().default_experiment.tolerance;
    last_successful_time_ = 0.0;
    terminate_requested_ = false;
    mode_ = Mode::instantiated;
}

std::vector<Instance::Access> Instance::access_of(std::span<const Variable> vars) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    std::vector<Access> access(vars.size());
    for (std::size_t i = 0; i < vars.size(); ++i) {
        const Variable& v = vars[i];
        access[i] = Access{.offset = v.offset,
                           .type = v.type,
                           .continuous_input = v.type == ValueType::Real && v.causality == Causality::input &&
                                               v.variability == Variability::continuous,
                           .min = v.min.value_or(-inf),
                           .max = v.max.value_or(inf)};
    }
    return access;
}

const Variable& Instance::variable(fmi2ValueReference vr, ValueType type) const {
    return variable(runner_.table().variables(), vr, type);
}

// The table looked up once per call by the getters and setters, not once per value (a virtual call each).
const Variable& Instance::variable(std::span<const Variable> vars, fmi2ValueReference vr, ValueType type) const {
    if (vr >= vars.size()) throw Error("unknown value reference " + std::to_string(vr));
    const Variable& v = vars[vr];
    // An Enumeration is read and written through the Integer functions (FMI 2.0 section 2.1.7).
    const bool integer_access = type == ValueType::Integer && v.type == ValueType::Enumeration;
    if (v.type != type && !integer_access)
        throw Error("value reference " + std::to_string(vr) + " (" + v.name + ") is of type " +
                    std::string(to_string(v.type)) + ", not " + std::string(to_string(type)));
    return v;
}

void Instance::check_settable(const Variable& v) const {
    auto refuse = [&](const char* why) {
        throw Error("cannot set " + v.name + " in mode " + std::string(to_string(mode_)) + ": " + why);
    };
    if (v.variability == Variability::constant) refuse("it is a constant");
    switch (mode_) {
        case Mode::instantiated:
        case Mode::initialization:
            if (!v.has_start()) refuse("it has no start value (it is calculated)");
            return;
        case Mode::event:
        case Mode::step_complete:
            if (v.causality == Causality::input) return;
            if (v.causality == Causality::parameter && v.variability == Variability::tunable) return;
            refuse("after initialization only inputs and tunable parameters can be set");
            return;
        case Mode::continuous_time:
            if (v.causality == Causality::input && v.variability == Variability::continuous) return;
            refuse("in continuous-time mode only continuous inputs can be set");
            return;
        default:
            refuse("setting is not allowed in this mode");
    }
}

namespace {

template <class T>
void require_arrays(std::span<const fmi2ValueReference> vr, const T* values) {
    if (!vr.empty() && (vr.data() == nullptr || values == nullptr))
        throw Error("null value-reference or value array with nvr = " + std::to_string(vr.size()));
}

}  // namespace

void Instance::get_real(std::span<const fmi2ValueReference> vr, fmi2Real* values) {
    require_arrays(vr, values);
    runner_.ensure_evaluated();
    const auto bytes = std::as_const(runner_.model()).bytes();
    for (std::size_t i = 0; i < vr.size(); ++i) {
        if (vr[i] < access_.size() && access_[vr[i]].type == ValueType::Real) [[likely]] {
            std::memcpy(&values[i], bytes.data() + access_[vr[i]].offset, sizeof(double));
        } else {
            values[i] = read_real(bytes, variable(runner_.table().variables(), vr[i], ValueType::Real));  // throws
        }
    }
}

void Instance::get_integer(std::span<const fmi2ValueReference> vr, fmi2Integer* values) {
    require_arrays(vr, values);
    runner_.ensure_evaluated();
    const auto bytes = std::as_const(runner_.model()).bytes();
    const auto& vars = runner_.table().variables();
    for (std::size_t i = 0; i < vr.size(); ++i)
        values[i] = read_integer(bytes, variable(vars, vr[i], ValueType::Integer));
}

void Instance::get_boolean(std::span<const fmi2ValueReference> vr, fmi2Boolean* values) {
    require_arrays(vr, values);
    runner_.ensure_evaluated();
    const auto bytes = std::as_const(runner_.model()).bytes();
    const auto& vars = runner_.table().variables();
    for (std::size_t i = 0; i < vr.size(); ++i)
        values[i] = read_boolean(bytes, variable(vars, vr[i], ValueType::Boolean)) ? fmi2True : fmi2False;
}

void Instance::get_string(std::span<const fmi2ValueReference> vr, fmi2String* values) {
    require_arrays(vr, values);
    runner_.ensure_evaluated();
    for (std::size_t i = 0; i < vr.size(); ++i) {
        const Variable& v = variable(vr[i], ValueType::String);
        values[i] = reinterpret_cast<const char*>(runner_.model().bytes().data() + v.offset);
    }
}

// Every set is all-or-nothing: all values are checked before any is written, and a parameter change
// the block's validate() refuses after initialization is rolled back.
template <class T, class Check, class Write>
void Instance::set_values(std::span<const fmi2ValueReference> vr, const T* values, ValueType type, Check&& check,
                          Write&& write) {
    require_arrays(vr, values);
    bool parameter_changed = false;
    const auto& vars = runner_.table().variables();
    for (std::size_t i = 0; i < vr.size(); ++i) {
        const Variable& v = variable(vars, vr[i], type);
        check_settable(v);
        check(v, values[i]);
        parameter_changed = parameter_changed || v.causality == Causality::parameter;
    }
    const bool initialized = mode_ != Mode::instantiated && mode_ != Mode::initialization;
    // A tunable parameter set after initialization is validated with the others and rolled back if the
    // block refuses it: only then is the whole data worth a copy (inputs are set at every step of a host).
    std::vector<std::byte> before;
    if (initialized && parameter_changed) {
        auto b = runner_.model().bytes();
        before.assign(b.begin(), b.end());
    }
    for (std::size_t i = 0; i < vr.size(); ++i) write(vars[vr[i]], values[i]);  // checked above
    if (parameter_changed)
        runner_.parameters_changed();
    else
        runner_.mark_changed();
    if (initialized && parameter_changed) {
        try {
            runner_.model().validate();
            runner_.ensure_configured();
        } catch (...) {
            std::copy(before.begin(), before.end(), runner_.model().bytes().begin());
            runner_.parameters_changed();
            throw;
        }
    }
    if (cs_solver_) cs_solver_->invalidate();
}

bool Instance::set_continuous_inputs(std::span<const fmi2ValueReference> vr, const fmi2Real* values) {
    if (mode_ != Mode::continuous_time && mode_ != Mode::event && mode_ != Mode::step_complete) return false;
    if (!vr.empty() && (vr.data() == nullptr || values == nullptr)) return false;
    for (std::size_t i = 0; i < vr.size(); ++i) {
        if (vr[i] >= access_.size()) return false;
        const Access& a = access_[vr[i]];
        // The checks set_values makes, for these variables: settable (a continuous input), finite, in range.
        if (!a.continuous_input || !std::isfinite(values[i]) || values[i] < a.min || values[i] > a.max) return false;
    }
    const auto bytes = runner_.model().bytes();
    for (std::size_t i = 0; i < vr.size(); ++i) {
        std::memcpy(bytes.data() + access_[vr[i]].offset, &values[i], sizeof(double));
        runner_.input_value_set(vr[i]);
    }
    runner_.mark_changed();
    if (cs_solver_) cs_solver_->invalidate();
    return true;
}

void Instance::set_real(std::span<const fmi2ValueReference> vr, const fmi2Real* values) {
    if (set_continuous_inputs(vr, values)) return;  // a host's inputs at every step
    set_values(vr, values, ValueType::Real, check_real, [&](const Variable& v, double x) {
        write_real(runner_.model().bytes(), v, x);
        if (v.causality == Causality::input)
            runner_.input_value_set(static_cast<std::size_t>(&v - runner_.table().variables().data()));
    });
}
void Instance::set_real_input_derivatives(std::span<const fmi2ValueReference> vr, const fmi2Integer* order,
                                          const fmi2Real* values) {
    require_arrays(vr, values);
    require_arrays(vr, order);
    for (std::size_t i = 0; i < vr.size(); ++i) {
        const Variable& v = variable(vr[i], ValueType::Real);
        if (v.causality != Causality::input || v.variability != Variability::continuous)
            throw Error("fmi2SetRealInputDerivatives: " + v.name + " is not a continuous Real input");
        // Inputs are interpolated linearly over a step; a higher derivative would be silently ignored.
        if (order[i] != 1)
            throw Error("fmi2SetRealInputDerivatives: order " + std::to_string(order[i]) + " for " + v.name +
                        " (this FMU interpolates inputs linearly: only order 1)");
        if (!std::isfinite(values[i]))
            throw Error("fmi2SetRealInputDerivatives: the derivative of " + v.name + " is not finite");
    }
    for (std::size_t i = 0; i < vr.size(); ++i) runner_.set_input_slope(vr[i], values[i]);
    runner_.mark_changed();
    if (cs_solver_) cs_solver_->invalidate();
}

void Instance::set_integer(std::span<const fmi2ValueReference> vr, const fmi2Integer* values) {
    set_values(vr, values, ValueType::Integer, check_integer,
               [&](const Variable& v, fmi2Integer x) { write_integer(runner_.model().bytes(), v, x); });
}

void Instance::set_boolean(std::span<const fmi2ValueReference> vr, const fmi2Boolean* values) {
    set_values(
        vr, values, ValueType::Boolean, [](const Variable&, fmi2Boolean) {},
        [&](const Variable& v, fmi2Boolean x) { write_boolean(runner_.model().bytes(), v, x != fmi2False); });
}

void Instance::set_string(std::span<const fmi2ValueReference> vr, const fmi2String* values) {
    set_values(
        vr, values, ValueType::String,
        [](const Variable& v, fmi2String x) {
            if (!x) throw Error(v.name + " cannot be set to a null string");
            const std::string_view text(x);
            if (text.size() > v.string_capacity)
                throw Error(v.name + " is limited to " + std::to_string(v.string_capacity) + " characters");
        },
        [&](const Variable& v, fmi2String x) { write_string(runner_.model().bytes(), v, x); });
}

void Instance::require_owned(const Snapshot* state) const {
    if (!state || !snapshots_.contains(state))
        throw Error("the FMU state pointer was not made by this instance, or was freed");
}

Snapshot* Instance::get_state(Snapshot* reuse) {
    Snapshot* s = reuse;
    if (s) {
        require_owned(s);
    } else {
        s = new Snapshot;
        snapshots_.insert(s);
    }
    s->model = runner_.model().clone();
    s->time = runner_.time();
    s->mode = mode_;
    s->last_successful_time = last_successful_time_;
    s->terminate_requested = terminate_requested_;
    return s;
}

void Instance::set_state(const Snapshot* state) {
    require_owned(state);
    runner_.restore(*state->model, state->time);
    last_successful_time_ = state->last_successful_time;
    terminate_requested_ = state->terminate_requested;
    // A restore is the one way out of the error mode besides reset (FMI 2.0 section 2.1.3): the
    // instance continues in the mode the state was taken in (a deserialized state: after
    // initialization, in event mode or with a completed step).
    if (mode_ == Mode::error)
        mode_ = state->mode ? *state->mode : (kind_ == Kind::model_exchange ? Mode::event : Mode::step_complete);
    if (cs_solver_) cs_solver_->invalidate();
}

void Instance::free_state(Snapshot* state) {
    if (!state) return;  // freeing nothing is allowed
    require_owned(state);
    snapshots_.erase(state);
    delete state;
}

std::size_t Instance::serialized_size(const Snapshot* state) const {
    require_owned(state);
    return serial_header + state->model->bytes().size() + serial_checksum;
}

std::vector<fmi2Byte> Instance::serialize(const Snapshot* state) const {
    require_owned(state);
    std::vector<fmi2Byte> out(serialized_size(state));
    char* p = out.data();
    auto put = [&](const void* src, std::size_t n) {
        std::memcpy(p, src, n);
        p += n;
    };
    const auto data = state->model->bytes();
    const std::uint64_t data_size = data.size();
    const std::uint8_t terminate = state->terminate_requested ? 1 : 0;
    char guid[serial_guid_bytes] = {};
    std::memcpy(guid, guid_.data(), std::min(guid_.size(), serial_guid_bytes));
    put(serial_magic, sizeof serial_magic);
    put(&data_size, 8);
    put(&state->time, 8);
    put(&state->last_successful_time, 8);
    put(&terminate, 1);
    put(guid, serial_guid_bytes);
    put(data.data(), data.size());
    const std::uint64_t checksum =
        serialized_state_checksum(std::span<const char>(out.data(), out.size() - serial_checksum));
    put(&checksum, serial_checksum);
    return out;
}

Snapshot* Instance::deserialize(std::span<const fmi2Byte> bytes) {
    const std::size_t data_size = runner_.model().bytes().size();
    if (bytes.size() != serial_header + data_size + serial_checksum)
        throw Error("serialized FMU state has " + std::to_string(bytes.size()) + " bytes; this FMU's have " +
                    std::to_string(serial_header + data_size + serial_checksum));
    const char* p = bytes.data();
    auto take = [&](void* dst, std::size_t n) {
        std::memcpy(dst, p, n);
        p += n;
    };
    char magic[sizeof serial_magic];
    std::uint64_t stored_size = 0;
    auto s = std::make_unique<Snapshot>();
    std::uint8_t terminate = 0;
    char guid[serial_guid_bytes];
    take(magic, sizeof magic);
    take(&stored_size, 8);
    take(&s->time, 8);
    take(&s->last_successful_time, 8);
    take(&terminate, 1);
    take(guid, serial_guid_bytes);
    if (std::memcmp(magic, serial_magic, sizeof magic) != 0 || stored_size != data_size)
        throw Error("the bytes are not a serialized state of this FMU");
    if (std::string_view(guid, strnlen(guid, serial_guid_bytes)) != guid_)
        throw Error("the serialized state belongs to another FMU (GUID differs)");
    std::uint64_t stored_checksum = 0;
    std::memcpy(&stored_checksum, p + data_size, serial_checksum);
    if (stored_checksum != serialized_state_checksum(bytes.first(serial_header + data_size)))
        throw Error("the serialized state's checksum does not match its content (corrupted or edited)");
    if (!std::isfinite(s->time) || !std::isfinite(s->last_successful_time))
        throw Error("the serialized state has a non-finite time");
    if (terminate > 1) throw Error("the serialized state's terminate flag is not a boolean");
    s->terminate_requested = terminate != 0;
    s->model = runner_.model().clone();
    std::memcpy(s->model->bytes().data(), p, data_size);
    check_restored_state(*s->model);
    Snapshot* raw = s.release();
    snapshots_.insert(raw);
    return raw;
}

void Instance::enter_event_mode() {
    mode_ = Mode::event;
}

void Instance::new_discrete_states(fmi2EventInfo& info) {
    const bool time_event = runner_.time_event_due();
    const EventUpdate r = runner_.update_discrete();
    if (category_on("logEvents"))
        log(fmi2OK, "logEvents",
            std::string(time_event ? "time" : "state") + " event at t = " + format_time(runner_.time()));
    const double next = runner_.next_time_event();
    info.newDiscreteStatesNeeded = r.again ? fmi2True : fmi2False;
    info.terminateSimulation = r.terminate ? fmi2True : fmi2False;
    info.nominalsOfContinuousStatesChanged = fmi2False;
    info.valuesOfContinuousStatesChanged = r.states_changed ? fmi2True : fmi2False;
    info.nextEventTimeDefined = std::isfinite(next) ? fmi2True : fmi2False;
    info.nextEventTime = std::isfinite(next) ? next : 0.0;
}

void Instance::enter_continuous_time_mode() {
    mode_ = Mode::continuous_time;
}

void Instance::completed_integrator_step(fmi2Boolean* enter_event_mode, fmi2Boolean* terminate) {
    if (!enter_event_mode || !terminate) throw Error("fmi2CompletedIntegratorStep: null output pointer");
    *enter_event_mode = fmi2False;  // no step events: every event is a time or state event
    *terminate = fmi2False;
}

void Instance::set_time(double t) {
    runner_.set_time_from_host(t);
}

void Instance::check_count(std::size_t given, std::size_t expected, const char* what) const {
    if (given != expected)
        throw Error(std::string(what) + ": expected " + std::to_string(expected) + " values, got " +
                    std::to_string(given));
}

void Instance::set_continuous_states(std::span<const double> x) {
    check_count(x.size(), runner_.state_count(), "fmi2SetContinuousStates");
    if (!x.empty() && !x.data()) throw Error("fmi2SetContinuousStates: null array");
    runner_.set_states(x);
}

void Instance::get_derivatives(std::span<double> dx) {
    check_count(dx.size(), runner_.state_count(), "fmi2GetDerivatives");
    if (!dx.empty() && !dx.data()) throw Error("fmi2GetDerivatives: null array");
    runner_.get_derivatives(dx);
}

void Instance::get_event_indicators(std::span<double> z) {
    check_count(z.size(), runner_.indicator_count(), "fmi2GetEventIndicators");
    if (!z.empty() && !z.data()) throw Error("fmi2GetEventIndicators: null array");
    runner_.get_indicators(z);
}

void Instance::get_continuous_states(std::span<double> x) {
    check_count(x.size(), runner_.state_count(), "fmi2GetContinuousStates");
    if (!x.empty() && !x.data()) throw Error("fmi2GetContinuousStates: null array");
    runner_.get_states(x);
}

void Instance::get_nominals(std::span<double> nominal) {
    check_count(nominal.size(), runner_.state_count(), "fmi2GetNominalsOfContinuousStates");
    if (!nominal.empty() && !nominal.data()) throw Error("fmi2GetNominalsOfContinuousStates: null array");
    runner_.get_nominals(nominal);
}

CsSolver& Instance::cs_solver() {
    // A restore out of the error mode may bring an instance whose solver a reset dropped (or that was never
    // initialized) back to step-complete: the solver is a function of the model's state, so it is rebuilt here.
    if (!cs_solver_) cs_solver_ = std::make_unique<CsSolver>(runner_, tolerance_);
    return *cs_solver_;
}

fmi2Status Instance::do_step(double current_time, double step_size, CsSolver::HostEvents host_events,
                             bool* event_pending, const std::function<bool(double)>& host_wants) {
    if (!std::isfinite(current_time))
        throw Error("fmi2DoStep: communication point must be finite (got " + format_real(current_time) + ")");
    if (!std::isfinite(step_size) || step_size < 0.0)
        throw Error("fmi2DoStep: step size must be finite and non-negative (got " + format_real(step_size) + ")");
    if (terminate_requested_) throw Error("fmi2DoStep: the block has asked to terminate the simulation");
    const double now = runner_.time();
    if (std::abs(current_time - now) > 1e-9 * std::max(1.0, std::abs(now)))
        throw Error("fmi2DoStep: communication point " + format_time(current_time) + " is not the FMU's current time " +
                    format_time(now));
    // A step that throws leaves the instance in the error mode (fmi2_api.cpp's guard): the host may
    // restore a saved state and retry, or reset.
    runner_.set_time(current_time);
    CsSolver& solver = cs_solver();
    solver.invalidate();  // inputs may have jumped at the communication point
    const auto outcome = solver.advance(current_time + step_size, host_events, host_wants);
    if (event_pending) *event_pending = outcome == CsSolver::Outcome::event_pending;
    runner_.clear_input_slopes();  // given for this step; the inputs stay at their values at its end
    last_successful_time_ = runner_.time();
    if (outcome == CsSolver::Outcome::terminated) {
        terminate_requested_ = true;
        log(fmi2Discard, "logStatusDiscard", "the block asked to terminate at t = " + format_time(runner_.time()));
        return fmi2Discard;
    }
    return fmi2OK;
}

fmi2Status Instance::get_status(fmi2StatusKind kind, fmi2Status* value) const {
    if (!value) throw Error("fmi2GetStatus: null output pointer");
    (void)kind;
    throw Discard("fmi2GetStatus: steps are never asynchronous here, so no status kind applies");
}

fmi2Status Instance::get_real_status(fmi2StatusKind kind, fmi2Real* value) const {
    if (!value) throw Error("fmi2GetRealStatus: null output pointer");
    if (kind != fmi2LastSuccessfulTime) throw Discard("fmi2GetRealStatus: only fmi2LastSuccessfulTime is available");
    *value = last_successful_time_;
    return fmi2OK;
}

fmi2Status Instance::get_boolean_status(fmi2StatusKind kind, fmi2Boolean* value) const {
    if (!value) throw Error("fmi2GetBooleanStatus: null output pointer");
    if (kind != fmi2Terminated) throw Discard("fmi2GetBooleanStatus: only fmi2Terminated is available");
    *value = terminate_requested_ ? fmi2True : fmi2False;
    return fmi2OK;
}

}  // namespace fmu
