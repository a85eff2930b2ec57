#include "analysis/couplings.hpp"

#include <cmath>
#include <optional>
#include <ostream>

#include "engine/cosim_error.hpp"
#include "engine/value_text.hpp"
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

// The truth's mean orbit radius and where it comes from.
std::optional<std::pair<double, std::string>> truth_orbit_radius(const cosim::System& s, std::size_t env) {
    const std::string name = s.components()[env].name;
    if (item(s, env, "orbit_model") == "tle") {
        const auto line1 = s.initial_value(env, "tle_line1"), line2 = s.initial_value(env, "tle_line2");
        if (!line1 || !line2) return std::nullopt;
        try {
            const orbit::Tle tle = orbit::parse_tle(*line1, *line2);
            const double n = tle.mean_motion_rev_per_day * 2.0 * M_PI / 86400.0;  // rad/s
            return std::pair{std::cbrt(earth_mu / (n * n)), name + "'s element set (semi-major axis)"};
        } catch (const orbit::TleError&) {
            return std::nullopt;  // the environment refuses it at initialization, with the column
        }
    }
    const auto altitude = real(s, env, "orbit_altitude");
    if (!altitude) return std::nullopt;
    return std::pair{earth_equatorial_radius + *altitude,
                     name + ".orbit_altitude " + cosim::format_real(*altitude / 1e3) + " km above 6378.137 km"};
}

}  // namespace

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
        const auto truth = truth_orbit_radius(system, env);
        if (!truth) continue;
        for (std::size_t e : ests) {
            const auto altitude = real(system, e, "orbit_altitude");
            if (!altitude) continue;
            const double radius = earth_mean_radius + *altitude;
            const double difference = radius - truth->first;
            if (std::abs(difference) <= max_orbit_radius_difference) continue;
            const double suggested = std::round((truth->first - earth_mean_radius) / 1e3);
            out.push_back(comps[e].name + ".orbit_altitude " + cosim::format_real(*altitude / 1e3) +
                          " km (an orbit radius of " + cosim::format_real(std::round(radius / 1e3)) +
                          " km over the computer's 6371 km Earth) is " +
                          cosim::format_real(std::round(std::abs(difference) / 1e3)) + " km off the truth's " +
                          cosim::format_real(std::round(truth->first / 1e3)) + " km (" + truth->second +
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
