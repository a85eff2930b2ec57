#include "draws.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "campaign_error.hpp"
#include "engine/value_text.hpp"
#include "orbit/calendar.hpp"
#include "orbit/element_age.hpp"
#include "orbit/orbit_classes.hpp"
#include "orbit/tle.hpp"
#include "random.hpp"

namespace campaign {

namespace {

using cosim::format_real;

std::uint64_t splitmix(std::uint64_t x) {
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

// Uniform in [0, 1) from the top 53 bits.
double unit(Random& rng) {
    return static_cast<double>(rng.next() >> 11) * 0x1.0p-53;
}

std::string element(const std::string& prefix, int i) {
    return prefix + "[" + std::to_string(i) + "]";
}

// "env.epoch" -> "env.epoch_year" ...
const char* const epoch_fields[] = {"_year", "_month", "_day", "_hour", "_minute", "_second"};

static_assert(orbit_min_altitude == orbit::kMinOrbitAltitudeKm * 1e3 &&
              orbit_max_altitude == orbit::kMaxOrbitAltitudeKm * 1e3);

constexpr double unix_epoch_jd = 2440587.5;  // 1970-01-01T00:00:00 UTC

// The epoch draw's instant: milliseconds since 1970 UTC.
std::int64_t epoch_ms(const Draw& d, Random& rng) {
    const auto from_ms = static_cast<std::int64_t>(std::llround(d.epoch_from * 1000.0));
    const auto span_ms = static_cast<std::int64_t>(std::llround((d.epoch_to - d.epoch_from) * 1000.0));
    const auto offset = static_cast<std::int64_t>(std::floor(unit(rng) * static_cast<double>(span_ms)));
    return from_ms + std::min(offset, span_ms - 1);
}

// "x[1]=...", ..., "x[8]=..." for an element-set array, into settings only.
void set_elements(const std::string& target, const orbit::Tle& tle, RunDraws& out) {
    const orbit::TleElements e = orbit::elements_of(tle);
    for (std::size_t k = 0; k < e.size(); ++k)
        out.settings.push_back(element(target, static_cast<int>(k + 1)) + "=" + format_real(e[k]));
}

orbit::Tle base_set(const Draw& d) {
    if (d.base_elements.size() != orbit::kTleElementCount)
        throw CampaignError(d.target +
                            ": the scenario's element set was not read from the system (read_scenario_base)");
    orbit::TleElements e{};
    std::copy(d.base_elements.begin(), d.base_elements.end(), e.begin());
    return orbit::tle_from_elements(e);
}

void add_epoch(const Draw& d, Random& rng, RunDraws& out) {
    const std::int64_t t = epoch_ms(d, rng);  // milliseconds since 1970 UTC
    const auto from_ms = static_cast<std::int64_t>(std::llround(d.epoch_from * 1000.0));
    constexpr std::int64_t day_ms = 86'400'000;
    const std::int64_t days = t >= 0 ? t / day_ms : -((-t + day_ms - 1) / day_ms);
    const std::int64_t ms = t - days * day_ms;
    using namespace std::chrono;
    const year_month_day ymd{sys_days{std::chrono::days{days}}};
    const int year = static_cast<int>(ymd.year()), month = static_cast<int>(static_cast<unsigned>(ymd.month()));
    const int day = static_cast<int>(static_cast<unsigned>(ymd.day()));
    const int hour = static_cast<int>(ms / 3'600'000), minute = static_cast<int>(ms / 60'000 % 60);
    const double second = static_cast<double>(ms % 60'000) / 1000.0;
    const std::string values[] = {std::to_string(year), std::to_string(month),  std::to_string(day),
                                  std::to_string(hour), std::to_string(minute), format_real(second)};
    // The truth's date, the on-board clock with it, and the element sets moved to it (not propagated there).
    std::vector<std::string> instants = {d.target};
    instants.insert(instants.end(), d.clocks.begin(), d.clocks.end());
    for (const auto& prefix : instants)
        for (int i = 0; i < 6; ++i) out.settings.push_back(prefix + epoch_fields[i] + "=" + values[i]);
    if (!d.element_sets.empty()) {
        // The Julian date from whole days and milliseconds apart (exact in a double to 1e-9 day).
        const double jd = unix_epoch_jd + static_cast<double>(days) + static_cast<double>(ms) / day_ms;
        const orbit::Tle moved = orbit::reepoched(base_set(d), jd);
        for (const auto& target : d.element_sets) set_elements(target, moved, out);
    }
    char iso[64];
    std::snprintf(iso, sizeof iso, "%04d-%02d-%02dT%02d:%02d:%06.3fZ", year, month, day, hour, minute, second);
    out.cells.push_back(iso);
    out.cells.push_back(format_real(static_cast<double>(t - from_ms) / static_cast<double>(day_ms)));
}

const char* class_name(OrbitClass c) {
    switch (c) {
        case OrbitClass::sun_synchronous:
            return "sun_synchronous";
        case OrbitClass::iss_like:
            return "iss_like";
        case OrbitClass::polar:
            return "polar";
        case OrbitClass::low_inclination:
            return "low_inclination";
    }
    return "";
}

// An orbit class's set at the scenario's date (jd): the class, then its altitude, node (or local time of the
// node) and argument of latitude, each uniform; B* the scenario's set's.
void add_orbit(const Draw& d, Random& rng, double jd, RunDraws& out) {
    const auto pick = std::min(static_cast<std::size_t>(unit(rng) * static_cast<double>(d.orbit_classes.size())),
                               d.orbit_classes.size() - 1);
    const OrbitClass c = d.orbit_classes[pick];
    const double altitude_km = (d.altitude_min + (d.altitude_max - d.altitude_min) * unit(rng)) / 1e3;
    const double u_node = unit(rng), u_latitude = unit(rng);
    const double latitude = 360.0 * u_latitude, bstar = base_set(d).bstar_per_earth_radius;
    orbit::Tle tle;
    if (c == OrbitClass::sun_synchronous) {
        const double ltan = d.ltan_min + (d.ltan_max - d.ltan_min) * u_node;
        tle = orbit::sun_synchronous_set(jd, altitude_km, std::min(ltan, std::nextafter(24.0, 0.0)), latitude, bstar);
    } else {
        const double inclination = c == OrbitClass::iss_like ? orbit::kIssLikeInclinationDeg
                                   : c == OrbitClass::polar  ? orbit::kPolarInclinationDeg
                                                             : orbit::kLowInclinationDeg;
        const double altitude = c == OrbitClass::iss_like ? orbit::kIssLikeAltitudeKm : altitude_km;
        tle = orbit::circular_orbit_set(jd, altitude, inclination, 360.0 * u_node, latitude, bstar);
    }
    set_elements(d.target, tle, out);
    for (const auto& copy : d.copies) set_elements(copy, tle, out);
    orbit::Sgp4<double> sgp4;
    (void)sgp4.initialize(tle.mean_elements<double>());
    out.cells.push_back(class_name(c));
    out.cells.push_back(format_real(sgp4.semi_major_axis_km() - orbit::Wgs72::earth_radius_km));
    out.cells.push_back(format_real(tle.inclination_deg));
    out.cells.push_back(format_real(orbit::ltan_hours(tle.raan_deg, jd)));
}

}  // namespace

std::uint64_t stream_seed(std::uint64_t base_seed, std::uint64_t unit_index, const std::string& target) {
    std::uint64_t h = 0xCBF29CE484222325ull;  // FNV-1a of the name
    for (unsigned char c : target) h = (h ^ c) * 0x100000001B3ull;
    return splitmix(splitmix(splitmix(base_seed) ^ unit_index) ^ h);
}

namespace {

std::vector<DrawColumn> columns_of(const Draw& d) {
    std::vector<DrawColumn> out;
    switch (d.kind) {
        case DrawKind::quaternion:
            for (int i = 1; i <= 4; ++i) out.push_back({element(d.target, i), false});
            break;
        case DrawKind::tumble:
            for (int i = 1; i <= 3; ++i) out.push_back({element(d.target, i), false});
            out.push_back({d.target + ".rate", d.figure});
            break;
        case DrawKind::epoch:
            out.push_back({d.target, false});
            out.push_back({d.target + ".days", d.figure});
            break;
        case DrawKind::orbit:
            out.push_back({d.target + ".class", false});
            for (const char* c : {".altitude", ".inclination", ".ltan"}) out.push_back({d.target + c, d.figure});
            break;
        default:
            out.push_back({d.target, d.figure});
    }
    return out;
}

// The columns the cases' draws fill, each once in the order first met (cases may draw the same target).
std::vector<DrawColumn> case_columns(const CampaignSpec& spec) {
    std::vector<DrawColumn> out;
    for (const auto& c : spec.cases)
        for (const auto& d : c.draws)
            for (const auto& column : columns_of(d))
                if (std::none_of(out.begin(), out.end(), [&](const DrawColumn& x) { return x.name == column.name; }))
                    out.push_back(column);
    return out;
}

// One random draw (not a grid) appended to `out`: its settings and its cells.
void seed_draw(Random& rng, const Draw& d, std::uint64_t seed, std::uint64_t unit_index) {
    rng.seed(stream_seed(seed, unit_index, d.stream.empty() ? d.target : d.stream));
}

// The scenario's date of a run (JD UTC): its epoch draw's instant (drawn again from the same stream), else
// the first orbit draw's base set's epoch.
double scenario_jd(const std::vector<const Draw*>& draws, std::uint64_t seed, std::uint64_t unit_index) {
    for (const Draw* d : draws)
        if (d->kind == DrawKind::epoch) {
            Random rng;
            seed_draw(rng, *d, seed, unit_index);
            return unix_epoch_jd + static_cast<double>(epoch_ms(*d, rng)) / 86'400'000.0;
        }
    for (const Draw* d : draws)
        if (d->kind == DrawKind::orbit) return base_set(*d).epoch_jd_utc;
    return 0.0;
}

void draw_one(const Draw& d, std::uint64_t seed, std::uint64_t unit_index, RunDraws& out, double jd = 0.0) {
    Random rng;
    seed_draw(rng, d, seed, unit_index);
    auto set = [&](const std::string& variable, const std::string& text) {
        out.settings.push_back(variable + "=" + text);
        out.cells.push_back(text);
    };
    switch (d.kind) {
        case DrawKind::uniform:
            set(d.target, format_real(d.min + (d.max - d.min) * unit(rng)));
            break;
        case DrawKind::normal: {
            // Rejection keeps the exact truncated distribution; the spec guarantees at least
            // min_truncated_normal_mass acceptance, so this bound is never the limit in practice.
            for (long tries = 0;; ++tries) {
                if (tries == 100'000'000)
                    throw CampaignError(d.target + ": truncated normal draw did not land in its interval");
                const double x = d.mean + d.sd * rng.normal();
                if (x >= d.min && x <= d.max) {
                    set(d.target, format_real(x));
                    break;
                }
            }
            break;
        }
        case DrawKind::integer: {
            const double span = d.max - d.min + 1.0;
            const double k = std::min(d.min + std::floor(unit(rng) * span), d.max);
            set(d.target, std::to_string(static_cast<long long>(k)));
            break;
        }
        case DrawKind::choice: {
            std::size_t pick = 0;
            if (d.weights.empty()) {
                pick = std::min(static_cast<std::size_t>(unit(rng) * static_cast<double>(d.values.size())),
                                d.values.size() - 1);
            } else {
                double total = 0.0;
                for (double w : d.weights) total += w;
                const double u = unit(rng) * total;
                double cumulative = 0.0;
                pick = d.values.size() - 1;
                for (std::size_t i = 0; i < d.weights.size(); ++i) {
                    cumulative += d.weights[i];
                    if (u < cumulative && d.weights[i] > 0.0) {
                        pick = i;
                        break;
                    }
                }
            }
            set(d.target, d.values[pick].text);
            break;
        }
        case DrawKind::grid:
            throw CampaignError(d.target + ": a grid draw is walked by the run index, not drawn");
        case DrawKind::quaternion: {
            // Shoemake (1992), "Uniform random rotations", Graphics Gems III: uniform on SO(3).
            const double u1 = unit(rng), u2 = unit(rng), u3 = unit(rng);
            const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1), tau = 2.0 * std::numbers::pi;
            const double q[4] = {a * std::sin(tau * u2), a * std::cos(tau * u2), b * std::sin(tau * u3),
                                 b * std::cos(tau * u3)};
            for (int i = 0; i < 4; ++i) set(element(d.target, i + 1), format_real(q[i]));
            break;
        }
        case DrawKind::tumble: {
            // Direction uniform on the sphere (Archimedes: z uniform in [-1, 1]), rate uniform in its range.
            const double z = 2.0 * unit(rng) - 1.0, phi = 2.0 * std::numbers::pi * unit(rng);
            const double rate = d.min + (d.max - d.min) * unit(rng), r = std::sqrt(std::max(0.0, 1.0 - z * z));
            const double w[3] = {rate * r * std::cos(phi), rate * r * std::sin(phi), rate * z};
            for (int i = 0; i < 3; ++i) set(element(d.target, i + 1), format_real(w[i]));
            out.cells.push_back(format_real(rate));
            break;
        }
        case DrawKind::epoch:
            add_epoch(d, rng, out);
            break;
        case DrawKind::orbit:
            add_orbit(d, rng, jd, out);
            break;
    }
}

}  // namespace

std::vector<DrawColumn> draw_columns(const CampaignSpec& spec) {
    std::vector<DrawColumn> out;
    if (!spec.cases.empty()) out.push_back({"case", true});
    for (const auto& d : spec.draws) {
        const auto columns = columns_of(d);
        out.insert(out.end(), columns.begin(), columns.end());
    }
    const auto cases = case_columns(spec);
    out.insert(out.end(), cases.begin(), cases.end());
    return out;
}

std::vector<std::string> drawn_variables(const Draw& d) {
    std::vector<std::string> out;
    if (d.kind == DrawKind::quaternion || d.kind == DrawKind::tumble)
        for (int i = 1; i <= (d.kind == DrawKind::quaternion ? 4 : 3); ++i) out.push_back(element(d.target, i));
    else if (d.kind == DrawKind::epoch) {
        std::vector<std::string> instants = {d.target};
        instants.insert(instants.end(), d.clocks.begin(), d.clocks.end());
        for (const auto& prefix : instants)
            for (const char* f : epoch_fields) out.push_back(prefix + f);
        for (const auto& set : d.element_sets)
            for (int k = 1; k <= static_cast<int>(orbit::kTleElementCount); ++k) out.push_back(element(set, k));
    } else if (d.kind == DrawKind::orbit) {
        std::vector<std::string> sets = {d.target};
        sets.insert(sets.end(), d.copies.begin(), d.copies.end());
        for (const auto& set : sets)
            for (int k = 1; k <= static_cast<int>(orbit::kTleElementCount); ++k) out.push_back(element(set, k));
    } else {
        out.push_back(d.target);
    }
    return out;
}

long case_count(const CampaignSpec& spec) {
    return spec.cases.empty() ? 1 : static_cast<long>(spec.cases.size());
}

long grid_size(const CampaignSpec& spec) {
    long n = case_count(spec);
    for (const auto& d : spec.draws)
        if (d.kind == DrawKind::grid) {
            if (n > max_runs / static_cast<long>(d.values.size()))
                throw CampaignError("the grid draws and cases have more than " + std::to_string(max_runs) +
                                    " combinations");
            n *= static_cast<long>(d.values.size());
        }
    return n;
}

std::optional<std::size_t> case_of(const CampaignSpec& spec, long index) {
    if (spec.cases.empty()) return std::nullopt;
    return static_cast<std::size_t>(index % case_count(spec));
}

std::optional<long> paired_control(const CampaignSpec& spec, long index) {
    if (!spec.paired) return std::nullopt;
    for (std::size_t c = 0; c < spec.cases.size(); ++c)
        if (spec.cases[c].control) return index / case_count(spec) * case_count(spec) + static_cast<long>(c);
    return std::nullopt;
}

RunDraws draw_run(const CampaignSpec& spec, long index) {
    const long grid = grid_size(spec), cases = case_count(spec);
    const auto unit_index = static_cast<std::uint64_t>(spec.paired ? index / grid : index);
    long stride = 1;
    RunDraws out;
    const auto which = case_of(spec, index);
    std::vector<const Draw*> all;
    for (const auto& d : spec.draws) all.push_back(&d);
    if (which)
        for (const auto& d : spec.cases[*which].draws) all.push_back(&d);
    const bool has_orbit =
        std::any_of(all.begin(), all.end(), [](const Draw* d) { return d->kind == DrawKind::orbit; });
    const double jd = has_orbit ? scenario_jd(all, spec.seed, unit_index) : 0.0;
    if (which) {
        out.cells.push_back(spec.cases[*which].name);
        out.settings = spec.cases[*which].settings;  // before the draws, after the spec's [set]
    }
    for (const auto& d : spec.draws) {
        if (d.kind == DrawKind::grid) {
            // The cases vary fastest, then the grid draws in spec order.
            const auto n = static_cast<long>(d.values.size());
            const std::string& text = d.values[static_cast<std::size_t>((index % grid) / cases / stride % n)].text;
            out.settings.push_back(d.target + "=" + text);
            out.cells.push_back(text);
            stride *= n;
        } else {
            draw_one(d, spec.seed, unit_index, out, jd);
        }
    }
    if (which) {
        // The case's own draws, each in its column; the other cases' columns stay empty.
        RunDraws own;
        for (const auto& d : spec.cases[*which].draws) draw_one(d, spec.seed, unit_index, own, jd);
        std::vector<std::string> names;
        for (const auto& d : spec.cases[*which].draws)
            for (const auto& c : columns_of(d)) names.push_back(c.name);
        for (const auto& column : case_columns(spec)) {
            const auto at = std::find(names.begin(), names.end(), column.name);
            out.cells.push_back(at == names.end() ? "" : own.cells[static_cast<std::size_t>(at - names.begin())]);
        }
        out.settings.insert(out.settings.end(), own.settings.begin(), own.settings.end());
    }
    return out;
}

void read_scenario_base(CampaignSpec& spec,
                        const std::function<std::optional<std::string>(const std::string&)>& value_of) {
    auto read = [&](Draw& d, const std::string& set) {
        // The draw writes numbers; a component that gives its set as lines would ignore them.
        const auto dot = set.find('.');
        for (const char* line : {".tle_line1", ".tle_line2"})
            if (const auto text = value_of(set.substr(0, dot) + line); text && !text->empty())
                throw CampaignError("draw of " + d.target + ": " + set.substr(0, dot) + line +
                                    " gives the set as text, which the drawn numbers (" + set +
                                    ") would not replace: give the system's set as " + set + "[1..8]");
        d.base_elements.clear();
        for (int k = 1; k <= static_cast<int>(orbit::kTleElementCount); ++k) {
            const auto text = value_of(element(set, k));
            if (!text) throw CampaignError("draw of " + d.target + ": the system has no " + element(set, k));
            d.base_elements.push_back(cosim::parse_real(*text, element(set, k)));
        }
        try {
            orbit::TleElements e{};
            std::copy(d.base_elements.begin(), d.base_elements.end(), e.begin());
            (void)orbit::checked_tle_from_elements(e);
        } catch (const orbit::TleElementsError& e) {
            throw CampaignError("draw of " + d.target + ": the system's " + set + e.what());
        }
    };
    auto each = [&](std::vector<Draw>& draws) {
        for (auto& d : draws) {
            if (d.kind == DrawKind::epoch && !d.element_sets.empty()) read(d, d.element_sets.front());
            if (d.kind == DrawKind::orbit) read(d, d.target);
        }
    };
    each(spec.draws);
    for (auto& c : spec.cases) each(c.draws);
}

}  // namespace campaign
