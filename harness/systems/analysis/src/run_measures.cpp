#include "analysis/run_measures.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <sstream>

#include "analysis/derived_signals.hpp"
#include "analysis/json_text.hpp"
#include "engine/cosim_error.hpp"
#include "engine/name_hint.hpp"
#include "engine/system.hpp"

namespace analysis {

double error_percentile(std::vector<double> v, double p) {
    if (v.empty()) return std::nan("");
    std::sort(v.begin(), v.end());
    return v[static_cast<std::size_t>(p * static_cast<double>(v.size() - 1) + 0.5)];
}

namespace {

const std::vector<double>* column(const cosim::CsvTable& table, const std::string& name) {
    const auto i = table.find(name);
    return i ? &table.columns[*i] : nullptr;
}

std::vector<const std::vector<double>*> group(const cosim::CsvTable& table, const std::string& base, int n) {
    std::vector<const std::vector<double>*> out;
    for (int i = 1; i <= n; ++i) {
        const auto* c = column(table, base + "[" + std::to_string(i) + "]");
        if (!c) return {};
        out.push_back(c);
    }
    return out;
}

ErrorStats stats_of(const std::vector<double>& v) {
    return {v.size(), error_percentile(v, 0.5), error_percentile(v, 0.95)};
}

// One estimate's samples: time, error (deg), sunlit, ε (NaN without a covariance).
struct Sample {
    double t, error;
    bool sunlit;
    double nees;
};

SpanMeasures span(const std::vector<Sample>& samples, double from, bool with_covariance) {
    std::vector<double> all, sun, ecl;
    Consistency c;
    double nees_sum = 0.0;
    std::size_t covered = 0;
    for (const auto& s : samples) {
        if (s.t < from) continue;
        all.push_back(s.error);
        (s.sunlit ? sun : ecl).push_back(s.error);
        if (std::isfinite(s.nees)) {
            ++c.samples;
            nees_sum += s.nees;
            covered += s.nees <= chi2_3dof_99;
        }
    }
    SpanMeasures m{stats_of(all), stats_of(sun), stats_of(ecl), std::nullopt};
    if (with_covariance) {
        c.nees_per_dof = c.samples ? nees_sum / 3.0 / static_cast<double>(c.samples) : std::nan("");
        c.chi2_coverage =
            c.samples ? 100.0 * static_cast<double>(covered) / static_cast<double>(c.samples) : std::nan("");
        m.consistency = c;
    }
    return m;
}

std::string fmt(double x, const char* f = "%.3g") {
    if (!std::isfinite(x)) return "-";
    char buf[48];
    std::snprintf(buf, sizeof buf, f, x);
    return buf;
}

std::string time_text(double t) {
    return fmt(t, "%.6g") + " s";
}

void declarations(const cosim::CsvTable& table, RunMeasures& m) {
    if (table.rows() == 0) return;
    const std::size_t last = table.rows() - 1;
    const char* faces[] = {"+x", "-x", "+y", "-y", "+z", "-z"};
    const char* axes[] = {"x", "y", "z"};
    const auto add = [&](const std::string& word_base, const std::string& time_base, int n, const char* const* names,
                         const std::string& what) {
        const auto words = group(table, word_base, n);
        const auto times = group(table, time_base, n);
        if (times.empty()) return;
        for (int i = 0; i < n; ++i) {
            const double t = (*times[static_cast<std::size_t>(i)])[last];
            if (!(t >= 0.0)) continue;
            std::string text = what + " " + names[i];
            if (!words.empty())
                text += " (fault word " + fmt((*words[static_cast<std::size_t>(i)])[last], "%.0f") + ")";
            m.declarations.push_back({text, t});
        }
    };
    add("fault_face", "fault_face_time", 6, faces, "panel face");
    add("fault_mag_axis", "fault_mag_axis_time", 3, axes, "magnetometer axis");
    if (const auto* t = column(table, "fault_mag_norm_time"); t && (*t)[last] >= 0.0)
        m.declarations.push_back({"magnetometer field magnitude", (*t)[last]});
    std::sort(m.declarations.begin(), m.declarations.end(),
              [](const auto& a, const auto& b) { return a.time < b.time; });
}

// The onset columns `cosim run` wrote ("mag.fault_stuck_onset"): one injected fault each.
void onsets(const cosim::CsvTable& table, RunMeasures& m) {
    if (table.rows() == 0) return;
    const std::string head = "fault_", tail = "_onset";
    for (std::size_t i = 0; i < table.names.size(); ++i) {
        const std::string& name = table.names[i];
        const auto dot = name.rfind('.');
        const std::string variable = dot == std::string::npos ? name : name.substr(dot + 1);
        if (variable.size() <= head.size() + tail.size() || variable.rfind(head, 0) != 0 ||
            variable.compare(variable.size() - tail.size(), tail.size(), tail) != 0)
            continue;
        const double t = table.columns[i][0];
        if (!std::isfinite(t)) continue;
        m.injected.push_back({dot == std::string::npos ? std::string() : name.substr(0, dot),
                              variable.substr(head.size(), variable.size() - head.size() - tail.size()), "", t});
    }
    std::stable_sort(m.injected.begin(), m.injected.end(),
                     [](const auto& a, const auto& b) { return a.onset < b.onset; });
}

}  // namespace

RunMeasures measure_run(const cosim::CsvTable& table, const MeasureOptions& options) {
    RunMeasures m;
    const auto* time = column(table, "time");
    const auto q_true = group(table, "q_true", 4);
    const auto* irradiance = column(table, "irradiance");
    // Sunlit and eclipse split where the run has both (the seed's lab sun never sets: one phase, "all").
    m.phases = irradiance && std::any_of(irradiance->begin(), irradiance->end(), [](double e) { return e <= 0.0; }) &&
               std::any_of(irradiance->begin(), irradiance->end(), [](double e) { return e > 0.0; });
    if (time) declarations(table, m);
    onsets(table, m);
    if (!time || q_true.empty()) return m;
    const std::size_t n = time->size();

    struct Estimate {
        const char* column;
        const char* valid;
        const char* name;
        const char* key;
    };
    const Estimate kinds[] = {{"q_filt", "filter_valid", "filter q_filt", "filter"},
                              {"q_est", "valid", "single-frame q_est", "single_frame"}};
    std::vector<std::vector<Sample>> per_estimate;
    for (const auto& e : kinds) {
        const auto q = group(table, e.column, 4);
        if (q.empty()) continue;
        const auto* valid = column(table, e.valid);
        const bool filter = std::string(e.column) == "q_filt";
        const auto l = filter ? group(table, "attitude_cov_sqrt", 6) : std::vector<const std::vector<double>*>{};
        EstimateMeasures em;
        em.name = e.name;
        em.key = e.key;
        std::vector<Sample> samples;
        for (std::size_t r = 0; r < n; ++r) {
            bool changed = r == 0;
            for (const auto* c : q) changed = changed || (*c)[r] != (*c)[r - 1];
            if (!changed || (valid && !((*valid)[r] > 0.5))) continue;
            const auto d = attitude_error_vector({(*q_true[0])[r], (*q_true[1])[r], (*q_true[2])[r], (*q_true[3])[r]},
                                                 {(*q[0])[r], (*q[1])[r], (*q[2])[r], (*q[3])[r]});
            const double error = std::hypot(d[0], d[1], d[2]) * 180.0 / std::numbers::pi;
            if (!std::isfinite(error)) continue;
            double nees = std::nan("");
            if (!l.empty())
                nees = 3.0 * normalized_error_per_dof(
                                 d, {(*l[0])[r], (*l[1])[r], (*l[2])[r], (*l[3])[r], (*l[4])[r], (*l[5])[r]});
            samples.push_back({(*time)[r], error, !irradiance || (*irradiance)[r] > 0.0, nees});
        }
        if (samples.empty()) continue;
        em.first_valid = samples.front().t;
        em.overall = span(samples, -INFINITY, !l.empty());
        m.estimates.push_back(em);
        per_estimate.push_back(std::move(samples));
    }

    // The sun vector: at the samples where sun_meas changed while sun_valid (unit vectors: the angle).
    const auto sun_true = group(table, "sun_body", 3), sun_meas = group(table, "sun_meas", 3);
    std::vector<Sample> sun_samples;
    if (!sun_true.empty() && !sun_meas.empty()) {
        const auto* sun_valid = column(table, "sun_valid");
        for (std::size_t r = 0; r < n; ++r) {
            bool changed = r == 0;
            for (const auto* c : sun_meas) changed = changed || (*c)[r] != (*c)[r - 1];
            if (!changed || (sun_valid && !((*sun_valid)[r] > 0.5))) continue;
            double dot = 0.0, na = 0.0, nb = 0.0;
            for (std::size_t i = 0; i < 3; ++i) {
                const double a = (*sun_true[i])[r], b = (*sun_meas[i])[r];
                dot += a * b;
                na += a * a;
                nb += b * b;
            }
            if (!(na > 0.0 && nb > 0.0)) continue;
            // atan2 of |a x b| and a.b: accurate at small angles, where acos of a rounded cosine is not.
            const double cx = (*sun_true[1])[r] * (*sun_meas[2])[r] - (*sun_true[2])[r] * (*sun_meas[1])[r];
            const double cy = (*sun_true[2])[r] * (*sun_meas[0])[r] - (*sun_true[0])[r] * (*sun_meas[2])[r];
            const double cz = (*sun_true[0])[r] * (*sun_meas[1])[r] - (*sun_true[1])[r] * (*sun_meas[0])[r];
            const double angle = std::atan2(std::hypot(cx, cy, cz), dot) * 180.0 / std::numbers::pi;
            if (!std::isfinite(angle)) continue;
            sun_samples.push_back({(*time)[r], angle, !irradiance || (*irradiance)[r] > 0.0, std::nan("")});
        }
        if (!sun_samples.empty()) {
            EstimateMeasures em;
            em.name = "sun vector sun_meas";
            em.key = "sun_vector";
            em.first_valid = sun_samples.front().t;
            em.overall = span(sun_samples, -INFINITY, false);
            m.sun_vectors.push_back(em);
        }
    }

    // After convergence: as declared, else the first sample where the filter is valid with the in-flight
    // calibration applied (before it, the field carries the spacecraft's own hard iron).
    const auto* filter_valid = column(table, "filter_valid");
    const auto* calibrated = column(table, "mag_cal_valid");
    if (options.converged_after) {
        m.converged_from = *options.converged_after;
        m.converged_because = "as the system declares (convergedAfter)";
    } else if (filter_valid && calibrated) {
        for (std::size_t r = 0; r < n; ++r)
            if ((*filter_valid)[r] > 0.5 && (*calibrated)[r] > 0.5) {
                m.converged_from = (*time)[r];
                m.converged_because = "the filter valid and the magnetometer calibration applied";
                break;
            }
    }
    if (m.converged_from && n > 0 && *m.converged_from < time->back())
        for (std::size_t i = 0; i < m.estimates.size(); ++i) {
            const bool cov = m.estimates[i].overall.consistency.has_value();
            m.estimates[i].converged = span(per_estimate[i], *m.converged_from, cov);
        }
    if (m.converged_from && !sun_samples.empty() && *m.converged_from < time->back())
        m.sun_vectors.front().converged = span(sun_samples, *m.converged_from, false);

    // Why the filter was not valid from the start: its own 3σ bound, and the calibration's moment.
    const auto* bound = column(table, "attitude_bound");
    const auto l11 = column(table, "attitude_cov_sqrt[1]");
    if (filter_valid && bound && l11 && n > 0) {
        std::optional<std::size_t> running, valid;
        for (std::size_t r = 0; r < n; ++r) {
            if (!running && (*l11)[r] > 0.0) running = r;
            if (!valid && (*filter_valid)[r] > 0.5) valid = r;
        }
        std::optional<double> calibration;
        if (calibrated)
            for (std::size_t r = 0; r < n; ++r)
                if ((*calibrated)[r] > 0.5) {
                    calibration = (*time)[r];
                    break;
                }
        const auto deg = [&](std::size_t r) { return fmt((*bound)[r] * 180.0 / std::numbers::pi) + "°"; };
        std::ostringstream why;
        // A covariance factor zero throughout is a filter that is off (filter = none, the seed): nothing to
        // explain.
        if (!running) {
        } else if (!valid) {
            why << "the filter never became valid: its 3σ bound was " << deg(*running) << " at "
                << time_text((*time)[*running]) << " and " << deg(n - 1) << " at the end, above its validity limit";
        } else if ((*time)[*valid] > (*time)[0]) {
            why << "the filter was not valid until " << time_text((*time)[*valid]) << ": its 3σ bound came down from "
                << deg(*running) << " at " << time_text((*time)[*running]) << " to " << deg(*valid)
                << " (below its validity limit)";
        }
        if (!why.str().empty() && calibrated)
            why << (calibration ? "; the magnetometer calibration applied at " + time_text(*calibration)
                                : std::string("; the magnetometer calibration never applied"));
        m.not_valid_reason = why.str();
    }
    return m;
}

namespace {

void print_span(const SpanMeasures& s, bool phases, std::ostream& out) {
    const auto one = [&](const char* what, const ErrorStats& e) {
        if (e.samples == 0)
            out << what << " no samples";
        else
            out << what << " " << fmt(e.median) << "° / " << fmt(e.p95) << "° (" << e.samples << ")";
    };
    if (phases) {
        one("sunlit", s.sunlit);
        out << ", ";
        one("eclipse", s.eclipse);
    } else {
        one("all", s.all);
    }
    if (s.consistency)
        out << "; NEES/dof " << fmt(s.consistency->nees_per_dof) << ", χ²(3) 99 % coverage "
            << fmt(s.consistency->chi2_coverage, "%.1f") << " %";
    out << "\n";
}

}  // namespace

void print_measures(const RunMeasures& m, std::ostream& out) {
    print_measures(m, {}, {}, out);
}

void print_measures(const RunMeasures& m, const std::vector<FaultOnset>& injected,
                    const std::vector<std::string>& report, std::ostream& out) {
    const auto wants = [&](const char* item) {
        return report.empty() || std::find(report.begin(), report.end(), item) != report.end();
    };
    if (wants("attitude") && !m.estimates.empty()) {
        out << "attitude error, median / p95 (samples)" << (m.phases ? ", sunlit and in eclipse" : "") << ":\n";
        for (auto e : m.estimates) {
            if (!wants("consistency")) {
                e.overall.consistency.reset();
                if (e.converged) e.converged->consistency.reset();
            }
            out << "  " << e.name << ", whole run: ";
            print_span(e.overall, m.phases, out);
            if (e.converged) {
                out << "  " << e.name << ", from " << time_text(*m.converged_from) << ": ";
                print_span(*e.converged, m.phases, out);
            }
        }
        if (m.converged_from) out << "  (from " << time_text(*m.converged_from) << ": " << m.converged_because << ")\n";
    }
    // The sun vector only where the system names it (print_measures(m, out), without a report, prints what
    // leo_orbit declares: pvatt.analysis.report's lines are those of its `cosim run`).
    if (std::find(report.begin(), report.end(), "sun_vector") != report.end() && !m.sun_vectors.empty()) {
        out << "sun vector error, median / p95 (samples)" << (m.phases ? ", sunlit and in eclipse" : "") << ":\n";
        for (const auto& e : m.sun_vectors) {
            out << "  " << e.name << ", whole run: ";
            print_span(e.overall, m.phases, out);
            if (e.converged) {
                out << "  " << e.name << ", from " << time_text(*m.converged_from) << ": ";
                print_span(*e.converged, m.phases, out);
            }
        }
    }
    if (wants("first_valid")) {
        for (const auto& e : m.estimates)
            if (e.first_valid) out << e.name << " first valid at " << time_text(*e.first_valid) << "\n";
        if (!m.not_valid_reason.empty()) out << m.not_valid_reason << "\n";
    }
    if (wants("faults")) {
        RunMeasures with = m;
        with.injected = injected;
        for (const auto& line : fault_lines(with)) out << line << "\n";
    }
}

std::vector<std::string> fault_lines(const RunMeasures& m) {
    std::vector<std::string> out;
    const auto name = [](const FaultOnset& f) { return (f.component.empty() ? "" : f.component + " ") + f.group; };
    for (const auto& f : m.injected)
        out.push_back("fault injected: " + name(f) + (f.settings.empty() ? "" : " (" + f.settings + ")") + " from " +
                      time_text(f.onset));
    for (const auto& d : m.declarations) {
        std::string line = "fault declared: " + d.what + " at " + time_text(d.time);
        const FaultOnset* cause = nullptr;  // the latest onset at or before the declaration
        for (const auto& f : m.injected)
            if (f.onset <= d.time && (!cause || f.onset >= cause->onset)) cause = &f;
        if (cause) line += ", " + time_text(d.time - cause->onset) + " after the onset of " + name(*cause);
        out.push_back(line);
    }
    if (!m.injected.empty() && m.declarations.empty()) out.push_back("no fault declared by the on-board computer");
    return out;
}

std::vector<std::string> onset_columns(const std::vector<FaultOnset>& injected) {
    std::vector<std::string> out;
    for (const auto& f : injected) out.push_back(f.component + ".fault_" + f.group + "_onset");
    return out;
}

namespace {

// Each measure column with how a run's value is found: the estimate's key, and what to take of it.
struct MeasureColumn {
    std::string name, key;
    std::function<double(const EstimateMeasures&)> value;
};

std::vector<MeasureColumn> measure_table(const std::vector<std::string>& report) {
    const auto wants = [&](const char* item) {
        return report.empty() || std::find(report.begin(), report.end(), item) != report.end();
    };
    std::vector<MeasureColumn> out;
    const auto spans = [&](const std::string& key) {
        for (const char* span_name : {"run", "converged"}) {
            const bool converged = std::string(span_name) == "converged";
            for (const char* phase : {"all", "sunlit", "eclipse"})
                for (const char* stat : {"p50", "p95"}) {
                    const std::string ph = phase, st = stat;
                    out.push_back(
                        {"measure." + key + "." + span_name + "." + ph + "." + st, key, [=](const EstimateMeasures& e) {
                             if (converged && !e.converged) return std::nan("");
                             const SpanMeasures& s = converged ? *e.converged : e.overall;
                             const ErrorStats& x = ph == "all" ? s.all : ph == "sunlit" ? s.sunlit : s.eclipse;
                             if (x.samples == 0) return std::nan("");
                             return st == "p50" ? x.median : x.p95;
                         }});
                }
        }
    };
    if (wants("attitude"))
        for (const char* key : {"filter", "single_frame"}) spans(key);
    if (wants("sun_vector")) spans("sun_vector");
    if (wants("consistency"))
        for (const char* span_name : {"run", "converged"})
            for (const char* what : {"nees_per_dof", "chi2_99"}) {
                const bool converged = std::string(span_name) == "converged",
                           nees = std::string(what) == "nees_per_dof";
                out.push_back(
                    {std::string("measure.filter.") + span_name + "." + what, "filter", [=](const EstimateMeasures& e) {
                         if (converged && !e.converged) return std::nan("");
                         const auto& c = (converged ? *e.converged : e.overall).consistency;
                         if (!c || c->samples == 0) return std::nan("");
                         return nees ? c->nees_per_dof : c->chi2_coverage;
                     }});
            }
    if (wants("first_valid"))
        for (const char* key : {"filter", "single_frame", "sun_vector"})
            if (std::string(key) != "sun_vector" || wants("sun_vector"))
                out.push_back({std::string("measure.") + key + ".first_valid", key, [](const EstimateMeasures& e) {
                                   return e.first_valid ? *e.first_valid : std::nan("");
                               }});
    return out;
}

}  // namespace

std::vector<std::string> measure_columns(const std::vector<std::string>& report) {
    std::vector<std::string> out;
    for (const auto& c : measure_table(report)) out.push_back(c.name);
    return out;
}

std::vector<double> measure_values(const RunMeasures& m, const std::vector<std::string>& report) {
    std::vector<double> out;
    for (const auto& c : measure_table(report)) {
        double v = std::nan("");
        for (const auto* list : {&m.estimates, &m.sun_vectors})
            for (const auto& e : *list)
                if (e.key == c.key) v = c.value(e);
        out.push_back(v);
    }
    return out;
}

void check_measure_names(const std::vector<std::string>& report, const std::string& where) {
    for (const auto& r : report)
        if (std::find(measure_names.begin(), measure_names.end(), r) == measure_names.end()) {
            std::string known;
            for (const auto& n : measure_names) known += (known.empty() ? "" : ", ") + n;
            throw cosim::CosimError(where + ": <ex:Measures report> names '" + r + "', not a measure" +
                                    cosim::name_hint(r, measure_names) + " (known: " + known + ")");
        }
}

std::vector<FaultOnset> fault_onsets(const cosim::System& system) {
    std::vector<FaultOnset> out;
    for (std::size_t ci = 0; ci < system.components().size(); ++ci) {
        const auto& c = system.components()[ci];
        const auto& variables = c.description().model_variables;
        for (const auto& onset : variables) {
            const std::string& n = onset.name;
            const std::string suffix = "_onset";
            if (onset.causality != fmi_loader::Causality::parameter || n.rfind("fault_", 0) != 0 ||
                n.size() <= suffix.size() + 6 || n.compare(n.size() - suffix.size(), suffix.size(), suffix) != 0)
                continue;
            const std::string prefix = n.substr(0, n.size() - suffix.size() + 1);  // "fault_stuck_"
            FaultOnset f{c.name, prefix.substr(6, prefix.size() - 7), "", 0.0};
            for (const auto& v : variables) {
                if (v.causality != fmi_loader::Causality::parameter || v.name.rfind(prefix, 0) != 0 || v.name == n ||
                    v.name == prefix + "end")
                    continue;
                const std::string now = system.initial_value(ci, v.name).value_or("");
                bool differs = false;
                if (v.type == fmi_loader::VariableType::string) {
                    differs = now != v.start.value_or("");
                } else if (v.type == fmi_loader::VariableType::boolean) {
                    differs = (now == "1" || now == "true") != v.start_as_boolean().value_or(false);
                } else {
                    differs = std::strtod(now.c_str(), nullptr) != v.start_as_real().value_or(0.0);
                }
                if (differs) f.settings += (f.settings.empty() ? "" : ", ") + v.name + " = " + now;
            }
            if (f.settings.empty()) continue;
            f.onset = std::strtod(system.initial_value(ci, n).value_or("0").c_str(), nullptr);
            out.push_back(f);
        }
    }
    return out;
}

namespace {

std::string json_span(const SpanMeasures& s) {
    const auto stats = [](const ErrorStats& e) {
        return "{\"samples\": " + std::to_string(e.samples) + ", \"median\": " + json_number(e.median) +
               ", \"p95\": " + json_number(e.p95) + "}";
    };
    std::string out = "{\"all\": " + stats(s.all) + ", \"sunlit\": " + stats(s.sunlit) +
                      ", \"eclipse\": " + stats(s.eclipse) + ", \"consistency\": ";
    if (s.consistency)
        out += "{\"samples\": " + std::to_string(s.consistency->samples) +
               ", \"nees_per_dof\": " + json_number(s.consistency->nees_per_dof) +
               ", \"chi2_coverage\": " + json_number(s.consistency->chi2_coverage) + "}";
    else
        out += "null";
    return out + "}";
}

}  // namespace

std::string measures_json(const RunMeasures& m) {
    const auto list = [](const std::vector<EstimateMeasures>& estimates) {
        std::string out;
        for (std::size_t i = 0; i < estimates.size(); ++i) {
            const auto& e = estimates[i];
            out += std::string(i ? ", " : "") + "{\"name\": " + json_string(e.name) +
                   ", \"first_valid\": " + (e.first_valid ? json_number(*e.first_valid) : "null") +
                   ", \"overall\": " + json_span(e.overall) +
                   ", \"converged\": " + (e.converged ? json_span(*e.converged) : "null") + "}";
        }
        return out;
    };
    std::string out = "{\"estimates\": [" + list(m.estimates) + "], \"sun_vectors\": [" + list(m.sun_vectors);
    out += "], \"converged_from\": " + (m.converged_from ? json_number(*m.converged_from) : std::string("null")) +
           ", \"converged_because\": " + json_string(m.converged_because) +
           ", \"not_valid_reason\": " + json_string(m.not_valid_reason) +
           ", \"phases\": " + (m.phases ? "true" : "false") + ", \"declarations\": [";
    for (std::size_t i = 0; i < m.declarations.size(); ++i)
        out += std::string(i ? ", " : "") + "{\"what\": " + json_string(m.declarations[i].what) +
               ", \"time\": " + json_number(m.declarations[i].time) + "}";
    out += "], \"injected\": [";
    for (std::size_t i = 0; i < m.injected.size(); ++i)
        out += std::string(i ? ", " : "") + "{\"component\": " + json_string(m.injected[i].component) +
               ", \"group\": " + json_string(m.injected[i].group) + ", \"onset\": " + json_number(m.injected[i].onset) +
               "}";
    return out + "]}";
}

// The text of a line in HTML (a fault's description may hold < or &).
static std::string html_text(const std::string& text) {
    std::string out;
    for (const char c : text) out += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
    return out;
}

std::string measures_html(const RunMeasures& m) {
    std::ostringstream h;
    if (!m.estimates.empty()) {
        h << "<h2>What the run reached</h2>\n<table><tr><th>estimate</th><th>span</th>";
        if (m.phases)
            h << "<th>sunlit median / p95 (deg)</th><th>eclipse median / p95 (deg)</th>";
        else
            h << "<th>median / p95 (deg)</th>";
        h << "<th>samples</th><th>NEES/dof</th><th>χ²(3) 99 % coverage</th></tr>\n";
        const auto row = [&](const std::string& name, const std::string& when, const SpanMeasures& s) {
            h << "<tr><td>" << name << "</td><td>" << when << "</td>";
            const auto cell = [&](const ErrorStats& e) {
                h << "<td>" << fmt(e.median) << " / " << fmt(e.p95) << "</td>";
            };
            if (m.phases) {
                cell(s.sunlit);
                cell(s.eclipse);
            } else {
                cell(s.all);
            }
            h << "<td>" << s.all.samples << "</td><td>" << (s.consistency ? fmt(s.consistency->nees_per_dof) : "")
              << "</td><td>" << (s.consistency ? fmt(s.consistency->chi2_coverage, "%.1f") + " %" : "")
              << "</td></tr>\n";
        };
        for (const auto* list : {&m.estimates, &m.sun_vectors})
            for (const auto& e : *list) {
                row(e.name, "whole run", e.overall);
                if (e.converged) row(e.name, "from " + time_text(*m.converged_from), *e.converged);
            }
        h << "</table>\n<p>Errors at each estimate's own samples while it is valid. NEES/dof is the mean of "
             "δθᵀP⁻¹δθ / 3 (1 when the filter's covariance is right); the χ²(3) 99 % coverage is the share of "
             "samples with δθᵀP⁻¹δθ ≤ 11.34 (99 % when it is right, less when it is overconfident).</p>\n<ul>\n";
        for (const auto& e : m.estimates)
            if (e.first_valid) h << "<li>" << e.name << " first valid at " << time_text(*e.first_valid) << "</li>\n";
        if (m.converged_from)
            h << "<li>converged from " << time_text(*m.converged_from) << ": " << m.converged_because << "</li>\n";
        if (!m.not_valid_reason.empty()) h << "<li>" << m.not_valid_reason << "</li>\n";
        h << "</ul>\n";
    }
    if (!m.declarations.empty() || !m.injected.empty()) {
        h << "<h2>Faults injected and declared</h2>\n<p>Onsets from the run's fault parameters (orange dotted "
             "lines on the figures), declarations by the on-board computer (red dashed lines).</p>\n<ul>\n";
        for (const auto& line : fault_lines(m)) h << "<li>" << html_text(line) << "</li>\n";
        h << "</ul>\n";
    }
    return h.str();
}

namespace {

// The variables measure_run reads (base names: an array's elements all match).
bool measured(const std::string& variable) {
    static const char* const names[] = {"q_true",
                                        "q_est",
                                        "valid",
                                        "q_filt",
                                        "filter_valid",
                                        "attitude_cov_sqrt",
                                        "attitude_bound",
                                        "irradiance",
                                        "mag_cal_valid",
                                        "sun_body",
                                        "sun_meas",
                                        "sun_valid",
                                        "fault_face",
                                        "fault_face_time",
                                        "fault_mag_axis",
                                        "fault_mag_axis_time",
                                        "fault_mag_norm_time"};
    const std::string base = variable.substr(0, variable.find('['));
    return std::find(std::begin(names), std::end(names), base) != std::end(names);
}

}  // namespace

MeasureRecorder::MeasureRecorder(const cosim::System& system) {
    table_.names.push_back("time");
    for (const auto& c : cosim::output_columns(system, {}))
        if (measured(c.variable->name)) {
            columns_.push_back(c);
            table_.names.push_back(system.components()[c.component].name + "." + c.variable->name);
        }
    table_.columns.resize(table_.names.size());
}

void MeasureRecorder::sample(double t, cosim::System& system) {
    if (columns_.empty()) return;
    table_.columns[0].push_back(t);
    for (std::size_t i = 0; i < columns_.size(); ++i) {
        const auto& c = columns_[i];
        auto& instance = *system.components()[c.component].instance;
        double v = std::nan("");
        switch (c.variable->type) {
            case fmi_loader::VariableType::real:
                v = instance.get_real(c.variable->value_reference);
                break;
            case fmi_loader::VariableType::integer:
            case fmi_loader::VariableType::enumeration:
                v = static_cast<double>(instance.get_integer(c.variable->value_reference));
                break;
            case fmi_loader::VariableType::boolean:
                v = instance.get_boolean(c.variable->value_reference) ? 1.0 : 0.0;
                break;
            case fmi_loader::VariableType::string:
                break;
        }
        table_.columns[i + 1].push_back(v);
    }
}

}  // namespace analysis
