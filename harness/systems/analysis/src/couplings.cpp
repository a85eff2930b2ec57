#include "analysis/couplings.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <ostream>

#include "engine/cosim_error.hpp"
#include "engine/value_text.hpp"
#include "orbit/calendar.hpp"
#include "orbit/element_age.hpp"
#include "orbit/element_plausibility.hpp"
#include "orbit/sgp4.hpp"
#include "orbit/tle.hpp"

namespace analysis {

namespace {

constexpr double earth_mean_radius = 6371e3;           // m: the estimator's albedo sphere (estimator_data.cpp)
constexpr double earth_equatorial_radius = 6378137.0;  // m: the environment's circular altitude is above it
constexpr double earth_mu = 3.986004418e14;            // m^3/s^2

std::string identifier(const cosim::Component& c) {
    const auto& md = c.description();
    if (md.model_exchange) return md.model_exchange->model_identifier;
    if (md.co_simulation) return md.co_simulation->model_identifier;
    return md.model_name;
}

// The run's value of an Enumeration as its item name (the number when the FMU names no such item).
std::optional<std::string> item(const cosim::System& s, std::size_t c, const std::string& variable) {
    const auto text = s.initial_value(c, variable);
    if (!text) return std::nullopt;
    const auto& md = s.components()[c].description();
    const auto* v = md.find_variable(variable);
    if (const auto* type = md.find_type(v->declared_type))
        for (const auto& i : type->items)
            if (std::to_string(i.value) == *text) return i.name;
    return text;
}

std::optional<double> real(const cosim::System& s, std::size_t c, const std::string& variable) {
    const auto text = s.initial_value(c, variable);
    if (!text) return std::nullopt;
    return cosim::parse_real(*text, s.components()[c].name + "." + variable);
}

std::optional<long> integer(const cosim::System& s, std::size_t c, const std::string& variable) {
    const auto text = s.initial_value(c, variable);
    if (!text) return std::nullopt;
    try {
        return std::stol(*text);
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

// A component's element set: its lines, or (both empty) its tle_elements[1..8]; nullopt when it has none
// or the block refuses it (the block says why, with the column, at initialization).
std::optional<orbit::Tle> element_set(const cosim::System& s, std::size_t c) {
    const auto line1 = s.initial_value(c, "tle_line1"), line2 = s.initial_value(c, "tle_line2");
    try {
        if ((line1 && !line1->empty()) || (line2 && !line2->empty()))
            return line1 && line2 ? std::optional<orbit::Tle>(orbit::parse_tle(*line1, *line2)) : std::nullopt;
        orbit::TleElements e{};
        for (std::size_t k = 0; k < e.size(); ++k) {
            const auto v = real(s, c, "tle_elements[" + std::to_string(k + 1) + "]");
            if (!v) return std::nullopt;
            e[k] = *v;
        }
        return orbit::checked_tle_from_elements(e);
    } catch (const std::invalid_argument&) {
        return std::nullopt;
    }
}

// A calendar instant of six parameters (prefix + _year ... _second) as a Julian date (UTC).
std::optional<double> instant(const cosim::System& s, std::size_t c, const std::string& prefix) {
    const auto year = integer(s, c, prefix + "_year"), month = integer(s, c, prefix + "_month"),
               day = integer(s, c, prefix + "_day"), hour = integer(s, c, prefix + "_hour"),
               minute = integer(s, c, prefix + "_minute");
    const auto second = real(s, c, prefix + "_second");
    if (!year || !month || !day || !hour || !minute || !second) return std::nullopt;
    return orbit::julian_date_at_midnight(static_cast<int>(*year), static_cast<int>(*month), static_cast<int>(*day)) +
           (static_cast<double>(*hour) * 3600.0 + static_cast<double>(*minute) * 60.0 + *second) / 86400.0;
}

// "est.clock_epoch_year=2026 est.clock_epoch_month=9 ..." for a Julian date.
std::string instant_settings(const std::string& prefix, double jd) {
    const double midnight = std::floor(jd - 0.5) + 0.5;
    const double seconds = std::round((jd - midnight) * 86400.0 * 1000.0) / 1000.0;
    const orbit::CalendarDay d = orbit::calendar_day(midnight + 0.25);
    const long whole = static_cast<long>(std::floor(seconds));
    return prefix + "_year=" + std::to_string(d.year) + " " + prefix + "_month=" + std::to_string(d.month) + " " +
           prefix + "_day=" + std::to_string(d.day) + " " + prefix + "_hour=" + std::to_string(whole / 3600) + " " +
           prefix + "_minute=" + std::to_string(whole / 60 % 60) + " " + prefix +
           "_second=" + cosim::format_real(seconds - static_cast<double>(whole / 60 * 60));
}

std::string elements_text(const orbit::Tle& t) {
    std::string out;
    for (double v : orbit::elements_of(t)) out += (out.empty() ? "" : ", ") + cosim::format_real(v);
    return "[" + out + "]";
}

// SGP4's TEME position (km) of a set at a Julian date; nullopt when it cannot propagate there.
std::optional<orbit::Vector3<double>> position_at(const orbit::Tle& t, double jd) {
    orbit::Sgp4<double> sgp4;
    if (sgp4.initialize(t.mean_elements<double>()) != orbit::Sgp4Status::ok) return std::nullopt;
    orbit::OrbitState<double> state;
    if (sgp4.propagate((jd - t.epoch_jd_utc) * 1440.0, state) != orbit::Sgp4Status::ok) return std::nullopt;
    return state.position_km;
}

// What the on-board computer with its own references (reference_source = onboard) must agree on with the
// truth: its clock, its set's epoch and its orbit at t = 0.
void check_uplink(const cosim::System& system, std::size_t env, std::size_t est, std::vector<std::string>& out) {
    const auto& comps = system.components();
    const std::string e = comps[est].name, t = comps[env].name;
    const auto truth_epoch = instant(system, env, "epoch");
    const auto clock_epoch = instant(system, est, "clock_epoch");
    if (!truth_epoch || !clock_epoch) return;
    const double offset = real(system, est, "clock_offset").value_or(0.0);
    const double clock = *clock_epoch + offset / 86400.0;
    const double clock_error = (clock - *truth_epoch) * 86400.0;
    if (std::abs(clock_error) > max_clock_difference) {
        out.push_back(e + "'s clock at t = 0 (clock_epoch_* + clock_offset) reads " + orbit::format_utc(clock) + ", " +
                      cosim::format_real(std::round(clock_error * 1000.0) / 1000.0) + " s from the truth's " +
                      orbit::format_utc(*truth_epoch) + " (" + t + ".epoch_*), more than the " +
                      cosim::format_real(max_clock_difference) + " s allowed (max_clock_difference; set " +
                      instant_settings(e + ".clock_epoch", *truth_epoch - offset / 86400.0) + ")");
        return;  // the set and the orbit below are compared at the computer's time: meaningless now
    }
    if (item(system, env, "orbit_model") != "tle") return;
    const auto truth = element_set(system, env);
    const auto given = element_set(system, est);
    if (!truth || !given) return;
    const double age_parameter = real(system, est, "uplink_age").value_or(0.0);
    const orbit::Tle onboard = age_parameter == 0.0 ? *given : orbit::older_set(*given, age_parameter);
    const double age_days = truth->epoch_jd_utc - onboard.epoch_jd_utc;
    // The values that agree: the truth's set, made older on board by the age it has now (within the bound).
    const double agreeing_age = std::clamp(age_days, 0.0, max_uplink_age_days) * 86400.0;
    const std::string fix = " (connect " + e + "'s set to the truth's and make it older with uplink_age: set " + e +
                            ".tle_elements=" + elements_text(*truth) + " and " + e +
                            ".uplink_age=" + cosim::format_real(std::round(agreeing_age)) + ")";
    if (std::abs(age_days) > max_uplink_age_days) {
        out.push_back(e + "'s element set (epoch " + orbit::format_utc(onboard.epoch_jd_utc) + ") is " +
                      cosim::format_real(std::round(std::abs(age_days) * 10.0) / 10.0) + " days " +
                      (age_days > 0 ? "older" : "newer") + " than the truth's (" + t + ", epoch " +
                      orbit::format_utc(truth->epoch_jd_utc) + "), more than the " +
                      cosim::format_real(max_uplink_age_days) + " days allowed (max_uplink_age_days)" + fix);
        return;
    }
    const auto r_truth = position_at(*truth, *truth_epoch), r_onboard = position_at(onboard, clock);
    if (!r_truth || !r_onboard) return;  // the blocks refuse it at initialization, with the reason
    const double distance = (*r_truth - *r_onboard).norm() * 1e3;
    if (distance > max_orbit_position_difference)
        out.push_back(e + "'s element set puts the satellite " + cosim::format_real(std::round(distance / 1e3)) +
                      " km from the truth's position at t = 0 (" + t + "'s set at " + orbit::format_utc(*truth_epoch) +
                      "), more than the " + cosim::format_real(max_orbit_position_difference / 1e3) +
                      " km allowed (max_orbit_position_difference; another satellite or orbit?)" + fix);
}

// The truth's orbit: its mean radius (m), where it comes from, and its period (s).
struct TruthOrbit {
    double radius, period;
    std::string source;
};

std::optional<TruthOrbit> truth_orbit(const cosim::System& s, std::size_t env) {
    const std::string name = s.components()[env].name;
    if (item(s, env, "orbit_model") == "tle") {
        const auto tle = element_set(s, env);  // nullopt: the environment refuses it at initialization
        if (!tle) return std::nullopt;
        // As the environment propagates it: SGP4's mean semi-major axis and period at epoch.
        orbit::Sgp4<double> sgp4;
        if (sgp4.initialize(tle->mean_elements<double>()) != orbit::Sgp4Status::ok) return std::nullopt;
        return TruthOrbit{sgp4.semi_major_axis_km() * 1e3, sgp4.period_minutes() * 60.0,
                          name + "'s element set (SGP4 semi-major axis)"};
    }
    const auto altitude = real(s, env, "orbit_altitude");
    if (!altitude) return std::nullopt;
    const double a = earth_equatorial_radius + *altitude;
    return TruthOrbit{a, 2.0 * M_PI * std::sqrt(a * a * a / earth_mu),
                      name + ".orbit_altitude " + cosim::format_real(*altitude / 1e3) + " km above 6378.137 km"};
}

std::optional<std::size_t> environment(const cosim::System& s) {
    for (std::size_t i = 0; i < s.components().size(); ++i)
        if (identifier(s.components()[i]) == "environment") return i;
    return std::nullopt;
}

}  // namespace

std::optional<double> truth_orbit_period(const cosim::System& system) {
    const auto env = environment(system);
    if (!env) return std::nullopt;
    const auto orbit = truth_orbit(system, *env);
    return orbit ? std::optional<double>(orbit->period) : std::nullopt;
}

std::optional<double> default_stop_time(const cosim::System& system) {
    const auto& d = system.description();
    if (!d.stop_orbits) return d.stop_time;
    const auto period = truth_orbit_period(system);
    if (!period)
        throw cosim::CosimError(d.file.string() + ": <Stop orbits=\"" + cosim::format_real(*d.stop_orbits) +
                                "\"/> but no environment orbit to derive the period from: give --stop-time");
    return d.start_time.value_or(0.0) + *d.stop_orbits * *period;
}

std::vector<std::string> coupling_mismatches(const cosim::System& system) {
    std::vector<std::size_t> envs, plants, ests;
    const auto& comps = system.components();
    for (std::size_t i = 0; i < comps.size(); ++i) {
        const std::string id = identifier(comps[i]);
        if (id == "environment") envs.push_back(i);
        if (id == "ssr_plant") plants.push_back(i);
        if (id == "attitude_estimator") ests.push_back(i);
    }
    std::vector<std::string> out;
    for (std::size_t p : plants) {
        const auto panels = item(system, p, "angular_response");
        if (!panels) continue;
        for (std::size_t e : ests) {
            const auto believed = item(system, e, "angular_response");
            if (believed && *believed != *panels)
                out.push_back(comps[e].name + ".angular_response is " + *believed + " but " + comps[p].name +
                              ".angular_response is " + *panels +
                              ": the computer inverts a response the panels do "
                              "not have (set " +
                              comps[e].name + ".angular_response=" + *panels + ")");
        }
        for (std::size_t e : envs) {
            const auto albedo_on = system.initial_value(e, "albedo_enabled");
            if (!albedo_on || (*albedo_on != "true" && *albedo_on != "1")) continue;
            const auto weighed = item(system, e, "albedo_response");
            if (weighed && *weighed != *panels)
                out.push_back(comps[e].name + ".albedo_response is " + *weighed + " but " + comps[p].name +
                              ".angular_response is " + *panels +
                              ": the albedo on each face is weighed with "
                              "another response than the panels' (set " +
                              comps[e].name + ".albedo_response=" + *panels + ")");
        }
    }
    for (std::size_t env : envs) {
        for (std::size_t e : ests)
            if (item(system, e, "reference_source") == "onboard") check_uplink(system, env, e, out);
        const auto truth = truth_orbit(system, env);
        if (!truth) continue;
        for (std::size_t e : ests) {
            // With its own references the computer takes its orbit radius from its element set, checked above.
            if (item(system, e, "reference_source") == "onboard") continue;
            const auto altitude = real(system, e, "orbit_altitude");
            if (!altitude) continue;
            const double radius = earth_mean_radius + *altitude;
            const double difference = radius - truth->radius;
            if (std::abs(difference) <= max_orbit_radius_difference) continue;
            const double suggested = std::round((truth->radius - earth_mean_radius) / 1e3);
            out.push_back(comps[e].name + ".orbit_altitude " + cosim::format_real(*altitude / 1e3) +
                          " km (an orbit radius of " + cosim::format_real(std::round(radius / 1e3)) +
                          " km over the computer's 6371 km Earth) is " +
                          cosim::format_real(std::round(std::abs(difference) / 1e3)) + " km off the truth's " +
                          cosim::format_real(std::round(truth->radius / 1e3)) + " km (" + truth->source +
                          "), more than the 20 km allowed (set " + comps[e].name +
                          ".orbit_altitude=" + cosim::format_real(suggested * 1e3) + ")");
        }
    }
    return out;
}

void check_couplings(const cosim::System& system, bool allow, std::ostream& warn) {
    const auto mismatches = coupling_mismatches(system);
    if (mismatches.empty()) return;
    if (allow) {
        for (const auto& m : mismatches) warn << "cosim: warning: " << m << "\n";
        return;
    }
    std::string text = system.description().file.string() + ": blocks that must agree do not";
    for (const auto& m : mismatches) text += "\n  " + m;
    text += "\n(give --allow-mismatch to run it anyway, e.g. to study the error it makes)";
    throw cosim::CosimError(text);
}

}  // namespace analysis
