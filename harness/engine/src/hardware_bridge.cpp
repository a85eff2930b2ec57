#include "engine/hardware_bridge.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>

#include "engine/cosim_error.hpp"
#include "engine/interrupt.hpp"
#include "engine/value_text.hpp"
#include "protocol/frame.hpp"
#include "time_rule/time_rule.hpp"

namespace cosim {

namespace {

using fmi_loader::Causality;
using fmi_loader::VariableType;

constexpr double infinity = std::numeric_limits<double>::infinity();

// Nearest-rank percentile of sorted values.
double percentile(const std::vector<double>& sorted, double p) {
    const auto rank = static_cast<std::size_t>(std::ceil(p * static_cast<double>(sorted.size())));
    return sorted[std::clamp<std::size_t>(rank, 1, sorted.size()) - 1];
}

}  // namespace

HardwareBridge::HardwareBridge(const fmi_loader::ModelDescription& description, std::string name,
                               BridgeDescription settings)
    : description_(description), name_(std::move(name)), settings_(std::move(settings)) {
    std::vector<std::pair<fmi2ValueReference, std::size_t>> ins, outs, params;
    for (const auto& v : description_.model_variables) {
        Kind kind = Kind::real;
        switch (v.type) {
            case VariableType::real:
                kind = Kind::real;
                break;
            case VariableType::integer:
            case VariableType::enumeration:
                kind = Kind::integer;
                break;
            case VariableType::boolean:
                kind = Kind::boolean;
                break;
            case VariableType::string:
                kind = Kind::string;
                break;
        }
        variables_[{kind, v.value_reference}] = &v;
        if (kind == Kind::string) {
            if (v.causality == Causality::input || v.causality == Causality::output)
                throw CosimError(name_ + "." + v.name + ": String inputs and outputs cannot cross the hardware link");
            slots_[{kind, v.value_reference}] = strings_.size();
            strings_.push_back(v.start.value_or(""));
            continue;
        }
        const std::size_t index = values_.size();
        slots_[{kind, v.value_reference}] = index;
        double start = 0.0;
        if (kind == Kind::boolean)
            start = v.start_as_boolean().value_or(false) ? 1.0 : 0.0;
        else
            start = v.start_as_real().value_or(0.0);
        values_.push_back(start);
        if (v.causality == Causality::input) ins.emplace_back(v.value_reference, index);
        if (v.causality == Causality::output) outs.emplace_back(v.value_reference, index);
        if (v.causality == Causality::parameter) params.emplace_back(v.value_reference, index);
        if (v.name == "sample_period") period_slot_ = index + 1;
    }
    // Frames carry inputs and outputs in value-reference order, as the block's own table numbers them.
    std::sort(ins.begin(), ins.end());
    std::sort(outs.begin(), outs.end());
    for (const auto& [vr, i] : ins) inputs_.push_back(i);
    for (const auto& [vr, i] : outs) outputs_.push_back(i);
    std::sort(params.begin(), params.end());
    for (const auto& [vr, i] : params) parameters_.push_back(i);
    if (!period_slot_)
        throw CosimError(name_ +
                         ": a hardware-bridged block needs a Real parameter 'sample_period' (its sampling instants)");
    if (inputs_.size() > bridge::max_values || outputs_.size() > bridge::max_values)
        throw CosimError(name_ + ": more inputs or outputs than one frame carries (" +
                         std::to_string(bridge::max_values) + ")");
}

HardwareBridge::~HardwareBridge() = default;

std::size_t HardwareBridge::slot(Kind kind, fmi2ValueReference vr) const {
    const auto it = slots_.find({kind, vr});
    if (it == slots_.end())
        throw CosimError(name_ + ": no variable of that type with value reference " + std::to_string(vr));
    return it->second;
}

std::size_t HardwareBridge::settable(Kind kind, fmi2ValueReference vr) const {
    const std::size_t i = slot(kind, vr);
    const auto* v = variables_.at({kind, vr});
    if (kind == Kind::string)
        throw CosimError(name_ + "." + v->name +
                         ": a String parameter cannot cross the hardware link (its frames carry numbers), so the "
                         "board would keep its own value; set it in the board's firmware, or run the block as an FMU");
    if (v->causality != Causality::input && v->causality != Causality::parameter)
        throw CosimError(name_ + "." + v->name + " is " + std::string(fmi_loader::to_string(v->causality)) +
                         ": only a hardware-bridged block's inputs and parameters are sent to the board");
    return i;
}

void HardwareBridge::setup_experiment(double start_time, std::optional<double> stop_time, std::optional<double>) {
    start_time_ = time_ = start_time;
    stop_time_ = stop_time;
    next_sample_ = 0;
    bridge::LinkSettings link;
    link.transport = settings_.transport;
    link.host = settings_.host;
    link.port = static_cast<std::uint16_t>(settings_.port);
    link.device = settings_.device;
    link.baud = settings_.baud;
    try {
        link_ = bridge::open_link(link);
    } catch (const bridge::LinkError& e) {
        throw CosimError(name_ + ": cannot open the hardware link: " + e.what());
    }
}

void HardwareBridge::exit_initialization_mode() {
    period_ = values_[period_slot_ - 1];
    if (!(period_ > 0.0) || !std::isfinite(period_))
        throw CosimError(name_ + ": sample_period must be positive, got " + format_real(period_));
    // Instants the tolerance cannot tell apart, or more of them than the count holds, are refused
    // before the board is told anything: the master would otherwise count them one at a time.
    const double resolution = time_rule::resolution(start_time_);
    const double span = stop_time_ ? *stop_time_ - start_time_ : 0.0;
    if (period_ <= resolution || (std::isfinite(span) && span / period_ > max_sample_index))
        throw CosimError(name_ + ": sample_period " + format_real(period_) + " s makes more than " +
                         format_real(max_sample_index) + " sample instants" +
                         (stop_time_ ? " over the run's " + format_real(span) + " s" : "") +
                         " (the limit of the master's sample count, max_sample_index)");
    // The parameters are final here: the board gets them now, before the run's wall clock starts and
    // before the first exchange (samples come only after initialization).
    configure_board();
}

void HardwareBridge::terminate() {
    link_.reset();
}

double HardwareBridge::get_real(fmi2ValueReference vr) {
    return values_[slot(Kind::real, vr)];
}
void HardwareBridge::set_real(fmi2ValueReference vr, double x) {
    values_[settable(Kind::real, vr)] = x;
}
fmi2Integer HardwareBridge::get_integer(fmi2ValueReference vr) {
    return static_cast<fmi2Integer>(std::lround(values_[slot(Kind::integer, vr)]));
}
void HardwareBridge::set_integer(fmi2ValueReference vr, fmi2Integer x) {
    values_[settable(Kind::integer, vr)] = x;
}
bool HardwareBridge::get_boolean(fmi2ValueReference vr) {
    return values_[slot(Kind::boolean, vr)] != 0.0;
}
void HardwareBridge::set_boolean(fmi2ValueReference vr, bool x) {
    values_[settable(Kind::boolean, vr)] = x ? 1.0 : 0.0;
}
std::string HardwareBridge::get_string(fmi2ValueReference vr) {
    return strings_[slot(Kind::string, vr)];
}
void HardwareBridge::set_string(fmi2ValueReference vr, const std::string& x) {
    // The value it has (its start, the board's own) is no change: only another is refused.
    if (strings_[slot(Kind::string, vr)] != x) settable(Kind::string, vr);
}

void HardwareBridge::do_step(double, double) {
    throw CosimError(name_ + ": a hardware bridge runs as a Model Exchange component only");
}

void HardwareBridge::set_real_input_derivatives(std::span<const fmi2ValueReference>, std::span<const double>) {
    throw CosimError(name_ + ": a hardware bridge runs as a Model Exchange component only");
}

bool HardwareBridge::completed_integrator_step(bool* terminate) {
    if (terminate) *terminate = false;
    return false;
}

fmi2EventInfo HardwareBridge::new_discrete_states() {
    // One exchange per sample instant, however many rounds the master's event iteration takes.
    if (period_ > 0.0 && time_rule::reached(time_, next_sample_time())) {
        exchange();
        advance_sample_count();
    }
    fmi2EventInfo info{};
    info.newDiscreteStatesNeeded = fmi2False;
    info.terminateSimulation = fmi2False;
    info.nominalsOfContinuousStatesChanged = fmi2False;
    info.valuesOfContinuousStatesChanged = fmi2False;
    const double next = period_ > 0.0 ? next_sample_time() : infinity;
    info.nextEventTimeDefined = fmi2True;
    info.nextEventTime = next;
    return info;
}

void HardwareBridge::advance_sample_count() {
    // As fmu::next_instant_index: the quotient first (in double, it can be beyond any integer), then at
    // most a few steps for rounding and the reached-time rule's tolerance.
    const double periods = std::floor((time_ - start_time_) / period_);
    const auto beyond = [&] {
        return CosimError(name_ + ": t = " + format_real(time_) + " s is more than " + format_real(max_sample_index) +
                          " sample periods of " + format_real(period_) +
                          " s after the start (the limit of the master's sample count, max_sample_index)");
    };
    if (!(periods < max_sample_index)) throw beyond();
    long k = std::max(next_sample_ + 1, static_cast<long>(std::max(periods, 0.0)));
    for (int step = 0; step < 4 && time_rule::reached(time_, start_time_ + static_cast<double>(k) * period_); ++step)
        ++k;
    if (static_cast<double>(k) > max_sample_index ||
        time_rule::reached(time_, start_time_ + static_cast<double>(k) * period_))
        throw beyond();
    next_sample_ = k;
}

std::optional<std::vector<std::uint8_t>> HardwareBridge::receive(bridge::Clock::time_point deadline) {
    for (;;) {
        throw_if_interrupted();
        const auto slice = std::min(deadline, bridge::Clock::now() + wait_slice);
        if (auto bytes = link_->receive(slice)) return bytes;
        if (slice >= deadline) {
            throw_if_interrupted();
            return std::nullopt;
        }
    }
}

void HardwareBridge::configure_board() {
    const auto total = static_cast<double>(parameters_.size());
    for (std::size_t first = 0; first < parameters_.size(); first += bridge::max_values) {
        bridge::Frame frame;
        frame.type = bridge::FrameType::configure;
        frame.sequence = static_cast<std::uint32_t>(first);
        frame.time = total;
        for (std::size_t i = first; i < std::min(parameters_.size(), first + bridge::max_values); ++i)
            frame.values.push_back(values_[parameters_[i]]);
        link_->send(bridge::encode(frame));
        const auto deadline = bridge::Clock::now() + std::chrono::milliseconds(settings_.timeout_ms);
        bool taken = false;
        while (!taken) {
            const auto bytes = receive(deadline);
            if (!bytes) break;
            bridge::Frame ack;
            try {
                ack = bridge::decode(*bytes);
            } catch (const bridge::FrameError& e) {
                ++stats_.malformed;
                last_error_ = e.what();
                continue;
            }
            if (ack.type != bridge::FrameType::configured || ack.sequence != frame.sequence) continue;
            if (ack.time != total)
                throw CosimError(name_ + ": the board has " + format_real(ack.time) + " parameters, the block " +
                                 std::to_string(parameters_.size()) + ": not the same block (or firmware version)");
            taken = true;
        }
        if (!taken)
            throw CosimError(name_ + ": the board did not acknowledge its configuration (parameters " +
                             std::to_string(first) + " on) within " + std::to_string(settings_.timeout_ms) +
                             " ms (the bridge's timeout_ms); refusing to run it with parameters it may not have" +
                             (last_error_.empty() ? "" : " (last error: " + last_error_ + ")"));
    }
}

void HardwareBridge::exchange() {
    if (pacer_) pacer_(time_);  // --realtime: the frame leaves at the sample instant's wall time
    // Answers to frames already given up arrive late: take them off the link first.
    while (auto stale = link_->receive(bridge::Clock::now())) {
        try {
            bridge::decode(*stale);
            ++stats_.late;
        } catch (const bridge::FrameError& e) {
            ++stats_.malformed;
            last_error_ = e.what();
        }
    }
    bridge::Frame request;
    request.type = bridge::FrameType::request;
    request.sequence = ++sequence_;
    request.time = time_;
    for (const auto i : inputs_) request.values.push_back(values_[i]);
    const auto sent = bridge::Clock::now();
    const auto deadline = sent + std::chrono::milliseconds(settings_.timeout_ms);
    link_->send(bridge::encode(request));
    ++stats_.exchanges;
    // Frames the SLIP layer dropped (noise, oversized) count as malformed too.
    const long framing_before = link_->framing_errors();
    auto count_framing_errors = [&] {
        if (link_->framing_errors() == framing_before) return;
        stats_.malformed += link_->framing_errors() - framing_before;
        last_error_ = link_->last_framing_error();
    };
    while (auto bytes = receive(deadline)) {
        bridge::Frame reply;
        try {
            reply = bridge::decode(*bytes);
        } catch (const bridge::FrameError& e) {
            ++stats_.malformed;
            last_error_ = e.what();
            std::cerr << name_ << ": rejected a frame from the board: " << e.what() << "\n";
            continue;
        }
        if (reply.type != bridge::FrameType::reply || reply.sequence != sequence_) {
            ++stats_.late;  // an answer to an earlier frame (or an echo): not this one's
            continue;
        }
        if (reply.values.size() != outputs_.size()) {
            ++stats_.malformed;
            last_error_ = "reply carries " + std::to_string(reply.values.size()) + " values, the block has " +
                          std::to_string(outputs_.size()) + " outputs";
            std::cerr << name_ << ": " << last_error_ << "\n";
            continue;
        }
        latencies_.push_back(std::chrono::duration<double>(bridge::Clock::now() - sent).count());
        for (std::size_t i = 0; i < outputs_.size(); ++i) values_[outputs_[i]] = reply.values[i];
        ++stats_.answered;
        consecutive_misses_ = 0;
        count_framing_errors();
        return;
    }
    count_framing_errors();
    ++stats_.misses;
    ++consecutive_misses_;
    const std::string what = "frame " + std::to_string(sequence_) + " at t = " + format_real(time_) +
                             " s got no valid answer within " + std::to_string(settings_.timeout_ms) + " ms" +
                             (last_error_.empty() ? "" : " (last error: " + last_error_ + ")");
    if (settings_.policy == "stop" && consecutive_misses_ >= settings_.max_misses)
        throw CosimError(name_ + ": " + std::to_string(consecutive_misses_) +
                         " consecutive misses, stopping (policy stop): " + what);
    if (stats_.misses == 1) std::cerr << name_ << ": " << what << "; holding the last outputs\n";
}

std::optional<LinkStatistics> HardwareBridge::link_statistics() const {
    LinkStatistics s = stats_;
    if (!latencies_.empty()) {
        std::vector<double> sorted = latencies_;
        std::sort(sorted.begin(), sorted.end());
        s.latency_min = sorted.front();
        s.latency_median = percentile(sorted, 0.5);
        s.latency_p95 = percentile(sorted, 0.95);
        s.latency_max = sorted.back();
    }
    return s;
}

}  // namespace cosim
