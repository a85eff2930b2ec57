#include "campaign_spec.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "campaign_error.hpp"
#include "engine/setting.hpp"
#include "engine/value_text.hpp"
#include "metric_observer.hpp"
#include "statistics.hpp"

namespace campaign {

namespace {

// Errors name the spec file and the line of the entry at fault.
struct Context {
    std::string file;
    [[noreturn]] void fail(const toml::node& at, const std::string& what) const {
        throw CampaignError(file + ":" + std::to_string(at.source().begin.line) + ": " + what);
    }
    [[noreturn]] void fail(const std::string& what) const { throw CampaignError(file + ": " + what); }
};

void only_keys(const Context& cx, const toml::table& t, const std::string& where,
               const std::set<std::string>& allowed) {
    for (const auto& [key, node] : t)
        if (!allowed.contains(std::string(key.str())))
            cx.fail(node, where + ": unknown key '" + std::string(key.str()) + "'");
}

const toml::node& required(const Context& cx, const toml::table& t, const std::string& key, const std::string& where) {
    const toml::node* n = t.get(key);
    if (!n) cx.fail(t, where + ": '" + key + "' is missing");
    return *n;
}

double number(const Context& cx, const toml::node& n, const std::string& what) {
    if (auto v = n.value<double>(); v && (n.is_floating_point() || n.is_integer())) {
        if (!std::isfinite(*v)) cx.fail(n, what + " must be finite");
        return *v;
    }
    cx.fail(n, what + " must be a number");
}

std::string string(const Context& cx, const toml::node& n, const std::string& what) {
    if (auto v = n.value<std::string>(); v && n.is_string()) return *v;
    cx.fail(n, what + " must be a string");
}

SpecValue scalar(const Context& cx, const toml::node& n, const std::string& what) {
    SpecValue v;
    if (n.is_integer()) {
        v.text = std::to_string(*n.value<std::int64_t>());
        v.numeric = true;
        v.number = static_cast<double>(*n.value<std::int64_t>());
    } else if (n.is_floating_point()) {
        v.number = number(cx, n, what);
        v.text = cosim::format_real(v.number);
        v.numeric = true;
    } else if (n.is_boolean()) {
        v.text = *n.value<bool>() ? "true" : "false";
    } else if (n.is_string()) {
        v.text = *n.value<std::string>();
    } else {
        cx.fail(n, what + " must be a number, a Boolean or a string");
    }
    return v;
}

// Seconds since 1970-01-01T00:00:00 UTC of a TOML date, local date-time (taken as UTC) or offset date-time.
double epoch_seconds(const Context& cx, const toml::node& n, const std::string& what) {
    toml::date d;
    toml::time t{};
    int offset_minutes = 0;
    if (auto dt = n.value<toml::date_time>(); dt && n.is_date_time()) {
        d = dt->date;
        t = dt->time;
        if (dt->offset) offset_minutes = dt->offset->minutes;
    } else if (auto dd = n.value<toml::date>(); dd && n.is_date()) {
        d = *dd;
    } else {
        cx.fail(n, what + " must be a TOML date or date-time (2026-03-20T00:00:00Z)");
    }
    using namespace std::chrono;
    const year_month_day ymd{year{d.year}, month{d.month}, day{d.day}};
    if (!ymd.ok()) cx.fail(n, what + " is not a calendar date");
    const double days = sys_days{ymd}.time_since_epoch().count();
    return days * 86400.0 + t.hour * 3600.0 + t.minute * 60.0 + t.second + t.nanosecond * 1e-9 - offset_minutes * 60.0;
}

// "env.q0": a component and a variable (prefix), both non-empty.
void check_target(const Context& cx, const toml::node& at, const std::string& target, const std::string& what) {
    if (!cosim::split_variable_name(target) || target.find_first_of("=,\"\n") != std::string::npos)
        cx.fail(at, what + ": '" + target + "' is not component.variable");
}

// A name without a '.' (and nothing a setting would split on): a system parameter of the .ssd, or its prefix
// ("epoch" for epoch_year .. epoch_second), checked against the system when it loads (campaign_run.cpp).
bool system_parameter_name(const std::string& name) {
    return !name.empty() && name.find_first_of(".=,\"\n ") == std::string::npos;
}

// What a draw sets: component.variable (prefix), or a system parameter (prefix) set as `--set NAME=VALUE`
// sets it, for every component it feeds.
void check_draw_target(const Context& cx, const toml::node& at, const std::string& target, const std::string& what) {
    if (!system_parameter_name(target)) check_target(cx, at, target, what);
}

std::vector<SpecValue> value_list(const Context& cx, const toml::table& t, const std::string& where) {
    const auto& n = required(cx, t, "values", where);
    const auto* arr = n.as_array();
    if (!arr || arr->empty()) cx.fail(n, where + ": 'values' must be a non-empty array");
    std::vector<SpecValue> out;
    for (const auto& v : *arr) out.push_back(scalar(cx, v, where + ": each of 'values'"));
    return out;
}

// What a list names: plain words, component.variable columns, or what a draw sets (check_draw_target).
enum class Names { plain, variables, draw_targets };
std::vector<std::string> name_list(const Context& cx, const toml::node& n, const std::string& what,
                                   Names names = Names::variables);

Draw read_draw(const Context& cx, const toml::table& t, std::size_t index, const std::string& prefix = "") {
    const std::string where = prefix + "draw " + std::to_string(index + 1);
    Draw d;
    const std::string kind = string(cx, required(cx, t, "kind", where), where + ": 'kind'");
    d.target = string(cx, required(cx, t, "target", where), where + ": 'target'");
    check_draw_target(cx, t, d.target, where);
    auto range = [&](const char* lo, const char* hi, bool allow_equal) {
        d.min = number(cx, required(cx, t, lo, where), where + ": '" + lo + "'");
        d.max = number(cx, required(cx, t, hi, where), where + ": '" + hi + "'");
        if (allow_equal ? d.max < d.min : d.max <= d.min)
            cx.fail(t, where + ": '" + hi + "' must be " + (allow_equal ? "at least" : "above") + " '" + lo + "'");
        // A draw computes min + (max - min) u: the span must be a double too.
        if (!std::isfinite(d.max - d.min)) cx.fail(t, where + ": '" + hi + "' - '" + lo + "' overflows a double");
    };
    if (kind == "uniform") {
        only_keys(cx, t, where, {"kind", "target", "figure", "stream", "min", "max"});
        d.kind = DrawKind::uniform;
        range("min", "max", false);
    } else if (kind == "normal") {
        only_keys(cx, t, where, {"kind", "target", "figure", "stream", "mean", "sd", "min", "max"});
        d.kind = DrawKind::normal;
        d.mean = number(cx, required(cx, t, "mean", where), where + ": 'mean'");
        d.sd = number(cx, required(cx, t, "sd", where), where + ": 'sd'");
        if (d.sd <= 0.0) cx.fail(t, where + ": 'sd' must be positive");
        // Draws reach mean +- 40 sd at most (a 64-bit generator's tail): they must stay doubles.
        if (!std::isfinite(std::abs(d.mean) + 40.0 * d.sd))
            cx.fail(t, where + ": 'mean' and 'sd' give draws beyond the range of a double");
        d.truncated_below = t.contains("min");
        d.truncated_above = t.contains("max");
        d.min = d.truncated_below ? number(cx, *t.get("min"), where + ": 'min'") : -INFINITY;
        d.max = d.truncated_above ? number(cx, *t.get("max"), where + ": 'max'") : INFINITY;
        if (d.max <= d.min) cx.fail(t, where + ": 'max' must be above 'min'");
        const double mass = normal_mass(d.mean, d.sd, d.min, d.max);
        if (mass < min_truncated_normal_mass)
            cx.fail(t, where + ": the truncation interval holds " + std::to_string(mass) +
                           " of the normal distribution, below the limit " + std::to_string(min_truncated_normal_mass) +
                           " (use a uniform draw)");
    } else if (kind == "integer") {
        only_keys(cx, t, where, {"kind", "target", "figure", "stream", "min", "max"});
        d.kind = DrawKind::integer;
        range("min", "max", true);
        if (d.min != std::floor(d.min) || d.max != std::floor(d.max) || d.min < -2147483648.0 || d.max > 2147483647.0)
            cx.fail(t, where + ": 'min' and 'max' must be 32-bit integers");
    } else if (kind == "choice") {
        only_keys(cx, t, where, {"kind", "target", "figure", "stream", "values", "weights"});
        d.kind = DrawKind::choice;
        d.values = value_list(cx, t, where);
        if (const auto* w = t.get("weights")) {
            const auto* arr = w->as_array();
            if (!arr || arr->size() != d.values.size())
                cx.fail(*w, where + ": 'weights' must be an array as long as 'values'");
            for (const auto& x : *arr) {
                d.weights.push_back(number(cx, x, where + ": each weight"));
                if (d.weights.back() < 0.0) cx.fail(x, where + ": weights must not be negative");
            }
            double sum = 0.0;
            for (double x : d.weights) sum += x;
            if (sum <= 0.0) cx.fail(*w, where + ": the weights must not all be zero");
            if (!std::isfinite(sum)) cx.fail(*w, where + ": the weights' sum overflows a double");
        }
    } else if (kind == "grid" || kind == "list") {
        only_keys(cx, t, where, {"kind", "target", "figure", "stream", "values"});
        d.kind = DrawKind::grid;
        d.values = value_list(cx, t, where);
    } else if (kind == "quaternion") {
        only_keys(cx, t, where, {"kind", "target", "figure", "stream"});
        d.kind = DrawKind::quaternion;
    } else if (kind == "tumble") {
        only_keys(cx, t, where, {"kind", "target", "figure", "stream", "min", "max"});
        d.kind = DrawKind::tumble;
        range("min", "max", true);
        if (d.min < 0.0) cx.fail(t, where + ": the rate range must not be negative");
    } else if (kind == "epoch") {
        only_keys(cx, t, where, {"kind", "target", "figure", "stream", "from", "to", "clocks", "element_sets"});
        d.kind = DrawKind::epoch;
        d.epoch_from = epoch_seconds(cx, required(cx, t, "from", where), where + ": 'from'");
        d.epoch_to = epoch_seconds(cx, required(cx, t, "to", where), where + ": 'to'");
        if (d.epoch_to - d.epoch_from < 1e-3)
            cx.fail(t, where + ": 'to' must be after 'from' (epochs are drawn to the millisecond)");
        if (const auto* n = t.get("clocks")) d.clocks = name_list(cx, *n, where + ": 'clocks'", Names::draw_targets);
        if (const auto* n = t.get("element_sets"))
            d.element_sets = name_list(cx, *n, where + ": 'element_sets'", Names::draw_targets);
    } else if (kind == "orbit") {
        only_keys(cx, t, where,
                  {"kind", "target", "figure", "stream", "classes", "min_altitude", "max_altitude", "min_ltan",
                   "max_ltan", "copies"});
        d.kind = DrawKind::orbit;
        static const std::map<std::string, OrbitClass> classes = {{"sun_synchronous", OrbitClass::sun_synchronous},
                                                                  {"iss_like", OrbitClass::iss_like},
                                                                  {"polar", OrbitClass::polar},
                                                                  {"low_inclination", OrbitClass::low_inclination}};
        for (const auto& name : name_list(cx, required(cx, t, "classes", where), where + ": 'classes'", Names::plain)) {
            const auto it = classes.find(name);
            if (it == classes.end())
                cx.fail(t, where + ": unknown orbit class '" + name +
                               "' (sun_synchronous, iss_like, polar, low_inclination)");
            d.orbit_classes.push_back(it->second);
        }
        range("min_altitude", "max_altitude", true);
        d.altitude_min = d.min;
        d.altitude_max = d.max;
        if (d.altitude_min < orbit_min_altitude || d.altitude_max > orbit_max_altitude)
            cx.fail(t, where + ": the altitudes must lie within [" + cosim::format_real(orbit_min_altitude) + ", " +
                           cosim::format_real(orbit_max_altitude) + "] m (SGP4's near-Earth range, orbit_classes.hpp)");
        if (t.contains("min_ltan") || t.contains("max_ltan")) {
            range("min_ltan", "max_ltan", true);
            d.ltan_min = d.min;
            d.ltan_max = d.max;
            if (d.ltan_min < 0.0 || d.ltan_max > 24.0)
                cx.fail(t, where + ": the local times of the node must lie within [0, 24] h");
        }
        d.min = d.max = 0.0;
        if (const auto* n = t.get("copies")) d.copies = name_list(cx, *n, where + ": 'copies'", Names::draw_targets);
    } else {
        cx.fail(t, where + ": unknown kind '" + kind +
                       "' (uniform, normal, integer, choice, grid, list, quaternion, tumble, epoch, orbit)");
    }
    if (const auto* f = t.get("figure")) {
        if (!f->is_boolean()) cx.fail(*f, where + ": 'figure' must be true or false");
        d.figure = *f->value<bool>();
    }
    if (const auto* n = t.get("stream")) {
        d.stream = string(cx, *n, where + ": 'stream'");
        if (d.stream.empty()) cx.fail(*n, where + ": 'stream' must not be empty");
        if (d.kind == DrawKind::grid) cx.fail(*n, where + ": a grid draw is not random: it takes no 'stream'");
    }
    return d;
}

bool valid_stat(const std::string& s) {
    static const std::set<std::string> plain = {"mean", "rms", "min", "max", "final", "count", "per_dof", "chi2_99"};
    if (plain.contains(s)) return true;
    return percentile_of(s).has_value();
}

// A column or group name, or a non-empty array of them.
std::vector<std::string> name_list(const Context& cx, const toml::node& n, const std::string& what, Names names) {
    std::vector<std::string> out;
    if (n.is_string()) {
        out.push_back(string(cx, n, what));
    } else if (const auto* arr = n.as_array(); arr && !arr->empty()) {
        for (const auto& x : *arr) out.push_back(string(cx, x, what));
    } else {
        cx.fail(n, what + " must be a string or a non-empty array of strings");
    }
    for (std::size_t i = 0; i < out.size(); ++i) {
        if (names == Names::variables) check_target(cx, n, out[i], what);
        if (names == Names::draw_targets) check_draw_target(cx, n, out[i], what);
        for (std::size_t j = 0; j < i; ++j)
            if (out[i] == out[j]) cx.fail(n, what + ": '" + out[i] + "' listed twice");
    }
    return out;
}

// kind = "detection": fault words and their declaration times, compared per run with what the run's case
// expects (README.md of this folder).
Metric read_detection(const Context& cx, const toml::table& t, const std::string& where, Metric m) {
    only_keys(cx, t, where, {"name", "kind", "words", "times", "after", "period", "within"});
    m.kind = MetricKind::detection;
    m.words = name_list(cx, required(cx, t, "words", where), where + ": 'words'");
    if (const auto* n = t.get("times")) {
        m.times = name_list(cx, *n, where + ": 'times'");
        if (m.times.size() != m.words.size())
            cx.fail(*n, where + ": 'times' must name one column or group per entry of 'words'");
    }
    if (const auto* a = t.get("after")) m.after = number(cx, *a, where + ": 'after'");
    m.period = number(cx, required(cx, t, "period", where), where + ": 'period'");
    if (m.period <= 0.0) cx.fail(t, where + ": 'period' must be positive");
    m.within = 60.0;
    if (const auto* w = t.get("within")) m.within = number(cx, *w, where + ": 'within'");
    if (m.within <= 0.0) cx.fail(t, where + ": 'within' must be positive");
    m.stats = detection_cells;
    m.figure_stat = "time";
    return m;
}

// "component.variable OP number", blanks around OP: a metric's condition (the samples a split such as sunlit
// or eclipse keeps) or its after_first (the output point `after` counts from).
struct Comparison {
    std::string column, op;
    double value = 0.0;
};

Comparison read_comparison(const Context& cx, const toml::node& n, const std::string& where) {
    const std::string text = string(cx, n, where);
    std::istringstream in(text);
    std::string column, op, value, rest;
    in >> column >> op >> value >> rest;
    static const std::set<std::string> ops = {"<", "<=", ">", ">=", "==", "!="};
    double x = 0.0;
    const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), x);
    if (column.empty() || !ops.contains(op) || value.empty() || ec != std::errc() ||
        end != value.data() + value.size() || !rest.empty() || !std::isfinite(x))
        cx.fail(n, where +
                       " must be \"component.variable OP number\" with OP one of < <= > >= == != "
                       "(e.g. \"env.irradiance > 0\"), got '" +
                       text + "'");
    check_target(cx, n, column, where);
    return {column, op, x};
}

Metric read_metric(const Context& cx, const toml::table& t, std::size_t index) {
    const std::string where = "metric " + std::to_string(index + 1);
    Metric m;
    m.name = string(cx, required(cx, t, "name", where), where + ": 'name'");
    if (m.name.empty() || m.name.find_first_of(",\"\n. ") != std::string::npos)
        cx.fail(t, where + ": 'name' must be non-empty without commas, quotes, dots or spaces");
    const std::string kind = string(cx, required(cx, t, "kind", where), where + ": 'kind'");
    if (kind == "detection") return read_detection(cx, t, where, std::move(m));
    only_keys(cx, t, where,
              {"name", "kind", "a", "b", "column", "covariance", "valid", "when", "after", "after_first", "condition",
               "stats", "figure_stat"});
    if (kind == "quaternion_angle" || kind == "vector_angle") {
        m.kind = kind == "quaternion_angle" ? MetricKind::quaternion_angle : MetricKind::vector_angle;
        m.a = string(cx, required(cx, t, "a", where), where + ": 'a'");
        m.b = string(cx, required(cx, t, "b", where), where + ": 'b'");
        check_target(cx, t, m.a, where);
        check_target(cx, t, m.b, where);
        if (t.contains("column")) cx.fail(t, where + ": 'column' belongs to kind column");
        if (t.contains("covariance")) cx.fail(t, where + ": 'covariance' belongs to kind normalized_error");
        m.stats = {"mean", "p50", "p95", "max", "count"};
    } else if (kind == "normalized_error") {
        // The filter's consistency (issue 39): per sample dtheta' inv(P) dtheta, summarized as NEES per degree
        // of freedom and the share within chi2(3)'s 99 % point.
        m.kind = MetricKind::normalized_error;
        m.a = string(cx, required(cx, t, "a", where), where + ": 'a'");
        m.b = string(cx, required(cx, t, "b", where), where + ": 'b'");
        m.covariance = string(cx, required(cx, t, "covariance", where), where + ": 'covariance'");
        check_target(cx, t, m.a, where);
        check_target(cx, t, m.b, where);
        check_target(cx, t, m.covariance, where);
        if (t.contains("column")) cx.fail(t, where + ": 'column' belongs to kind column");
        m.stats = {"per_dof", "chi2_99", "count"};
    } else if (kind == "column") {
        m.kind = MetricKind::column;
        m.a = string(cx, required(cx, t, "column", where), where + ": 'column'");
        check_target(cx, t, m.a, where);
        if (t.contains("a") || t.contains("b")) cx.fail(t, where + ": 'a' and 'b' belong to the angle kinds");
        if (t.contains("covariance")) cx.fail(t, where + ": 'covariance' belongs to kind normalized_error");
        m.stats = {"mean", "min", "max", "final"};
    } else {
        cx.fail(t, where + ": unknown kind '" + kind +
                       "' (quaternion_angle, vector_angle, normalized_error, column, detection)");
    }
    if (const auto* v = t.get("valid")) {
        m.valid = string(cx, *v, where + ": 'valid'");
        check_target(cx, *v, m.valid, where + ": 'valid'");
    }
    if (const auto* w = t.get("when")) {
        m.when = string(cx, *w, where + ": 'when'");
        check_target(cx, *w, m.when, where + ": 'when'");
    }
    if (const auto* a = t.get("after")) m.after = number(cx, *a, where + ": 'after'");
    if (const auto* c = t.get("condition")) {
        const Comparison x = read_comparison(cx, *c, where + ": 'condition'");
        m.condition_column = x.column;
        m.condition_op = x.op;
        m.condition_value = x.value;
    }
    if (const auto* c = t.get("after_first")) {
        const Comparison x = read_comparison(cx, *c, where + ": 'after_first'");
        m.start_column = x.column;
        m.start_op = x.op;
        m.start_value = x.value;
    }
    if (const auto* s = t.get("stats")) {
        const auto* arr = s->as_array();
        if (!arr || arr->empty()) cx.fail(*s, where + ": 'stats' must be a non-empty array of strings");
        m.stats.clear();
        for (const auto& x : *arr) {
            m.stats.push_back(string(cx, x, where + ": each of 'stats'"));
            if (!valid_stat(m.stats.back()))
                cx.fail(
                    x, where + ": unknown statistic '" + m.stats.back() +
                           "' (mean, rms, min, max, final, count, per_dof, chi2_99, or a percentile p0 to p100 such as "
                           "p95 or p99.9)");
        }
    }
    for (std::size_t i = 0; i < m.stats.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (m.stats[i] == m.stats[j]) cx.fail(t, where + ": statistic '" + m.stats[i] + "' listed twice");
    if (const auto* f = t.get("figure_stat")) {
        m.figure_stat = string(cx, *f, where + ": 'figure_stat'");
        if (std::find(m.stats.begin(), m.stats.end(), m.figure_stat) == m.stats.end())
            cx.fail(*f, where + ": 'figure_stat' must be one of its 'stats'");
    } else {
        const bool has_p95 = std::find(m.stats.begin(), m.stats.end(), "p95") != m.stats.end();
        m.figure_stat = has_p95 ? "p95" : m.stats.front();
    }
    return m;
}

// "component.variable" = value entries of a [set] table, or name = value for a system parameter (a name
// without a '.', checked against the system when it loads).
std::vector<std::string> read_settings(const Context& cx, const toml::node& n, const std::string& where) {
    const auto* t = n.as_table();
    if (!t) cx.fail(n, where + " must be a table of \"component.variable\" = value");
    std::vector<std::string> out;
    for (const auto& [key, value] : *t) {
        const std::string name(key.str());
        if (!system_parameter_name(name)) check_target(cx, value, name, where);
        out.push_back(name + "=" + scalar(cx, value, where + " " + name).text);
    }
    return out;
}

// A case's observable = { column = "...", above = x } (or below): the column's braces each hold a variable.
Observable read_observable(const Context& cx, const toml::node& n, const std::string& where) {
    const auto* t = n.as_table();
    if (!t) cx.fail(n, where + " must be a table { column = \"component.variable\", above = number } (or below)");
    only_keys(cx, *t, where, {"column", "above", "below"});
    Observable o;
    o.column = string(cx, required(cx, *t, "column", where), where + ": 'column'");
    // Each {component.variable} checked, and the column with each replaced by an element number (1).
    for (std::size_t i = 0; i < o.column.size();) {
        const std::size_t open = o.column.find_first_of("{}", i);
        if (open == std::string::npos) break;
        const std::size_t close = o.column.find('}', open + 1);
        if (o.column[open] == '}' || close == std::string::npos || o.column.find('{', open + 1) < close)
            cx.fail(n, where + ": 'column' '" + o.column + "' has unbalanced braces");
        o.variables.push_back(o.column.substr(open + 1, close - open - 1));
        check_target(cx, n, o.variables.back(), where + ": 'column' {" + o.variables.back() + "}");
        i = close + 1;
    }
    check_target(cx, n, observable_column(o, std::vector<std::string>(o.variables.size(), "1")), where + ": 'column'");
    const auto* above = t->get("above");
    const auto* below = t->get("below");
    if ((above == nullptr) == (below == nullptr)) cx.fail(n, where + " takes one of 'above' and 'below'");
    o.above = above != nullptr;
    o.threshold = number(cx, above ? *above : *below, where + (above ? ": 'above'" : ": 'below'"));
    return o;
}

Case read_case(const Context& cx, const toml::table& t, std::size_t index) {
    const std::string numbered = "case " + std::to_string(index + 1);
    Case c;
    c.name = string(cx, required(cx, t, "name", numbered), numbered + ": 'name'");
    if (c.name.empty() || c.name.find_first_of(",\"\n ") != std::string::npos)
        cx.fail(t, numbered + ": 'name' must be non-empty without commas, quotes or spaces");
    const std::string where = "case '" + c.name + "'";
    only_keys(cx, t, where, {"name", "control", "set", "draw", "onset", "expect", "observable"});
    if (const auto* n = t.get("control")) {
        if (!n->is_boolean()) cx.fail(*n, where + ": 'control' must be true or false");
        c.control = *n->value<bool>();
    }
    if (const auto* n = t.get("set")) c.settings = read_settings(cx, *n, where + ": [case.set]");
    if (const auto* n = t.get("draw")) {
        const auto* arr = n->as_array();
        if (!arr || !arr->is_array_of_tables()) cx.fail(*n, where + ": its draws are written [[case.draw]]");
        for (std::size_t i = 0; i < arr->size(); ++i) {
            c.draws.push_back(read_draw(cx, *arr->get(i)->as_table(), i, where + ": "));
            if (c.draws.back().kind == DrawKind::grid)
                cx.fail(*arr->get(i), where + ": draw " + std::to_string(i + 1) +
                                          ": a case holds no grid draw (the cases are walked like a grid)");
        }
    }
    if (const auto* n = t.get("onset")) {
        c.onset = string(cx, *n, where + ": 'onset'");
        check_target(cx, *n, c.onset, where + ": 'onset'");
    }
    if (const auto* n = t.get("expect")) {
        const auto* table = n->as_table();
        if (!table) cx.fail(*n, where + ": 'expect' must be a table of \"words\" = element(s)");
        for (const auto& [key, value] : *table) {
            Expectation e;
            e.words = std::string(key.str());
            check_target(cx, value, e.words, where + ": 'expect'");
            const std::string what = where + ": 'expect' " + e.words;
            if (value.is_string()) {
                e.variable = string(cx, value, what);
                check_target(cx, value, e.variable, what);
            } else if (value.is_integer() || (value.is_array() && !value.as_array()->empty())) {
                auto element = [&](const toml::node& x) {
                    if (!x.is_integer() || *x.value<std::int64_t>() < 1 || *x.value<std::int64_t>() > 1'000'000)
                        cx.fail(x, what + ": elements are integers from 1 (the first of the group) to 1000000");
                    e.elements.push_back(static_cast<long>(*x.value<std::int64_t>()));
                };
                if (value.is_integer())
                    element(value);
                else
                    for (const auto& x : *value.as_array()) element(x);
            } else {
                cx.fail(value, what + " must be a variable's name, an element number or a non-empty array of them");
            }
            c.expect.push_back(std::move(e));
        }
    }
    if (const auto* n = t.get("observable")) c.observable = read_observable(cx, *n, where + ": 'observable'");
    if (c.control && (!c.onset.empty() || !c.expect.empty() || !c.observable.column.empty()))
        cx.fail(t, where + ": the control expects no fault: it takes no 'onset', 'expect' or 'observable'");
    if (!c.observable.column.empty() && c.onset.empty())
        cx.fail(t, where + ": 'observable' needs 'onset' (it is looked for from the fault's onset on)");
    if (!c.expect.empty() && c.onset.empty())
        cx.fail(t, where + ": 'expect' needs 'onset' (declarations count from the fault's onset)");
    return c;
}

// What no single table can check: names unique across cases, one control, a variable either set or
// drawn, expectations naming a detection metric's words.
void check_cases(const Context& cx, const CampaignSpec& spec) {
    std::set<std::string> names, top_drawn;
    for (const auto& d : spec.draws) top_drawn.insert(d.target);
    std::set<std::string> words;
    for (const auto& m : spec.metrics) words.insert(m.words.begin(), m.words.end());
    const Case* control = nullptr;
    for (const auto& c : spec.cases) {
        const std::string where = "case '" + c.name + "'";
        if (!names.insert(c.name).second) cx.fail("two cases named '" + c.name + "'");
        if (c.control) {
            if (control) cx.fail("cases '" + control->name + "' and '" + c.name + "' are both the control");
            control = &c;
        }
        std::set<std::string> drawn;
        for (const auto& d : c.draws) {
            if (top_drawn.contains(d.target))
                cx.fail(where + ": '" + d.target + "' is also drawn for every run (a [[draw]] of the spec)");
            if (!drawn.insert(d.target).second) cx.fail(where + ": '" + d.target + "' is drawn twice");
        }
        for (const auto& setting : c.settings) {
            const std::string variable = setting.substr(0, setting.find('='));
            if (drawn.contains(variable) || top_drawn.contains(variable))
                cx.fail(where + ": '" + variable + "' is both set by the case and drawn");
        }
        for (const auto& e : c.expect)
            if (!words.contains(e.words))
                cx.fail(where + ": 'expect' names '" + e.words + "', which is no detection metric's 'words'");
    }
}

std::filesystem::path relative_to(const std::filesystem::path& base, const std::string& p) {
    const std::filesystem::path path = p;
    return (path.is_absolute() ? path : base / path).lexically_normal();
}

// [[aim]]: column, and one of below, at_least, within; skip_empty.
Aim read_aim(const Context& cx, const toml::table& t, std::size_t index) {
    const std::string where = "aim " + std::to_string(index + 1);
    only_keys(cx, t, where, {"column", "below", "at_least", "within", "skip_empty"});
    Aim a;
    a.column = string(cx, required(cx, t, "column", where), where + ": 'column'");
    if (a.column.ends_with(".which"))
        cx.fail(t, where + ": '" + a.column + "' holds text (the declarations in order), not a number to judge");
    const int bounds = t.contains("below") + t.contains("at_least") + t.contains("within");
    if (bounds != 1) cx.fail(t, where + ": give exactly one of 'below', 'at_least' and 'within'");
    if (const auto* n = t.get("below")) {
        a.kind = AimKind::below;
        a.high = number(cx, *n, where + ": 'below'");
    } else if (const auto* n = t.get("at_least")) {
        a.kind = AimKind::at_least;
        a.low = number(cx, *n, where + ": 'at_least'");
    } else {
        const auto* w = t.get("within");
        const auto* arr = w->as_array();
        if (!arr || arr->size() != 2) cx.fail(*w, where + ": 'within' must be [low, high]");
        a.kind = AimKind::within;
        a.low = number(cx, *arr->get(0), where + ": 'within'");
        a.high = number(cx, *arr->get(1), where + ": 'within'");
        if (a.low > a.high) cx.fail(*w, where + ": 'within' must be [low, high] with low <= high");
    }
    if (const auto* n = t.get("skip_empty")) {
        if (!n->is_boolean()) cx.fail(*n, where + ": 'skip_empty' must be true or false");
        a.skip_empty = *n->value<bool>();
    }
    return a;
}

}  // namespace

std::string observable_column(const Observable& o, const std::vector<std::string>& values) {
    std::string out;
    std::size_t from = 0;
    for (const auto& v : values) {
        const std::size_t open = o.column.find('{', from);
        const std::size_t close = o.column.find('}', open);
        out += o.column.substr(from, open - from) + v;
        from = close + 1;
    }
    return out + o.column.substr(from);
}

CampaignSpec parse_spec(const std::string& text, const std::filesystem::path& file) {
    const Context cx{file.string()};
    toml::table root;
    try {
        root = toml::parse(text, file.string());
    } catch (const toml::parse_error& e) {
        throw CampaignError(file.string() + ":" + std::to_string(e.source().begin.line) + ": " +
                            std::string(e.description()));
    }
    only_keys(cx, root, "campaign",
              {"system", "stop_time", "output_interval", "tolerance", "runs", "seed", "paired", "fmu_dirs", "output",
               "parameters", "set", "draw", "metric", "case", "aim"});
    CampaignSpec spec;
    spec.file = file;
    const auto base = file.parent_path();
    spec.system = relative_to(base, string(cx, required(cx, root, "system", "campaign"), "'system'"));
    if (const auto* n = root.get("stop_time")) spec.stop_time = number(cx, *n, "'stop_time'");
    if (const auto* n = root.get("output_interval")) spec.output_interval = number(cx, *n, "'output_interval'");
    if (const auto* n = root.get("tolerance")) spec.tolerance = number(cx, *n, "'tolerance'");
    if (spec.output_interval && *spec.output_interval <= 0) cx.fail("'output_interval' must be positive");
    if (spec.tolerance && *spec.tolerance <= 0) cx.fail("'tolerance' must be positive");
    {
        const auto& n = required(cx, root, "runs", "campaign");
        if (!n.is_integer() || *n.value<std::int64_t>() < 1 || *n.value<std::int64_t>() > max_runs)
            cx.fail(n, "'runs' must be an integer from 1 to " + std::to_string(max_runs));
        spec.runs = static_cast<long>(*n.value<std::int64_t>());
    }
    {
        const auto& n = required(cx, root, "seed", "campaign");
        if (!n.is_integer() || *n.value<std::int64_t>() < 0) cx.fail(n, "'seed' must be a non-negative integer");
        spec.seed = static_cast<std::uint64_t>(*n.value<std::int64_t>());
    }
    if (const auto* n = root.get("paired")) {
        if (!n->is_boolean()) cx.fail(*n, "'paired' must be true or false");
        spec.paired = *n->value<bool>();
    }
    if (const auto* n = root.get("fmu_dirs")) {
        const auto* arr = n->as_array();
        if (!arr) cx.fail(*n, "'fmu_dirs' must be an array of strings");
        for (const auto& d : *arr) spec.fmu_dirs.push_back(relative_to(base, string(cx, d, "each of 'fmu_dirs'")));
    }
    if (const auto* n = root.get("parameters")) {
        const auto* arr = n->as_array();
        if (!arr) cx.fail(*n, "'parameters' must be an array of parameter files (.ssv), relative to the spec");
        for (const auto& f : *arr)
            spec.parameter_files.push_back(relative_to(base, string(cx, f, "each of 'parameters'")));
    }
    if (const auto* n = root.get("output"))
        spec.output = string(cx, *n, "'output'");
    else
        spec.output = file.stem().string() + "_results";

    if (const auto* n = root.get("set")) spec.settings = read_settings(cx, *n, "[set]");
    if (const auto* n = root.get("draw")) {
        const auto* arr = n->as_array();
        if (!arr || !arr->is_array_of_tables()) cx.fail(*n, "draws are written [[draw]]");
        for (std::size_t i = 0; i < arr->size(); ++i) spec.draws.push_back(read_draw(cx, *arr->get(i)->as_table(), i));
    }
    if (const auto* n = root.get("metric")) {
        const auto* arr = n->as_array();
        if (!arr || !arr->is_array_of_tables()) cx.fail(*n, "metrics are written [[metric]]");
        for (std::size_t i = 0; i < arr->size(); ++i)
            spec.metrics.push_back(read_metric(cx, *arr->get(i)->as_table(), i));
    }
    if (const auto* n = root.get("case")) {
        const auto* arr = n->as_array();
        if (!arr || !arr->is_array_of_tables()) cx.fail(*n, "cases are written [[case]]");
        for (std::size_t i = 0; i < arr->size(); ++i) spec.cases.push_back(read_case(cx, *arr->get(i)->as_table(), i));
        check_cases(cx, spec);
        // A case with an observable: every detection metric also reports the time from it.
        if (std::any_of(spec.cases.begin(), spec.cases.end(),
                        [](const Case& c) { return !c.observable.column.empty(); }))
            for (auto& m : spec.metrics)
                if (m.kind == MetricKind::detection)
                    m.stats.insert(m.stats.end(), observable_cells.begin(), observable_cells.end());
    }
    std::set<std::string> targets, names;
    for (const auto& d : spec.draws)
        if (!targets.insert(d.target).second) cx.fail("'" + d.target + "' is drawn twice");
    // The scenario's draws: one epoch and one orbit draw at most, no variable written by two of them (the
    // orbit draw makes its set at the epoch draw's date: the epoch draw must not re-epoch it too).
    std::set<std::string> scenario;
    for (DrawKind kind : {DrawKind::epoch, DrawKind::orbit})
        if (std::count_if(spec.draws.begin(), spec.draws.end(), [&](const Draw& d) { return d.kind == kind; }) > 1)
            cx.fail(std::string("more than one ") + (kind == DrawKind::epoch ? "epoch" : "orbit") +
                    " draw (one scenario date, one orbit)");
    for (const auto& d : spec.draws) {
        std::vector<std::string> written = d.clocks;
        written.insert(written.end(), d.element_sets.begin(), d.element_sets.end());
        written.insert(written.end(), d.copies.begin(), d.copies.end());
        if (d.kind == DrawKind::orbit || d.kind == DrawKind::epoch) written.push_back(d.target);
        for (const auto& w : written)
            if (!scenario.insert(w).second)
                cx.fail("'" + w +
                        "' is written by two draws (an orbit draw's set is made at the epoch draw's "
                        "date: leave it out of the epoch draw's element_sets)");
    }
    for (const auto& m : spec.metrics)
        if (!names.insert(m.name).second) cx.fail("two metrics named '" + m.name + "'");
    if (const auto* n = root.get("aim")) {
        const auto* arr = n->as_array();
        if (!arr || !arr->is_array_of_tables()) cx.fail(*n, "aims are written [[aim]]");
        for (std::size_t i = 0; i < arr->size(); ++i) spec.aims.push_back(read_aim(cx, *arr->get(i)->as_table(), i));
    }
    // A metric's column is known now; a measure.* column only once prepare() has read the system's measures.
    const auto columns = metric_columns(spec);
    for (std::size_t i = 0; i < spec.aims.size(); ++i)
        if (!spec.aims[i].column.starts_with("measure.") &&
            std::find(columns.begin(), columns.end(), spec.aims[i].column) == columns.end())
            cx.fail(*root.get("aim")->as_array()->get(i), "aim " + std::to_string(i + 1) + ": '" + spec.aims[i].column +
                                                              "' is not a metric's column (name.stat)");
    return spec;
}

CampaignSpec read_spec(const std::filesystem::path& file) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec))
        throw CampaignError("campaign spec " + file.string() + ": not a regular file");
    if (const auto size = std::filesystem::file_size(file, ec); !ec && size > max_spec_bytes)
        throw CampaignError("campaign spec " + file.string() + " is " + std::to_string(size) +
                            " bytes, more than the limit of " + std::to_string(max_spec_bytes) +
                            " bytes (max_spec_bytes)");
    std::ifstream in(file);
    if (!in) throw CampaignError("cannot read campaign spec " + file.string());
    std::stringstream text;
    text << in.rdbuf();
    if (in.bad()) throw CampaignError("cannot read campaign spec " + file.string());
    return parse_spec(text.str(), file);
}

}  // namespace campaign
