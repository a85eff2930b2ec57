#include "detection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "engine/value_text.hpp"

namespace campaign {

namespace {
constexpr std::size_t none = static_cast<std::size_t>(-1);
}

DetectionTracker::DetectionTracker(std::vector<std::string> elements)
    : elements_(std::move(elements)), last_(elements_.size(), 0.0), open_(elements_.size(), none) {}

void DetectionTracker::sample(double t, const std::vector<double>& words, const std::vector<double>& times) {
    if (!first_t_) first_t_ = t;
    last_t_ = t;
    for (std::size_t i = 0; i < elements_.size(); ++i) {
        const double w = words[i];
        if (w != 0.0 && last_[i] == 0.0) {
            // A new declaration: at the time the system says it declared, else at this output point.
            const double at = i < times.size() && std::isfinite(times[i]) && times[i] >= 0.0 ? times[i] : t;
            open_[i] = declarations_.size();
            declarations_.push_back({i, at, w});
        } else if (w != 0.0) {
            declarations_[open_[i]].word = w;  // bits added to a standing declaration: the latest word
        } else {
            open_[i] = none;
        }
        last_[i] = w;
    }
}

DetectionOutcome DetectionTracker::outcome(std::optional<double> onset, const std::vector<std::size_t>& expected,
                                           double after, double period, std::optional<double> observable) const {
    DetectionOutcome o;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    o.time = o.observable = o.time_observable = nan;
    if (!first_t_) {
        o.detected = o.isolated = o.declared = o.before = o.orbits = nan;
        return o;
    }
    const double start = std::max({*first_t_, after, onset.value_or(-INFINITY)});
    std::vector<Declaration> counted;
    for (const auto& d : declarations_) {
        if (d.time < after) continue;
        if (d.time >= start)
            counted.push_back(d);
        else
            o.before += 1.0;
    }
    std::stable_sort(counted.begin(), counted.end(),
                     [](const Declaration& a, const Declaration& b) { return a.time < b.time; });
    o.declared = static_cast<double>(counted.size());
    o.detected = counted.empty() ? 0.0 : 1.0;
    if (onset && !counted.empty()) o.time = counted.front().time - *onset;
    if (onset && observable) {
        o.observable = *observable - *onset;
        if (!counted.empty()) o.time_observable = counted.front().time - *observable;
    }
    std::set<std::size_t> got, want(expected.begin(), expected.end());
    for (const auto& d : counted) {
        got.insert(d.element);
        o.which += (o.which.empty() ? "" : " ") + elements_[d.element] + "=" + cosim::format_real(d.word);
    }
    o.isolated = got == want ? 1.0 : 0.0;
    o.orbits = std::max(0.0, *last_t_ - start) / period;
    return o;
}

}  // namespace campaign
