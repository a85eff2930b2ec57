#include "engine/callback_instance.hpp"

#include <cmath>

#include "engine/cosim_error.hpp"
#include "engine/hardware_bridge.hpp"  // max_sample_index: the same sample count as a bridged block's
#include "engine/value_text.hpp"
#include "time_rule/time_rule.hpp"

namespace cosim {

namespace {

using time_rule::reached;

}  // namespace

CallbackInstance::CallbackInstance(const fmi_loader::ModelDescription& description, std::string name, double period,
                                   StepFunction step, bool current_inputs)
    : description_(description),
      name_(std::move(name)),
      period_(period),
      step_(std::move(step)),
      current_inputs_(current_inputs) {
    if (!(period_ > 0.0) || !std::isfinite(period_))
        throw CosimError(name_ + ": the sample period must be positive and finite, got " + format_real(period_));
    for (const auto& v : description_.model_variables) {
        if (v.type == fmi_loader::VariableType::string) {
            strings_.emplace(v.value_reference, v.start.value_or(""));
            continue;
        }
        // Aliases (one value reference, several names) share one slot, as they share one value in an FMU.
        auto [it, added] = slots_.emplace(v.value_reference, values_.size());
        if (added) values_.push_back(v.start_as_real().value_or(0.0));
        if (v.causality == fmi_loader::Causality::input) {
            input_variables_.push_back(&v);
            input_slots_.push_back(it->second);
        } else if (v.causality == fmi_loader::Causality::output) {
            output_variables_.push_back(&v);
            output_slots_.push_back(it->second);
        }
    }
    in_.resize(input_slots_.size());
    out_.resize(output_slots_.size());
}

std::size_t CallbackInstance::slot(fmi2ValueReference vr) const {
    const auto it = slots_.find(vr);
    if (it == slots_.end())
        throw CosimError(name_ + ": no Real, Integer or Boolean variable with value reference " + std::to_string(vr));
    return it->second;
}

fmi2Integer CallbackInstance::get_integer(fmi2ValueReference vr) {
    return static_cast<fmi2Integer>(std::lround(values_[slot(vr)]));
}

std::string CallbackInstance::get_string(fmi2ValueReference vr) {
    const auto it = strings_.find(vr);
    if (it == strings_.end())
        throw CosimError(name_ + ": no String variable with value reference " + std::to_string(vr));
    return it->second;
}

void CallbackInstance::set_string(fmi2ValueReference vr, const std::string& x) {
    const auto it = strings_.find(vr);
    if (it == strings_.end())
        throw CosimError(name_ + ": no String variable with value reference " + std::to_string(vr));
    it->second = x;
}

void CallbackInstance::setup_experiment(double start_time, std::optional<double> stop_time, std::optional<double>) {
    start_time_ = time_ = start_time;
    next_sample_ = 0;
    last_sample_time_.reset();
    const double span = stop_time ? *stop_time - start_time : 0.0;
    if (std::isfinite(span) && span / period_ > max_sample_index)
        throw CosimError(name_ + ": sample period " + format_real(period_) + " s makes more than " +
                         format_real(max_sample_index) + " sample instants over the run's " + format_real(span) +
                         " s (the limit of the master's sample count, max_sample_index)");
}

void CallbackInstance::sample() {
    for (std::size_t i = 0; i < input_slots_.size(); ++i) in_[i] = values_[input_slots_[i]];
    for (std::size_t i = 0; i < output_slots_.size(); ++i) out_[i] = values_[output_slots_[i]];
    step_(time_, in_, out_);
    // All checked before any is kept: a Boolean of 0.5 or an Integer of 1e30 is refused, never rounded.
    for (std::size_t i = 0; i < output_slots_.size(); ++i)
        check_value(
            description_, *output_variables_[i], out_[i],
            name_ + "." + output_variables_[i]->name + " from the callback at t = " + format_real(time_) + " s");
    for (std::size_t i = 0; i < output_slots_.size(); ++i) values_[output_slots_[i]] = out_[i];
}

fmi2EventInfo CallbackInstance::new_discrete_states() {
    // One call per sample instant, however many rounds the master's event iteration takes; with
    // current_inputs another whenever the inputs changed since the last call at this instant.
    if (!reached(time_, next_sample_time()) && current_inputs_ && last_sample_time_ && *last_sample_time_ == time_) {
        bool changed = false;
        for (std::size_t i = 0; i < input_slots_.size() && !changed; ++i) changed = in_[i] != values_[input_slots_[i]];
        if (changed) sample();
    }
    if (reached(time_, next_sample_time())) {
        sample();
        last_sample_time_ = time_;
        // The next instant the current time has not reached (a run that skipped instants skips them).
        long k = std::max(next_sample_ + 1, static_cast<long>(std::floor((time_ - start_time_) / period_)));
        while (reached(time_, start_time_ + static_cast<double>(k) * period_)) ++k;
        next_sample_ = k;
    }
    fmi2EventInfo info{};
    info.nextEventTimeDefined = fmi2True;
    info.nextEventTime = next_sample_time();
    return info;
}

bool CallbackInstance::completed_integrator_step(bool* terminate) {
    if (terminate) *terminate = false;
    return false;
}

void CallbackInstance::do_step(double, double) {
    throw CosimError(name_ + ": a callback component runs as Model Exchange only");
}

}  // namespace cosim
