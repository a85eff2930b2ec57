#include "fmu/model_runner.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "fmu/errors.hpp"
#include "fmu/value_access.hpp"

namespace fmu {

namespace {
// A block that keeps asking for another round at one instant is broken; stop instead of hanging.
constexpr int max_event_rounds = 1000;
}  // namespace

ModelRunner::ModelRunner(std::unique_ptr<Model> model)
    : model_(std::move(model)), indicator_count_(model_->event_indicator_count()) {}

void ModelRunner::set_time(double t) {
    if (!std::isfinite(t)) throw Error("time must be finite");
    time_ = t;
    mark_changed();
    if (!input_slopes_.empty()) apply_input_slopes();
}

void ModelRunner::set_time_from_host(double t) {
    // The same bits: the outputs and derivatives computed at this time (and these states and inputs) still hold.
    // In initialization mode every read re-runs initialize(), so the mark is kept there.
    if (!initializing_ && std::bit_cast<std::uint64_t>(t) == std::bit_cast<std::uint64_t>(time_)) return;
    set_time(t);
}

std::optional<SpanReached> ModelRunner::advance_between_events(double t_stop, double relative_tolerance) {
    if (initializing_) return std::nullopt;
    ensure_configured();
    const double t0 = time_;
    const auto reached =
        model_->advance_between_events(t0, t_stop, relative_tolerance, [this](double t) { set_time(t); });
    set_time(reached ? reached->time : t0);  // the block's states changed (or its trial times must be undone)
    return reached;
}

void ModelRunner::set_input_slope(std::size_t variable, double slope) {
    const auto& v = table().variables()[variable];
    if (!std::isfinite(slope)) throw Error("the derivative of input " + v.name + " is not finite");
    std::erase_if(input_slopes_, [variable](const InputSlope& s) { return s.variable == variable; });
    input_slopes_.push_back({variable, time_, read_real(model_->bytes(), v), slope});
}

void ModelRunner::rebase_input_slope(std::size_t variable) {
    for (auto& s : input_slopes_) {
        if (s.variable != variable) continue;
        s.base_time = time_;
        s.base_value = read_real(model_->bytes(), table().variables()[variable]);
    }
}

void ModelRunner::apply_input_slopes() {
    const auto& vars = table().variables();
    for (const auto& s : input_slopes_) {
        const Variable& v = vars[s.variable];
        double u = s.base_value + s.slope * (time_ - s.base_time);
        // A host's line between two admissible values stays admissible but for rounding (an
        // irradiance falling to 0 at the end of a step must not come out as -1e-17).
        if (v.min) u = std::max(u, *v.min);
        if (v.max) u = std::min(u, *v.max);
        write_real(model_->bytes(), v, u);
    }
}

void ModelRunner::ensure_configured() {
    if (configured_) return;
    model_->configure();
    configured_ = true;
}

void ModelRunner::exit_initialization() {
    model_->validate();
    configured_ = false;
    ensure_configured();
    mark_changed();
    ensure_evaluated();  // initialize() once more, with the final parameters and inputs
    set_initializing(false);
}

void ModelRunner::reset(double start_time) {
    model_->reset_to_defaults();
    input_slopes_.clear();
    configured_ = false;
    set_initializing(false);
    set_time(start_time);
}

void ModelRunner::ensure_evaluated() {
    if (!stale_) return;
    ensure_configured();
    if (initializing_) model_->initialize(time_);
    model_->evaluate(time_);
    stale_ = derivatives_stale_ = false;
}

void ModelRunner::ensure_derivatives() {
    if (!derivatives_stale_) return;
    if (initializing_) return ensure_evaluated();
    ensure_configured();
    model_->evaluate_derivatives(time_);
    derivatives_stale_ = false;
}

void ModelRunner::get_states(std::span<double> x) const {
    const auto& vars = table().variables();
    const auto& states = table().states();
    for (std::size_t i = 0; i < states.size(); ++i) x[i] = read_real(model_->bytes(), vars[states[i]]);
}

void ModelRunner::set_states(std::span<const double> x) {
    const auto& vars = table().variables();
    const auto& states = table().states();
    for (std::size_t i = 0; i < states.size(); ++i) {
        if (!std::isfinite(x[i])) throw Error("state " + vars[states[i]].name + " set to a non-finite value");
    }
    // A host sets the states it set last at each instant it stops at (after checking its indicators
    // there): the same bits leave the outputs current, as an evaluation of them would give the same bits.
    bool changed = false;
    for (std::size_t i = 0; i < states.size(); ++i) {
        const Variable& v = vars[states[i]];
        if (std::bit_cast<std::uint64_t>(read_real(model_->bytes(), v)) == std::bit_cast<std::uint64_t>(x[i])) continue;
        write_real(model_->bytes(), v, x[i]);
        changed = true;
    }
    if (changed) mark_changed();
}

void ModelRunner::get_derivatives(std::span<double> dx) {
    ensure_derivatives();
    const auto& vars = table().variables();
    const auto& ders = table().derivatives();
    for (std::size_t i = 0; i < ders.size(); ++i) dx[i] = read_real(model_->bytes(), vars[ders[i]]);
}

void ModelRunner::get_nominals(std::span<double> nominal) const {
    const auto& vars = table().variables();
    const auto& states = table().states();
    for (std::size_t i = 0; i < states.size(); ++i) nominal[i] = vars[states[i]].nominal.value_or(1.0);
}

void ModelRunner::get_indicators(std::span<double> z) {
    ensure_derivatives();
    model_->event_indicators(time_, z);
}

bool ModelRunner::time_event_due() {
    const double next = next_time_event();
    return std::isfinite(next) && reached(time_, next);
}

EventUpdate ModelRunner::update_discrete() {
    ensure_evaluated();  // the update sees outputs consistent with the instant before it
    const EventUpdate result = model_->event_update(time_, time_event_due());
    mark_changed();
    ensure_evaluated();
    return result;
}

EventUpdate ModelRunner::event_iteration() {
    EventUpdate total;
    for (int round = 0; round < max_event_rounds; ++round) {
        const EventUpdate r = update_discrete();
        total.states_changed = total.states_changed || r.states_changed;
        total.terminate = total.terminate || r.terminate;
        if (!r.again) return total;
    }
    throw Error("event iteration did not settle after " + std::to_string(max_event_rounds) + " rounds");
}

void ModelRunner::restore(const Model& saved, double time) {
    auto src = saved.bytes();
    std::copy(src.begin(), src.end(), model_->bytes().begin());
    time_ = time;
    configured_ = false;  // the restored parameters may differ from the current ones
    mark_changed();
    input_slopes_.clear();
}

}  // namespace fmu
