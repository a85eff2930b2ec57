#include "analysis/couplings.hpp"

#include <cmath>
#include <optional>
#include <ostream>

#include "engine/cosim_error.hpp"
#include "engine/value_text.hpp"
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

// The truth's orbit: its mean radius (m), where it comes from, and its period (s).
struct TruthOrbit {
    double radius, period;
    std::string source;
};

std::optional<TruthOrbit> truth_orbit(const cosim::System& s, std::size_t env) {
    const std::string name = s.components()[env].name;
    if (item(s, env, "orbit_model") == "tle") {
        const auto line1 = s.initial_value(env, "tle_line1"), line2 = s.initial_value(env, "tle_line2");
        if (!line1 || !line2) return std::nullopt;
        try {
            // As the environment propagates it: SGP4's mean semi-major axis and period at epoch.
            orbit::Sgp4<double> sgp4;
            if (sgp4.initialize(orbit::parse_tle(*line1, *line2).mean_elements<double>()) != orbit::Sgp4Status::ok)
                return std::nullopt;
            return TruthOrbit{sgp4.semi_major_axis_km() * 1e3, sgp4.period_minutes() * 60.0,
                              name + "'s element set (SGP4 semi-major axis)"};
        } catch (const orbit::TleError&) {
            return std::nullopt;  // the environment refuses it at initialization, with the column
        }
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
        const auto truth = truth_orbit(system, env);
        if (!truth) continue;
        for (std::size_t e : ests) {
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
