// What the end-to-end tests share: a recorder of named variables at every output point and the columns
// every bundled system has.
#pragma once

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/execution.hpp"
#include "engine/system.hpp"

namespace e2e {

using cosim::System;

// Records the named Real variables ("component.variable") at every sample.
struct Recorder : cosim::Observer {
    std::vector<std::string> names;
    std::vector<std::pair<std::size_t, fmi2ValueReference>> refs;
    std::vector<double> time;
    std::map<std::string, std::vector<double>> values;
    Recorder(System& system, std::vector<std::string> columns) : names(std::move(columns)) {
        for (const auto& n : names) {
            const auto dot = n.find('.');
            const auto c = system.component_index(n.substr(0, dot));
            const auto* v = system.components()[c].description().find_variable(n.substr(dot + 1));
            if (!v) throw std::runtime_error("no variable " + n);
            refs.emplace_back(c, v->value_reference);
        }
    }
    void sample(double t, System& system) override {
        time.push_back(t);
        for (std::size_t i = 0; i < names.size(); ++i) {
            auto& inst = *system.components()[refs[i].first].instance;
            const auto* v = [&]() {
                const auto& md = system.components()[refs[i].first].description();
                for (const auto& var : md.model_variables)
                    if (var.value_reference == refs[i].second) return &var;
                return static_cast<const fmi_loader::ScalarVariable*>(nullptr);
            }();
            values[names[i]].push_back(v->type == fmi_loader::VariableType::real ? inst.get_real(refs[i].second)
                                                                                 : std::stod(inst.get_as_text(*v)));
        }
    }
    const std::vector<double>& operator[](const std::string& n) const { return values.at(n); }
};

inline std::vector<std::string> vec(const std::string& base, int n) {
    std::vector<std::string> out;
    for (int i = 1; i <= n; ++i) out.push_back(base + "[" + std::to_string(i) + "]");
    return out;
}

inline double angle_deg(const double a[3], const double b[3]) {
    const double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    const double na = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    const double nb = std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
    return std::acos(std::clamp(dot / (na * nb), -1.0, 1.0)) * 180.0 / std::numbers::pi;
}

struct Run {
    Recorder recorder;
    cosim::RunStatistics stats;
};

inline std::vector<std::string> columns() {
    std::vector<std::string> c;
    for (const auto& n : vec("sun_body", 3)) c.push_back("env." + n);
    for (const auto& n : vec("q_true", 4)) c.push_back("env." + n);
    c.push_back("env.irradiance");
    for (const auto& n : vec("sun_meas", 3)) c.push_back("est." + n);
    for (const auto& n : vec("q_est", 4)) c.push_back("est." + n);
    for (const auto& n : {"est.valid", "est.samples", "plant.v_bus", "plant.soc", "plant.i_batt"}) c.push_back(n);
    return c;
}

}  // namespace e2e
