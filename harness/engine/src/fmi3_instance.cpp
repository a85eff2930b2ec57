#include "engine/fmi3_instance.hpp"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <limits>
#include <memory>

#include "engine/cosim_error.hpp"
#include "fmi_loader/loader_error.hpp"

namespace cosim {

using fmi_loader::Fmi3Type;
using fmi_loader::ScalarElement;

namespace {

void logger(fmi3InstanceEnvironment env, fmi3Status status, fmi3String, fmi3String message) {
    if (env && message) static_cast<Fmi3Instance*>(env)->record(status, message);
}

const char* status_name(int s) {
    switch (s) {
        case fmi3OK:
            return "OK";
        case fmi3Warning:
            return "Warning";
        case fmi3Discard:
            return "Discard";
        case fmi3Error:
            return "Error";
        case fmi3Fatal:
            return "Fatal";
    }
    return "?";
}

bool is_float(Fmi3Type t) {
    return t == Fmi3Type::float32 || t == Fmi3Type::float64;
}

}  // namespace

void refuse_unsupported_fmi3(const fmi_loader::ModelDescription& md, const std::string& name) {
    if (!md.model_exchange && !md.co_simulation && md.scheduled_execution)
        throw fmi_loader::LoaderError(fmi_loader::LoaderErrc::unsupported,
                                      name +
                                          ": the FMU offers only Scheduled Execution, which cosim does not support "
                                          "(FMI 3.0 Model Exchange and Co-Simulation are)");
    for (const auto& v : md.model_variables) {
        if (v.fmi3_type == Fmi3Type::clock || !v.clocks.empty())
            throw fmi_loader::LoaderError(
                fmi_loader::LoaderErrc::unsupported,
                name + ": variable '" + v.name + "' is a clock or clocked; FMI 3.0 clocks are not supported by cosim");
        if ((v.fmi3_type == Fmi3Type::string || v.fmi3_type == Fmi3Type::binary) && !v.dimensions.empty())
            throw fmi_loader::LoaderError(fmi_loader::LoaderErrc::unsupported,
                                          name + ": variable '" + v.name + "' is an array of " +
                                              std::string(fmi_loader::to_string(*v.fmi3_type)) +
                                              "; arrays of String and Binary are not supported by cosim");
    }
}

namespace {

std::string hex(const std::uint8_t* bytes, std::size_t n) {
    static const char digits[] = "0123456789abcdef";
    std::string out;
    out.reserve(2 * n);
    for (std::size_t i = 0; i < n; ++i) {
        out += digits[bytes[i] >> 4];
        out += digits[bytes[i] & 0xF];
    }
    return out;
}

std::vector<std::uint8_t> unhex(const std::string& text, const std::string& what) {
    const auto nibble = [&](char c) -> int {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        if (c >= 'A' && c <= 'F') return c - 'A' + 10;
        throw CosimError(what + ": a Binary value is hexadecimal text, '" + text + "' is not");
    };
    if (text.size() % 2) throw CosimError(what + ": a Binary value has an even number of hexadecimal digits");
    std::vector<std::uint8_t> out(text.size() / 2);
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = static_cast<std::uint8_t>(nibble(text[2 * i]) << 4 | nibble(text[2 * i + 1]));
    return out;
}

}  // namespace

Fmi3Instance::Fmi3Instance(fmi_loader::Fmu& fmu, fmi_loader::FmuKind kind, std::string instance_name, bool event_mode,
                           bool logging_on)
    : fmu_(fmu),
      lib_((refuse_unsupported_fmi3(fmu.description(), instance_name), fmu.library3(kind))),
      view_(fmi_loader::scalar_view(fmu.description())),
      name_(std::move(instance_name)),
      co_simulation_(kind == fmi_loader::FmuKind::co_simulation) {
    const auto& md = fmu_.description();
    event_mode_ = co_simulation_ && event_mode && md.co_simulation->has_event_mode;
    // FMI 3.0 passes the resources folder as a path with a trailing separator, not as a URI.
    const std::string resources = (fmu_.archive().directory() / "resources").string() + "/";
    if (co_simulation_)
        instance_ =
            lib_->fmi3InstantiateCoSimulation(name_.c_str(), md.guid.c_str(), resources.c_str(), fmi3False, logging_on,
                                              event_mode_, fmi3False, nullptr, 0, this, logger, nullptr);
    else
        instance_ = lib_->fmi3InstantiateModelExchange(name_.c_str(), md.guid.c_str(), resources.c_str(), fmi3False,
                                                       logging_on, this, logger);
    if (!instance_) {
        std::string why = messages_.empty() ? "no message from the FMU" : messages_.back().second;
        throw CosimError(name_ + ": fmi3Instantiate" + (co_simulation_ ? "CoSimulation" : "ModelExchange") +
                         " failed: " + why);
    }
    float_arrays_.resize(md.model_variables.size());
    int_arrays_.resize(md.model_variables.size());
}

Fmi3Instance::~Fmi3Instance() {
    if (instance_) lib_->fmi3FreeInstance(instance_);
}

// As Fmi2Instance::record: warnings printed as they come, an error's message said once, in the exception
// of the call that failed.
void Fmi3Instance::record(int status, std::string message) {
    if (status >= fmi3Error)
        ++unreported_errors_;
    else if (status >= fmi3Warning)
        std::cerr << name_ << " [" << status_name(status) << "] " << message << "\n";
    messages_.emplace_back(status, std::move(message));
}

void Fmi3Instance::check(int status, const char* function) {
    const std::size_t held = std::min(unreported_errors_, messages_.size());
    unreported_errors_ = 0;
    if (status < fmi3Error) {
        // An error logged by a call that did not fail: said now, not lost.
        for (std::size_t i = messages_.size() - held; i < messages_.size(); ++i)
            if (messages_[i].first >= fmi3Error)
                std::cerr << name_ << " [" << status_name(messages_[i].first) << "] " << messages_[i].second << "\n";
        return;
    }
    std::string why = messages_.empty() ? "no message from the FMU" : messages_.back().second;
    throw CosimError(name_ + ": " + function + " returned " + status_name(status) + ": " + why);
}

const ScalarElement& Fmi3Instance::element(fmi2ValueReference vr) const {
    if (vr >= view_.elements.size())
        throw CosimError(name_ + ": no variable with value reference " + std::to_string(vr));
    return view_.elements[vr];
}

void Fmi3Instance::setup_experiment(double start_time, std::optional<double> stop_time,
                                    std::optional<double> tolerance) {
    start_time_ = start_time;
    stop_time_ = stop_time;
    tolerance_ = tolerance;
}

void Fmi3Instance::enter_initialization_mode() {
    instantiated_ = false;
    check(lib_->fmi3EnterInitializationMode(instance_, tolerance_.has_value(), tolerance_.value_or(0.0), start_time_,
                                            stop_time_.has_value(), stop_time_.value_or(0.0)),
          "fmi3EnterInitializationMode");
}

void Fmi3Instance::exit_initialization_mode() {
    check(lib_->fmi3ExitInitializationMode(instance_), "fmi3ExitInitializationMode");
    if (!co_simulation_) return;  // Model Exchange: in Event Mode, the master's event iteration follows
    if (event_mode_) {
        event_iteration();
        check(lib_->fmi3EnterStepMode(instance_), "fmi3EnterStepMode");
    }
    in_step_mode_ = true;
}

void Fmi3Instance::terminate() {
    check(lib_->fmi3Terminate(instance_), "fmi3Terminate");
}

// Co-Simulation's own event iteration (FMI 3.0.2 section 4.2.4): update until the FMU needs no more.
void Fmi3Instance::event_iteration() {
    constexpr int max_rounds = 1000;
    for (int round = 0; round < max_rounds; ++round) {
        const fmi2EventInfo info = new_discrete_states();
        terminate_requested_ = terminate_requested_ || info.terminateSimulation;
        if (!info.newDiscreteStatesNeeded) return;
    }
    throw CosimError(name_ + ": fmi3UpdateDiscreteStates still asked for another round after " +
                     std::to_string(max_rounds) + " rounds");
}

void Fmi3Instance::read_floats(const ScalarElement& e, std::vector<double>& out) {
    out.resize(e.count);
    if (e.type == Fmi3Type::float64) {
        check(lib_->fmi3GetFloat64(instance_, &e.value_reference, 1, out.data(), e.count), "fmi3GetFloat64");
        return;
    }
    scratch_f32_.resize(e.count);
    check(lib_->fmi3GetFloat32(instance_, &e.value_reference, 1, scratch_f32_.data(), e.count), "fmi3GetFloat32");
    for (std::size_t i = 0; i < e.count; ++i) out[i] = scratch_f32_[i];
}

void Fmi3Instance::write_floats(const ScalarElement& e, const std::vector<double>& values) {
    if (e.type == Fmi3Type::float64) {
        check(lib_->fmi3SetFloat64(instance_, &e.value_reference, 1, values.data(), e.count), "fmi3SetFloat64");
        return;
    }
    scratch_f32_.assign(values.begin(), values.end());
    check(lib_->fmi3SetFloat32(instance_, &e.value_reference, 1, scratch_f32_.data(), e.count), "fmi3SetFloat32");
}

namespace {

// One integer type's get and set, widened to 64 bits.
template <class T, class Get>
std::vector<std::int64_t> get_as(Get* get, fmi3Instance inst, const ScalarElement& e, int& status) {
    std::vector<T> raw(e.count);
    status = get(inst, &e.value_reference, 1, raw.data(), e.count);
    return std::vector<std::int64_t>(raw.begin(), raw.end());
}

template <class T, class Set>
int set_as(Set* set, fmi3Instance inst, const ScalarElement& e, const std::vector<std::int64_t>& values) {
    std::vector<T> raw(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) raw[i] = static_cast<T>(values[i]);
    return set(inst, &e.value_reference, 1, raw.data(), e.count);
}

}  // namespace

std::vector<std::int64_t> Fmi3Instance::read_integers(const ScalarElement& e) {
    const auto& f = lib_.functions();
    int s = fmi3OK;
    std::vector<std::int64_t> out;
    switch (e.type) {
        case Fmi3Type::int8:
            out = get_as<fmi3Int8>(f.fmi3GetInt8, instance_, e, s);
            break;
        case Fmi3Type::uint8:
            out = get_as<fmi3UInt8>(f.fmi3GetUInt8, instance_, e, s);
            break;
        case Fmi3Type::int16:
            out = get_as<fmi3Int16>(f.fmi3GetInt16, instance_, e, s);
            break;
        case Fmi3Type::uint16:
            out = get_as<fmi3UInt16>(f.fmi3GetUInt16, instance_, e, s);
            break;
        case Fmi3Type::int32:
            out = get_as<fmi3Int32>(f.fmi3GetInt32, instance_, e, s);
            break;
        case Fmi3Type::uint32:
            out = get_as<fmi3UInt32>(f.fmi3GetUInt32, instance_, e, s);
            break;
        case Fmi3Type::uint64:
            out = get_as<fmi3UInt64>(f.fmi3GetUInt64, instance_, e, s);
            break;
        default:  // Int64 and Enumeration
            out = get_as<fmi3Int64>(f.fmi3GetInt64, instance_, e, s);
            break;
    }
    check(s, "fmi3GetInt/UInt");
    return out;
}

void Fmi3Instance::write_integers(const ScalarElement& e, const std::vector<std::int64_t>& values) {
    const auto& f = lib_.functions();
    int s = fmi3OK;
    switch (e.type) {
        case Fmi3Type::int8:
            s = set_as<fmi3Int8>(f.fmi3SetInt8, instance_, e, values);
            break;
        case Fmi3Type::uint8:
            s = set_as<fmi3UInt8>(f.fmi3SetUInt8, instance_, e, values);
            break;
        case Fmi3Type::int16:
            s = set_as<fmi3Int16>(f.fmi3SetInt16, instance_, e, values);
            break;
        case Fmi3Type::uint16:
            s = set_as<fmi3UInt16>(f.fmi3SetUInt16, instance_, e, values);
            break;
        case Fmi3Type::int32:
            s = set_as<fmi3Int32>(f.fmi3SetInt32, instance_, e, values);
            break;
        case Fmi3Type::uint32:
            s = set_as<fmi3UInt32>(f.fmi3SetUInt32, instance_, e, values);
            break;
        case Fmi3Type::uint64:
            s = set_as<fmi3UInt64>(f.fmi3SetUInt64, instance_, e, values);
            break;
        default:
            s = set_as<fmi3Int64>(f.fmi3SetInt64, instance_, e, values);
            break;
    }
    check(s, "fmi3SetInt/UInt");
}

std::vector<double>& Fmi3Instance::float_array(const ScalarElement& e) {
    auto& values = float_arrays_[e.variable];
    if (!values.empty()) return values;
    if (!instantiated_) {
        read_floats(e, values);
        return values;
    }
    // Instantiated Mode allows no get: the values are the start values until the FMU is initialized.
    for (std::size_t k = 0; k < e.count; ++k)
        values.push_back(
            view_.description.model_variables[view_.first_element[e.variable] + k].start_as_real().value_or(0.0));
    return values;
}

std::vector<std::int64_t>& Fmi3Instance::int_array(const ScalarElement& e) {
    auto& values = int_arrays_[e.variable];
    if (!values.empty()) return values;
    if (!instantiated_) {
        values = read_integers(e);
        return values;
    }
    for (std::size_t k = 0; k < e.count; ++k) {
        const auto& v = view_.description.model_variables[view_.first_element[e.variable] + k];
        values.push_back(static_cast<std::int64_t>(v.start_as_real().value_or(0.0)));
    }
    return values;
}

bool Fmi3Instance::must_defer(fmi2ValueReference vr) const {
    const auto& v = view_.description.model_variables[vr];
    // The arrays' sizes were taken from the structural parameters' start values (scalar_view).
    if (v.causality == fmi_loader::Causality::structural_parameter)
        throw CosimError(name_ + "." + v.name +
                         ": structural parameters (FMI 3.0 Configuration Mode) are not supported; it keeps its start "
                         "value");
    return event_mode_ && in_step_mode_ && v.causality == fmi_loader::Causality::input &&
           v.variability == fmi_loader::Variability::discrete;
}

void Fmi3Instance::set_or_defer(fmi2ValueReference vr, std::function<void()> set) {
    if (must_defer(vr))
        deferred_.push_back(std::move(set));
    else
        set();
}

double Fmi3Instance::get_real(fmi2ValueReference vr) {
    const ScalarElement& e = element(vr);
    if (!is_float(e.type)) throw CosimError(name_ + ": variable vr " + std::to_string(vr) + " is not a Float");
    if (e.count == 1 && e.type == Fmi3Type::float64) {
        double x = 0.0;
        check(lib_->fmi3GetFloat64(instance_, &e.value_reference, 1, &x, 1), "fmi3GetFloat64");
        return x;
    }
    read_floats(e, scratch_values_);
    return scratch_values_[e.offset];
}

void Fmi3Instance::write_real(const ScalarElement& e, double x) {
    if (e.count == 1 && e.type == Fmi3Type::float64) {
        check(lib_->fmi3SetFloat64(instance_, &e.value_reference, 1, &x, 1), "fmi3SetFloat64");
        return;
    }
    if (e.count == 1) return write_floats(e, std::vector<double>{x});
    auto& values = float_array(e);
    values[e.offset] = x;
    write_floats(e, values);
}

void Fmi3Instance::set_real(fmi2ValueReference vr, double x) {
    const ScalarElement& e = element(vr);
    if (must_defer(vr)) {
        deferred_.push_back([this, &e, x] { write_real(e, x); });
        return;
    }
    write_real(e, x);
}

// The master's hot path: scalar Float64s in one call; an array read once for its consecutive elements.
void Fmi3Instance::get_reals(std::span<const fmi2ValueReference> vr, std::span<double> x) {
    scratch_vr_.clear();
    bool scalars = true;
    for (const auto r : vr) {
        const ScalarElement& e = element(r);
        if (e.count != 1 || e.type != Fmi3Type::float64) {
            scalars = false;
            break;
        }
        scratch_vr_.push_back(e.value_reference);
    }
    if (scalars) {
        check(lib_->fmi3GetFloat64(instance_, scratch_vr_.data(), scratch_vr_.size(), x.data(), x.size()),
              "fmi3GetFloat64");
        return;
    }
    std::size_t last = view_.elements.size();  // no variable
    for (std::size_t i = 0; i < vr.size(); ++i) {
        const ScalarElement& e = element(vr[i]);
        if (e.count == 1) {
            x[i] = get_real(vr[i]);
            last = view_.elements.size();  // a Float32 scalar reads through scratch_values_ too
            continue;
        }
        if (e.variable != last) {
            if (!is_float(e.type))
                throw CosimError(name_ + ": variable vr " + std::to_string(vr[i]) + " is not a Float");
            read_floats(e, scratch_values_);
            last = e.variable;
        }
        x[i] = scratch_values_[e.offset];
    }
}

// Consecutive elements of one array are written in one call.
void Fmi3Instance::set_reals(std::span<const fmi2ValueReference> vr, std::span<const double> x) {
    for (std::size_t i = 0; i < vr.size();) {
        const ScalarElement& e = element(vr[i]);
        if (e.count == 1 || must_defer(vr[i])) {
            set_real(vr[i], x[i]);
            ++i;
            continue;
        }
        auto& values = float_array(e);
        std::size_t j = i;
        for (; j < vr.size() && element(vr[j]).variable == e.variable && !must_defer(vr[j]); ++j)
            values[element(vr[j]).offset] = x[j];
        write_floats(e, values);
        i = j;
    }
}

fmi2Integer Fmi3Instance::get_integer(fmi2ValueReference vr) {
    const ScalarElement& e = element(vr);
    const std::int64_t x = read_integers(e)[e.offset];
    if (x < std::numeric_limits<fmi2Integer>::min() || x > std::numeric_limits<fmi2Integer>::max() ||
        (e.type == Fmi3Type::uint64 && static_cast<std::uint64_t>(x) > std::numeric_limits<fmi2Integer>::max()))
        throw CosimError(name_ + "." + view_.description.model_variables[vr].name + ": the value " + std::to_string(x) +
                         " is beyond the 32-bit Integer the master carries");
    return static_cast<fmi2Integer>(x);
}

void Fmi3Instance::set_integer(fmi2ValueReference vr, fmi2Integer x) {
    const ScalarElement& e = element(vr);
    set_or_defer(vr, [this, &e, x] {
        if (e.count == 1) return write_integers(e, {x});
        auto& values = int_array(e);
        values[e.offset] = x;
        write_integers(e, values);
    });
}

bool Fmi3Instance::get_boolean(fmi2ValueReference vr) {
    const ScalarElement& e = element(vr);
    // fmi3Boolean is bool: no std::vector<bool>, which packs bits.
    const auto values = std::make_unique<fmi3Boolean[]>(e.count);
    check(lib_->fmi3GetBoolean(instance_, &e.value_reference, 1, values.get(), e.count), "fmi3GetBoolean");
    return values[e.offset];
}

void Fmi3Instance::set_boolean(fmi2ValueReference vr, bool x) {
    const ScalarElement& e = element(vr);
    set_or_defer(vr, [this, &e, x] {
        // Booleans are few and arrays of them rare: the whole array is read back before one is changed.
        const auto values = std::make_unique<fmi3Boolean[]>(e.count);
        if (instantiated_)
            for (std::size_t k = 0; k < e.count; ++k)
                values[k] =
                    view_.description.model_variables[view_.first_element[e.variable] + k].start_as_boolean().value_or(
                        false);
        else if (e.count > 1)
            check(lib_->fmi3GetBoolean(instance_, &e.value_reference, 1, values.get(), e.count), "fmi3GetBoolean");
        values[e.offset] = x;
        check(lib_->fmi3SetBoolean(instance_, &e.value_reference, 1, values.get(), e.count), "fmi3SetBoolean");
    });
}

std::string Fmi3Instance::get_string(fmi2ValueReference vr) {
    const ScalarElement& e = element(vr);
    if (e.type == Fmi3Type::binary) {
        std::size_t size = 0;
        fmi3Binary bytes = nullptr;
        check(lib_->fmi3GetBinary(instance_, &e.value_reference, 1, &size, &bytes, 1), "fmi3GetBinary");
        return bytes ? hex(bytes, size) : "";
    }
    fmi3String s = nullptr;
    check(lib_->fmi3GetString(instance_, &e.value_reference, 1, &s, 1), "fmi3GetString");
    return s ? s : "";
}

void Fmi3Instance::set_string(fmi2ValueReference vr, const std::string& x) {
    const ScalarElement& e = element(vr);
    if (e.type == Fmi3Type::binary) {
        auto bytes = unhex(x, name_ + "." + view_.description.model_variables[vr].name);
        set_or_defer(vr, [this, &e, bytes = std::move(bytes)] {
            const std::size_t size = bytes.size();
            const fmi3Binary data = bytes.data();
            check(lib_->fmi3SetBinary(instance_, &e.value_reference, 1, &size, &data, 1), "fmi3SetBinary");
        });
        return;
    }
    set_or_defer(vr, [this, &e, x] {
        const fmi3String s = x.c_str();
        check(lib_->fmi3SetString(instance_, &e.value_reference, 1, &s, 1), "fmi3SetString");
    });
}

void Fmi3Instance::do_step(double t, double h) {
    if (!deferred_.empty()) {
        check(lib_->fmi3EnterEventMode(instance_), "fmi3EnterEventMode");
        in_step_mode_ = false;
        auto sets = std::move(deferred_);
        deferred_.clear();
        for (auto& set : sets) set();
        event_iteration();
        check(lib_->fmi3EnterStepMode(instance_), "fmi3EnterStepMode");
        in_step_mode_ = true;
    }
    fmi3Boolean event = fmi3False, terminate = fmi3False, early = fmi3False;
    fmi3Float64 last = t;
    check(lib_->fmi3DoStep(instance_, t, h, fmi3True, &event, &terminate, &early, &last), "fmi3DoStep");
    terminate_requested_ = terminate_requested_ || terminate;
    if (event && event_mode_) {
        check(lib_->fmi3EnterEventMode(instance_), "fmi3EnterEventMode");
        in_step_mode_ = false;
        event_iteration();
        check(lib_->fmi3EnterStepMode(instance_), "fmi3EnterStepMode");
        in_step_mode_ = true;
    }
}

void Fmi3Instance::set_real_input_derivatives(std::span<const fmi2ValueReference>, std::span<const double>) {
    throw CosimError(name_ + ": FMI 3.0 has no input derivatives (canInterpolateInputs is an FMI 2.0 capability)");
}

void Fmi3Instance::set_time(double t) {
    check(lib_->fmi3SetTime(instance_, t), "fmi3SetTime");
}

void Fmi3Instance::set_states(const double* x, std::size_t n) {
    check(lib_->fmi3SetContinuousStates(instance_, x, n), "fmi3SetContinuousStates");
}

void Fmi3Instance::get_states(double* x, std::size_t n) {
    check(lib_->fmi3GetContinuousStates(instance_, x, n), "fmi3GetContinuousStates");
}

void Fmi3Instance::get_derivatives(double* dx, std::size_t n) {
    check(lib_->fmi3GetContinuousStateDerivatives(instance_, dx, n), "fmi3GetContinuousStateDerivatives");
}

void Fmi3Instance::get_nominals(double* nominal, std::size_t n) {
    check(lib_->fmi3GetNominalsOfContinuousStates(instance_, nominal, n), "fmi3GetNominalsOfContinuousStates");
}

void Fmi3Instance::get_event_indicators(double* z, std::size_t n) {
    check(lib_->fmi3GetEventIndicators(instance_, z, n), "fmi3GetEventIndicators");
}

void Fmi3Instance::enter_event_mode() {
    check(lib_->fmi3EnterEventMode(instance_), "fmi3EnterEventMode");
}

fmi2EventInfo Fmi3Instance::new_discrete_states() {
    fmi3Boolean need = fmi3False, terminate = fmi3False, nominals = fmi3False, values = fmi3False, defined = fmi3False;
    fmi3Float64 next = 0.0;
    check(lib_->fmi3UpdateDiscreteStates(instance_, &need, &terminate, &nominals, &values, &defined, &next),
          "fmi3UpdateDiscreteStates");
    fmi2EventInfo info{};
    info.newDiscreteStatesNeeded = need ? fmi2True : fmi2False;
    info.terminateSimulation = terminate ? fmi2True : fmi2False;
    info.nominalsOfContinuousStatesChanged = nominals ? fmi2True : fmi2False;
    info.valuesOfContinuousStatesChanged = values ? fmi2True : fmi2False;
    info.nextEventTimeDefined = defined ? fmi2True : fmi2False;
    info.nextEventTime = next;
    return info;
}

void Fmi3Instance::enter_continuous_time_mode() {
    check(lib_->fmi3EnterContinuousTimeMode(instance_), "fmi3EnterContinuousTimeMode");
}

bool Fmi3Instance::completed_integrator_step(bool* terminate) {
    fmi3Boolean enter = fmi3False, stop = fmi3False;
    check(lib_->fmi3CompletedIntegratorStep(instance_, fmi3True, &enter, &stop), "fmi3CompletedIntegratorStep");
    if (terminate) *terminate = stop;
    return enter;
}

namespace {

void require(bool capability, const void* function, const std::string& name, const char* what) {
    if (!capability) throw CosimError(name + ": the FMU does not declare " + what);
    if (!function) throw CosimError(name + ": the FMU declares " + std::string(what) + " but lacks its functions");
}

}  // namespace

Fmi3Instance::State Fmi3Instance::get_state() {
    const auto& md = fmu_.description();
    require(co_simulation_ ? md.co_simulation->can_get_and_set_fmu_state : md.model_exchange->can_get_and_set_fmu_state,
            reinterpret_cast<const void*>(lib_->fmi3GetFMUState), name_, "canGetAndSetFMUState");
    fmi3FMUState s = nullptr;
    check(lib_->fmi3GetFMUState(instance_, &s), "fmi3GetFMUState");
    return s;
}

void Fmi3Instance::set_state(State s) {
    check(lib_->fmi3SetFMUState(instance_, s), "fmi3SetFMUState");
    // The arrays' last written values are the FMU's no more.
    for (auto& a : float_arrays_) a.clear();
    for (auto& a : int_arrays_) a.clear();
}

void Fmi3Instance::free_state(State s) {
    check(lib_->fmi3FreeFMUState(instance_, &s), "fmi3FreeFMUState");
}

std::vector<std::uint8_t> Fmi3Instance::serialize(State s) {
    const auto& md = fmu_.description();
    require(co_simulation_ ? md.co_simulation->can_serialize_fmu_state : md.model_exchange->can_serialize_fmu_state,
            reinterpret_cast<const void*>(lib_->fmi3SerializeFMUState), name_, "canSerializeFMUState");
    std::size_t size = 0;
    check(lib_->fmi3SerializedFMUStateSize(instance_, s, &size), "fmi3SerializedFMUStateSize");
    std::vector<std::uint8_t> bytes(size);
    check(lib_->fmi3SerializeFMUState(instance_, s, bytes.data(), size), "fmi3SerializeFMUState");
    return bytes;
}

Fmi3Instance::State Fmi3Instance::deserialize(const std::vector<std::uint8_t>& bytes) {
    fmi3FMUState s = nullptr;
    check(lib_->fmi3DeserializeFMUState(instance_, bytes.data(), bytes.size(), &s), "fmi3DeserializeFMUState");
    return s;
}

}  // namespace cosim
