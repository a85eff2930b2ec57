#include "orbit/element_plausibility.hpp"

#include <cmath>
#include <cstdio>

#include "orbit/calendar.hpp"
#include "orbit/sgp4.hpp"

namespace orbit {

std::string format_utc(double jd_utc) {
    // Rounded to the millisecond first, so that 23:59:59.9999 becomes the next day's 00:00:00.000.
    const double midnight = std::floor(jd_utc - 0.5) + 0.5;
    const double ms = std::round((jd_utc - midnight) * 86'400'000.0);
    const CalendarDay d = calendar_day(midnight + std::floor(ms / 86'400'000.0) + 0.25);
    const long long rest = static_cast<long long>(ms) % 86'400'000;
    char text[64];
    std::snprintf(text, sizeof text, "%04d-%02d-%02d %02lld:%02lld:%06.3f UTC", d.year, d.month, d.day,
                  rest / 3'600'000, rest / 60'000 % 60, static_cast<double>(rest % 60'000) / 1000.0);
    return text;
}

std::string element_set_problem_at(const Tle& tle, double jd_utc, const std::string& what) {
    const double days = jd_utc - tle.epoch_jd_utc;
    const std::string sets = "the element set's epoch " + format_utc(tle.epoch_jd_utc);
    if (!(std::abs(days) <= kMaxElementSetAgeDays)) {
        char span[64];
        std::snprintf(span, sizeof span, "%.1f days", std::abs(days));
        return sets + " is " + span + (days > 0 ? " before " : " after ") + what + " " + format_utc(jd_utc) +
               ": more than the " + std::to_string(static_cast<int>(kMaxElementSetAgeDays)) +
               " days a set is used for (orbit::kMaxElementSetAgeDays; a wrong date or year?)";
    }
    Sgp4<double> sgp4;
    Sgp4Status status = sgp4.initialize(tle.mean_elements<double>());
    if (status == Sgp4Status::ok) {
        OrbitState<double> state;
        status = sgp4.propagate(days * 1440.0, state);
    }
    if (status != Sgp4Status::ok)
        return sets + " propagated to " + what + " " + format_utc(jd_utc) + ": " + describe(status);
    return {};
}

}  // namespace orbit
