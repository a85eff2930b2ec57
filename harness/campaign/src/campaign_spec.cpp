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

std::vector<SpecValue> value_list(const Context& cx, const toml::table& t, const std::string& where) {
    const auto& n = required(cx, t, "values", where);
    const auto* arr = n.as_array();
    if (!arr || arr->empty()) cx.fail(n, where + ": 'values' must be a non-empty array");
    std::vector<SpecValue> out;
    for (const auto& v : *arr) out.push_back(scalar(cx, v, where + ": each of 'values'"));
    return out;
}

Draw read_draw(const Context& cx, const toml::table& t, std::size_t index) {
    const std::string where = "draw " + std::to_string(index + 1);
    Draw d;
    const std::string kind = string(cx, required(cx, t, "kind", where), where + ": 'kind'");
    d.target = string(cx, required(cx, t, "target", where), where + ": 'target'");
    check_target(cx, t, d.target, where);
    auto range = [&](const char* lo, const char* hi, bool allow_equal) {
        d.min = number(cx, required(cx, t, lo, where), where + ": '" + lo + "'");
        d.max = number(cx, required(cx, t, hi, where), where + ": '" + hi + "'");
        if (allow_equal ? d.max < d.min : d.max <= d.min)
            cx.fail(t, where + ": '" + hi + "' must be " + (allow_equal ? "at least" : "above") + " '" + lo + "'");
        // A draw computes min + (max - min) u: the span must be a double too.
        if (!std::isfinite(d.max - d.min)) cx.fail(t, where + ": '" + hi + "' - '" + lo + "' overflows a double");
    };
    if (kind == "uniform") {
        only_keys(cx, t, where, {"kind", "target", "figure", "min", "max"});
        d.kind = DrawKind::uniform;
        range("min", "max", false);
    } else if (kind == "normal") {
        only_keys(cx, t, where, {"kind", "target", "figure", "mean", "sd", "min", "max"});
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
        only_keys(cx, t, where, {"kind", "target", "figure", "min", "max"});
        d.kind = DrawKind::integer;
        range("min", "max", true);
        if (d.min != std::floor(d.min) || d.max != std::floor(d.max) || d.min < -2147483648.0 || d.max > 2147483647.0)
            cx.fail(t, where + ": 'min' and 'max' must be 32-bit integers");
    } else if (kind == "choice") {
        only_keys(cx, t, where, {"kind", "target", "figure", "values", "weights"});
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
        only_keys(cx, t, where, {"kind", "target", "figure", "values"});
        d.kind = DrawKind::grid;
        d.values = value_list(cx, t, where);
    } else if (kind == "quaternion") {
        only_keys(cx, t, where, {"kind", "target", "figure"});
        d.kind = DrawKind::quaternion;
    } else if (kind == "tumble") {
        only_keys(cx, t, where, {"kind", "target", "figure", "min", "max"});
        d.kind = DrawKind::tumble;
        range("min", "max", true);
        if (d.min < 0.0) cx.fail(t, where + ": the rate range must not be negative");
    } else if (kind == "epoch") {
        only_keys(cx, t, where, {"kind", "target", "figure", "from", "to"});
        d.kind = DrawKind::epoch;
        d.epoch_from = epoch_seconds(cx, required(cx, t, "from", where), where + ": 'from'");
        d.epoch_to = epoch_seconds(cx, required(cx, t, "to", where), where + ": 'to'");
        if (d.epoch_to - d.epoch_from < 1e-3)
            cx.fail(t, where + ": 'to' must be after 'from' (epochs are drawn to the millisecond)");
    } else {
        cx.fail(t, where + ": unknown kind '" + kind +
                       "' (uniform, normal, integer, choice, grid, list, quaternion, tumble, epoch)");
    }
    if (const auto* f = t.get("figure")) {
        if (!f->is_boolean()) cx.fail(*f, where + ": 'figure' must be true or false");
        d.figure = *f->value<bool>();
    }
    return d;
}

bool valid_stat(const std::string& s) {
    static const std::set<std::string> plain = {"mean", "rms", "min", "max", "final", "count"};
    if (plain.contains(s)) return true;
    return percentile_of(s).has_value();
}

Metric read_metric(const Context& cx, const toml::table& t, std::size_t index) {
    const std::string where = "metric " + std::to_string(index + 1);
    only_keys(cx, t, where,
              {"name", "kind", "a", "b", "column", "valid", "when", "after", "condition", "stats", "figure_stat"});
    Metric m;
    m.name = string(cx, required(cx, t, "name", where), where + ": 'name'");
    if (m.name.empty() || m.name.find_first_of(",\"\n. ") != std::string::npos)
        cx.fail(t, where + ": 'name' must be non-empty without commas, quotes, dots or spaces");
    const std::string kind = string(cx, required(cx, t, "kind", where), where + ": 'kind'");
    if (kind == "quaternion_angle" || kind == "vector_angle") {
        m.kind = kind == "quaternion_angle" ? MetricKind::quaternion_angle : MetricKind::vector_angle;
        m.a = string(cx, required(cx, t, "a", where), where + ": 'a'");
        m.b = string(cx, required(cx, t, "b", where), where + ": 'b'");
        check_target(cx, t, m.a, where);
        check_target(cx, t, m.b, where);
        if (t.contains("column")) cx.fail(t, where + ": 'column' belongs to kind column");
        m.stats = {"mean", "p50", "p95", "max", "count"};
    } else if (kind == "column") {
        m.kind = MetricKind::column;
        m.a = string(cx, required(cx, t, "column", where), where + ": 'column'");
        check_target(cx, t, m.a, where);
        if (t.contains("a") || t.contains("b")) cx.fail(t, where + ": 'a' and 'b' belong to the angle kinds");
        m.stats = {"mean", "min", "max", "final"};
    } else {
        cx.fail(t, where + ": unknown kind '" + kind + "' (quaternion_angle, vector_angle, column)");
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
        // "component.variable OP number", blanks around OP: the samples a split (sunlit, eclipse) keeps.
        const std::string text = string(cx, *c, where + ": 'condition'");
        std::istringstream in(text);
        std::string column, op, value, rest;
        in >> column >> op >> value >> rest;
        static const std::set<std::string> ops = {"<", "<=", ">", ">=", "==", "!="};
        double x = 0.0;
        const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), x);
        if (column.empty() || !ops.contains(op) || value.empty() || ec != std::errc() ||
            end != value.data() + value.size() || !rest.empty() || !std::isfinite(x))
            cx.fail(*c, where +
                            ": 'condition' must be \"component.variable OP number\" with OP one of < <= > >= == != "
                            "(e.g. \"env.irradiance > 0\"), got '" +
                            text + "'");
        check_target(cx, *c, column, where + ": 'condition'");
        m.condition_column = column;
        m.condition_op = op;
        m.condition_value = x;
    }
    if (const auto* s = t.get("stats")) {
        const auto* arr = s->as_array();
        if (!arr || arr->empty()) cx.fail(*s, where + ": 'stats' must be a non-empty array of strings");
        m.stats.clear();
        for (const auto& x : *arr) {
            m.stats.push_back(string(cx, x, where + ": each of 'stats'"));
            if (!valid_stat(m.stats.back()))
                cx.fail(x,
                        where + ": unknown statistic '" + m.stats.back() +
                            "' (mean, rms, min, max, final, count, or a percentile p0 to p100 such as p95 or p99.9)");
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

std::filesystem::path relative_to(const std::filesystem::path& base, const std::string& p) {
    const std::filesystem::path path = p;
    return (path.is_absolute() ? path : base / path).lexically_normal();
}

}  // namespace

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
               "set", "draw", "metric"});
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
    if (const auto* n = root.get("output"))
        spec.output = string(cx, *n, "'output'");
    else
        spec.output = file.stem().string() + "_results";

    if (const auto* n = root.get("set")) {
        const auto* t = n->as_table();
        if (!t) cx.fail(*n, "[set] must be a table of \"component.variable\" = value");
        for (const auto& [key, value] : *t) {
            const std::string name(key.str());
            check_target(cx, value, name, "[set]");
            spec.settings.push_back(name + "=" + scalar(cx, value, "[set] " + name).text);
        }
    }
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
    std::set<std::string> targets, names;
    for (const auto& d : spec.draws)
        if (!targets.insert(d.target).second) cx.fail("'" + d.target + "' is drawn twice");
    for (const auto& m : spec.metrics)
        if (!names.insert(m.name).second) cx.fail("two metrics named '" + m.name + "'");
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
