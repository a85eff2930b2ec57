#include "emulator/board_emulator.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <thread>

#include "fmu/errors.hpp"
#include "fmu/value_access.hpp"
#include "fmu/value_check.hpp"

namespace bridge {

namespace {

std::vector<const fmu::Variable*> by_causality(const fmu::TableBase& table, fmu::Causality causality) {
    std::vector<const fmu::Variable*> out;
    for (const auto& v : table.variables())
        if (v.causality == causality) out.push_back(&v);
    std::sort(out.begin(), out.end(), [](auto* a, auto* b) { return a->value_reference < b->value_reference; });
    return out;
}

// An Integer or Enumeration from an f64: only a whole number in the 32-bit range (1.4 is not item 1).
bool exact_int32(double x) {
    return x == std::floor(x) && x >= -2147483648.0 && x <= 2147483647.0;
}

// Every value on the wire is an f64: Integers travel exactly up to 2^53, Booleans as 0 or 1. Checked by
// the runtime's rule for every writer (fmu/value_check.hpp: finite, range, items) before it is written.
void check_value(const fmu::Variable& v, double x) {
    switch (v.type) {
        case fmu::ValueType::Real:
            fmu::check_real(v, x);
            return;
        case fmu::ValueType::Integer:
        case fmu::ValueType::Enumeration:
            if (!exact_int32(x)) throw fmu::Error(v.name + " = " + std::to_string(x) + " is not a 32-bit integer");
            fmu::check_integer(v, static_cast<std::int32_t>(x));
            return;
        case fmu::ValueType::Boolean:
            return;
        case fmu::ValueType::String:
            break;
    }
    throw fmu::Error(v.name + ": String variables cannot cross the link");
}

void write_value(std::span<std::byte> data, const fmu::Variable& v, double x) {
    check_value(v, x);
    if (v.type == fmu::ValueType::Real)
        fmu::write_real(data, v, x);
    else if (v.type == fmu::ValueType::Boolean)
        fmu::write_boolean(data, v, x != 0.0);
    else
        fmu::write_integer(data, v, static_cast<std::int32_t>(x));
}

double read_value(std::span<const std::byte> data, const fmu::Variable& v) {
    if (v.type == fmu::ValueType::String) throw fmu::Error(v.name + ": String variables cannot cross the link");
    return fmu::read_number(data, v);
}

std::string format_count(double x) {
    return x == std::floor(x) && std::abs(x) < 1e15 ? std::to_string(static_cast<long long>(x)) : std::to_string(x);
}

}  // namespace

BoardEmulator::BoardEmulator(std::unique_ptr<fmu::Model> model, const std::vector<std::string>& settings)
    : runner_(std::move(model)), settings_(settings) {
    inputs_ = by_causality(runner_.table(), fmu::Causality::input);
    outputs_ = by_causality(runner_.table(), fmu::Causality::output);
    for (const auto* v : by_causality(runner_.table(), fmu::Causality::parameter))
        if (v->type != fmu::ValueType::String) parameters_.push_back(v);
    if (inputs_.size() > max_values || outputs_.size() > max_values)
        throw FrameError("the block has more inputs or outputs than a frame carries (" + std::to_string(max_values) +
                         ")");
    apply_settings();
}

// The board's own settings, name=value as on its command line, through the runtime's checks.
void BoardEmulator::apply_settings() {
    for (const auto& s : settings_) {
        const auto eq = s.find('=');
        if (eq == std::string::npos) throw fmu::Error("--set expects name=value, got '" + s + "'");
        const auto& v = runner_.table().by_name(s.substr(0, eq));
        const std::string_view text = std::string_view(s).substr(eq + 1);
        if (v.causality != fmu::Causality::parameter)
            throw fmu::Error("--set " + v.name + ": only parameters are the board's settings");
        if (v.type == fmu::ValueType::String) {
            if (text.size() > v.string_capacity)
                throw fmu::Error(v.name + " is limited to " + std::to_string(v.string_capacity) + " characters");
            fmu::write_string(runner_.model().bytes(), v, text);
        } else {
            write_value(runner_.model().bytes(), v, fmu::checked_value_from_text(v, text));
        }
    }
}

void BoardEmulator::set_inputs(const std::vector<double>& values) {
    for (std::size_t i = 0; i < inputs_.size(); ++i) write_value(runner_.model().bytes(), *inputs_[i], values[i]);
    runner_.mark_changed();
}

Frame BoardEmulator::configure(const Frame& frame) {
    if (frame.time != static_cast<double>(parameters_.size()))
        throw FrameError("configuration of " + format_count(frame.time) + " parameters; the block has " +
                         std::to_string(parameters_.size()));
    if (frame.sequence > parameters_.size() || frame.values.size() > parameters_.size() - frame.sequence)
        throw FrameError("configure frame at index " + std::to_string(frame.sequence) + " with " +
                         std::to_string(frame.values.size()) + " values runs past the block's " +
                         std::to_string(parameters_.size()) + " parameters");
    // Checked before any is kept: a value outside a parameter's declared range is refused whole.
    for (std::size_t i = 0; i < frame.values.size(); ++i) {
        try {
            check_value(*parameters_[frame.sequence + i], frame.values[i]);
        } catch (const fmu::Error& e) {
            throw FrameError(std::string("configuration: ") + e.what());
        }
    }
    if (configuration_.size() != parameters_.size()) {
        configuration_.assign(parameters_.size(), 0.0);
        configured_.assign(parameters_.size(), false);
    }
    for (std::size_t i = 0; i < frame.values.size(); ++i) {
        configuration_[frame.sequence + i] = frame.values[i];
        configured_[frame.sequence + i] = true;
    }
    Frame ack;
    ack.type = FrameType::configured;
    ack.sequence = frame.sequence;
    ack.time = static_cast<double>(parameters_.size());
    return ack;
}

// The master's parameter values over the board's own settings, for the run that starts now.
void BoardEmulator::apply_configuration() {
    for (std::size_t i = 0; i < configuration_.size(); ++i)
        if (configured_[i]) write_value(runner_.model().bytes(), *parameters_[i], configuration_[i]);
}

Frame BoardEmulator::answer(const Frame& request) {
    if (request.type == FrameType::configure) return configure(request);
    if (request.type != FrameType::request) throw FrameError("expected a request or configure frame");
    if (request.values.size() != inputs_.size())
        throw FrameError("request carries " + std::to_string(request.values.size()) + " values, the block has " +
                         std::to_string(inputs_.size()) + " inputs");
    if (request.sequence == 1) initialized_ = false;  // sequence 1 opens a run
    if (!initialized_) {
        // The board starts over from its defaults, its own settings and the master's configuration; then,
        // as an FMU's initialization, the first frame's inputs are the initial inputs, its time the start
        // time, and the block's event iteration at the start follows.
        runner_.reset(request.time);
        apply_settings();
        apply_configuration();
        runner_.set_time(request.time);
        runner_.enter_initialization();
        set_inputs(request.values);
        runner_.exit_initialization();
        runner_.event_iteration();
        initialized_ = true;
    } else {
        set_inputs(request.values);
        runner_.set_time(request.time);
        if (runner_.time_event_due()) runner_.event_iteration();
    }
    runner_.ensure_evaluated();
    Frame reply;
    reply.type = FrameType::reply;
    reply.sequence = request.sequence;
    reply.time = request.time;
    reply.values.reserve(outputs_.size());
    for (const auto* v : outputs_) reply.values.push_back(read_value(runner_.model().bytes(), *v));
    return reply;
}

ServeStatistics serve(BoardEmulator& board, Link& link, const ServeOptions& options) {
    ServeStatistics stats;
    auto last_frame = Clock::now();
    for (;;) {
        if (options.stop && options.stop->load()) return stats;
        if (options.max_frames > 0 && stats.requests >= options.max_frames) return stats;
        if (options.idle_timeout_s > 0.0 &&
            Clock::now() - last_frame > std::chrono::duration<double>(options.idle_timeout_s))
            return stats;
        const auto bytes = link.receive(Clock::now() + std::chrono::milliseconds(50));
        if (!bytes) continue;
        last_frame = Clock::now();
        Frame reply;
        bool configuration = false;
        try {
            const Frame request = decode(*bytes);
            configuration = request.type == FrameType::configure;
            ++(configuration ? stats.configure_frames : stats.requests);
            reply = board.answer(request);
        } catch (const std::exception& e) {
            ++stats.rejected;
            if (options.log) *options.log << "board: rejected a frame: " << e.what() << "\n";
            continue;
        }
        if (configuration) {
            link.send(encode(reply));
            continue;
        }
        if (options.drop_every > 0 && stats.requests % options.drop_every == 0) {
            ++stats.dropped;
            continue;
        }
        if (options.delay_ms > 0) std::this_thread::sleep_for(std::chrono::milliseconds(options.delay_ms));
        link.send(encode(reply));
        ++stats.replies;
    }
}

}  // namespace bridge
