#include "draws.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "campaign_error.hpp"
#include "engine/value_text.hpp"
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

void add_epoch(const Draw& d, Random& rng, RunDraws& out) {
    const auto from_ms = static_cast<std::int64_t>(std::llround(d.epoch_from * 1000.0));
    const auto span_ms = static_cast<std::int64_t>(std::llround((d.epoch_to - d.epoch_from) * 1000.0));
    const auto offset = static_cast<std::int64_t>(std::floor(unit(rng) * static_cast<double>(span_ms)));
    const std::int64_t t = from_ms + std::min(offset, span_ms - 1);  // milliseconds since 1970 UTC
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
    for (int i = 0; i < 6; ++i) out.settings.push_back(d.target + epoch_fields[i] + "=" + values[i]);
    char iso[64];
    std::snprintf(iso, sizeof iso, "%04d-%02d-%02dT%02d:%02d:%06.3fZ", year, month, day, hour, minute, second);
    out.cells.push_back(iso);
    out.cells.push_back(format_real(static_cast<double>(t - from_ms) / static_cast<double>(day_ms)));
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
void draw_one(const Draw& d, std::uint64_t seed, std::uint64_t unit_index, RunDraws& out) {
    Random rng;
    rng.seed(stream_seed(seed, unit_index, d.stream.empty() ? d.target : d.stream));
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
    else if (d.kind == DrawKind::epoch)
        for (const char* f : epoch_fields) out.push_back(d.target + f);
    else
        out.push_back(d.target);
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
            draw_one(d, spec.seed, unit_index, out);
        }
    }
    if (which) {
        // The case's own draws, each in its column; the other cases' columns stay empty.
        RunDraws own;
        for (const auto& d : spec.cases[*which].draws) draw_one(d, spec.seed, unit_index, own);
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

}  // namespace campaign
