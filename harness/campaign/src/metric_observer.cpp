#include "metric_observer.hpp"

#include "analysis/run_measures.hpp"

#include <array>
#include <cmath>
#include <utility>

#include "analysis/angle_error.hpp"
#include "analysis/derived_signals.hpp"
#include "campaign_error.hpp"
#include "engine/name_hint.hpp"
#include "engine/setting.hpp"
#include "engine/value_text.hpp"
#include "statistics.hpp"

namespace campaign {

namespace {

std::vector<std::string> group(const std::string& prefix, int n) {
    std::vector<std::string> out;
    for (int i = 1; i <= n; ++i) out.push_back(prefix + "[" + std::to_string(i) + "]");
    return out;
}

}  // namespace

std::vector<std::string> metric_columns(const CampaignSpec& spec) {
    std::vector<std::string> out;
    for (const auto& m : spec.metrics)
        for (const auto& s : m.stats) out.push_back(m.name + "." + s);
    if (spec.measures)
        for (const auto& c : analysis::measure_columns(spec.measure_report)) out.push_back(c);
    return out;
}

MetricObserver::Column MetricObserver::resolve(const cosim::System& system, const std::string& name,
                                               const std::string& metric) {
    const auto split = cosim::split_variable_name(name).value_or(cosim::VariableName{name, ""});
    const auto& components = system.components();
    std::size_t index = components.size();
    for (std::size_t i = 0; i < components.size(); ++i)
        if (components[i].name == split.component) index = i;
    if (index == components.size())
        throw CampaignError("metric " + metric + ": no component named '" + split.component + "'");
    const auto* v = components[index].description().find_variable(split.variable);
    if (!v)
        throw CampaignError(
            "metric " + metric + ": " +
            cosim::unknown_variable_message(components[index].description(), split.component, split.variable));
    if (v->type == fmi_loader::VariableType::string)
        throw CampaignError("metric " + metric + ": '" + name + "' is a String");
    return {index, v};
}

namespace {

// A metric's condition ("env.irradiance > 0") on the value read at an output point.
bool holds(double x, const std::string& op, double value) {
    if (op == "<") return x < value;
    if (op == "<=") return x <= value;
    if (op == ">") return x > value;
    if (op == ">=") return x >= value;
    if (op == "==") return x == value;
    return x != value;
}

}  // namespace

double MetricObserver::read(cosim::System& system, const Column& c) {
    auto& instance = *system.components()[c.component].instance;
    switch (c.variable->type) {
        case fmi_loader::VariableType::real:
            return instance.get_real(c.variable->value_reference);
        case fmi_loader::VariableType::boolean:
            return instance.get_boolean(c.variable->value_reference) ? 1.0 : 0.0;
        default:
            return static_cast<double>(instance.get_integer(c.variable->value_reference));
    }
}

namespace {

// A fault word (or time) column, or the prefix of a [1..n] group: the names of its elements.
std::vector<std::string> word_group(const cosim::System& system, const std::string& name) {
    const auto split = cosim::split_variable_name(name);
    const auto& components = system.components();
    for (const auto& c : components)
        if (split && c.name == split->component) {
            if (c.description().find_variable(split->variable)) return {name};
            std::vector<std::string> out;
            while (c.description().find_variable(split->variable + "[" + std::to_string(out.size() + 1) + "]"))
                out.push_back(name + "[" + std::to_string(out.size() + 1) + "]");
            if (!out.empty()) return out;
        }
    return {name};  // resolve() names what is missing
}

}  // namespace

MetricObserver::MetricObserver(const std::vector<Metric>& metrics, const cosim::System& system, const Case* run_case)
    : case_(run_case) {
    if (run_case && !run_case->onset.empty())
        onset_ = resolve(system, run_case->onset, "onset of case " + run_case->name);
    if (run_case && !run_case->observable.column.empty()) {
        const std::string what = "observable of case " + run_case->name;
        for (const auto& v : run_case->observable.variables) observable_variables_.push_back(resolve(system, v, what));
        // Before any run: the column exists with each variable at 1 (the first element of a group).
        resolve(system,
                observable_column(run_case->observable,
                                  std::vector<std::string>(run_case->observable.variables.size(), "1")),
                what);
    }
    for (const auto& m : metrics) {
        Tracked t{};
        t.metric = &m;
        const int n = m.kind == MetricKind::quaternion_angle ? 4 : 3;
        if (m.kind == MetricKind::detection) {
            std::vector<std::string> names;
            for (std::size_t g = 0; g < m.words.size(); ++g) {
                const auto words = word_group(system, m.words[g]);
                t.group_start.push_back(names.size());
                t.group_size.push_back(words.size());
                for (const auto& w : words) {
                    t.a.push_back(resolve(system, w, m.name));
                    names.push_back(w);
                }
                if (!m.times.empty()) {
                    const auto times = word_group(system, m.times[g]);
                    if (times.size() != words.size())
                        throw CampaignError("metric " + m.name + ": '" + m.times[g] + "' has " +
                                            std::to_string(times.size()) + " columns where '" + m.words[g] + "' has " +
                                            std::to_string(words.size()));
                    for (const auto& c : times) t.times.push_back(resolve(system, c, m.name));
                }
                if (!run_case) continue;
                for (const auto& e : run_case->expect) {
                    if (e.words != m.words[g]) continue;
                    if (!e.variable.empty()) {
                        t.expect_variables.emplace_back(
                            g, resolve(system, e.variable, "expect of case " + run_case->name));
                        continue;
                    }
                    for (long k : e.elements) {
                        if (k > static_cast<long>(words.size()))
                            throw CampaignError("case " + run_case->name + ": 'expect' element " + std::to_string(k) +
                                                " of '" + e.words + "', which has " + std::to_string(words.size()));
                        t.expected.push_back(t.group_start[g] + static_cast<std::size_t>(k - 1));
                    }
                }
            }
            t.detection.emplace(names);
        } else if (m.kind == MetricKind::column) {
            t.a.push_back(resolve(system, m.a, m.name));
        } else if (m.kind == MetricKind::normalized_error) {
            for (const auto& c : group(m.a, 4)) t.a.push_back(resolve(system, c, m.name));
            for (const auto& c : group(m.b, 4)) t.b.push_back(resolve(system, c, m.name));
            for (const auto& c : group(m.covariance, 6)) t.covariance.push_back(resolve(system, c, m.name));
        } else {
            for (const auto& c : group(m.a, n)) t.a.push_back(resolve(system, c, m.name));
            for (const auto& c : group(m.b, n)) t.b.push_back(resolve(system, c, m.name));
        }
        if (!m.valid.empty()) t.valid = resolve(system, m.valid, m.name);
        if (!m.when.empty()) t.when = resolve(system, m.when, m.name);
        if (!m.condition_column.empty()) t.condition = resolve(system, m.condition_column, m.name);
        if (!m.start_column.empty()) t.start = resolve(system, m.start_column, m.name);
        tracked_.push_back(std::move(t));
    }
}

void MetricObserver::sample(double t, cosim::System& system) {
    if (first_) {
        // The case's onset and expected elements are parameters: read once, at the first output point.
        first_ = false;
        if (onset_) onset_value_ = read(system, *onset_);
        for (auto& k : tracked_)
            for (const auto& [g, column] : k.expect_variables) {
                const double v = read(system, column);
                if (v == 0.0) continue;  // no element: none expected
                const auto size = static_cast<double>(k.group_size[g]);
                if (v != std::floor(v) || v < 1.0 || v > size)
                    throw CampaignError("metric " + k.metric->name + ": the expected element " + cosim::format_real(v) +
                                        " is not one of 1 to " + cosim::format_real(size) + " of '" +
                                        k.metric->words[g] + "'");
                k.expected.push_back(k.group_start[g] + static_cast<std::size_t>(v) - 1);
            }
        if (case_ && !case_->observable.column.empty()) {
            std::vector<std::string> values;
            for (std::size_t i = 0; i < observable_variables_.size(); ++i) {
                const double v = read(system, observable_variables_[i]);
                if (!std::isfinite(v) || v != std::floor(v))
                    throw CampaignError("observable of case " + case_->name + ": '" + case_->observable.variables[i] +
                                        "' is " + cosim::format_real(v) + ", not an integer");
                values.push_back(cosim::format_real(v));
            }
            observable_ =
                resolve(system, observable_column(case_->observable, values), "observable of case " + case_->name);
        }
    }
    // The first output point from the onset on where the case's fault can be seen.
    if (observable_ && onset_value_ && !observable_at_ && t >= *onset_value_) {
        const double x = read(system, *observable_);
        if (case_->observable.above ? x > case_->observable.threshold : x < case_->observable.threshold)
            observable_at_ = t;
    }
    for (auto& k : tracked_) {
        const Metric& m = *k.metric;
        if (k.detection) {
            std::vector<double> words, times;
            for (const auto& c : k.a) words.push_back(read(system, c));
            for (const auto& c : k.times) times.push_back(read(system, c));
            k.detection->sample(t, words, times);
            continue;
        }
        // The change detector follows every output point, also those before `after` or while invalid,
        // so that a new estimate is recognised by comparison with the previous point.
        bool changed = true;
        if (k.when) {
            const double w = read(system, *k.when);
            changed = !k.last_when || w != *k.last_when;
            k.last_when = w;
        }
        // after_first: `after` counts from the first output point where it held (none yet: no sample).
        if (k.start && !k.started && holds(read(system, *k.start), m.start_op, m.start_value)) k.started = t;
        if (k.start && !k.started) continue;
        if (!changed || t < m.after + k.started.value_or(0.0)) continue;
        if (k.valid && read(system, *k.valid) == 0.0) continue;
        if (k.condition && !holds(read(system, *k.condition), m.condition_op, m.condition_value)) continue;
        double value = 0.0;
        if (m.kind == MetricKind::column) {
            value = read(system, k.a[0]);
        } else if (m.kind == MetricKind::normalized_error) {
            std::array<double, 4> q_true{}, q_est{};
            std::array<double, 6> l{};
            for (std::size_t i = 0; i < 4; ++i) {
                q_true[i] = read(system, k.a[i]);
                q_est[i] = read(system, k.b[i]);
            }
            for (std::size_t i = 0; i < 6; ++i) l[i] = read(system, k.covariance[i]);
            // NaN for a zero factor (the filter not running): no sample.
            value = 3.0 * analysis::normalized_error_per_dof(analysis::attitude_error_vector(q_true, q_est), l);
        } else {
            double a[4], b[4];
            for (std::size_t i = 0; i < k.a.size(); ++i) {
                a[i] = read(system, k.a[i]);
                b[i] = read(system, k.b[i]);
            }
            value = m.kind == MetricKind::quaternion_angle ? analysis::attitude_error_degrees(a, b)
                                                           : analysis::vector_angle_degrees(a, b);
        }
        if (!std::isfinite(value)) continue;  // a zero vector or quaternion has no angle
        if (k.values.size() == max_metric_samples)
            throw CampaignError("metric " + m.name + ": more than " + std::to_string(max_metric_samples) +
                                " samples in one run (max_metric_samples): sample less often (output_interval, when)");
        k.values.push_back(value);
    }
}

std::vector<std::string> MetricObserver::cells() const {
    std::vector<std::string> out;
    for (const auto& k : tracked_) {
        if (k.detection) {
            const Metric& m = *k.metric;
            const DetectionOutcome o =
                k.detection->outcome(onset_value_, k.expected, m.after, m.period, observable_at_);
            for (double x : {o.detected, o.time, o.isolated, o.declared, o.before, o.orbits})
                out.push_back(cosim::format_real(x));
            out.push_back(o.which);
            if (reports_observable(m))
                for (double x : {o.observable, o.time_observable}) out.push_back(cosim::format_real(x));
            continue;
        }
        for (const auto& s : k.metric->stats) out.push_back(cosim::format_real(statistic(s, k.values)));
    }
    return out;
}

}  // namespace campaign
