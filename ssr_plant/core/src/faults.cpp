#include "ssr_plant/faults.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "time_rule/time_rule.hpp"

namespace ssr_plant {
namespace {

constexpr std::array<const char*, fault_kind_count> parameter_prefix = {
    "fault_string_open", "fault_cell_short", "fault_degradation", "fault_shadow",
    "fault_switch",      "fault_hall",       "fault_appendage"};

void require(bool ok, const std::string& what) {
    if (!ok) throw ParameterError("ssr_plant parameters: " + what);
}

// A time event is due by the rule the runtime and the master use (time_rule/time_rule.hpp).
using time_rule::reached;

}  // namespace

const FaultWindow& window(const FaultParameters& f, FaultKind kind) {
    switch (kind) {
        case fault_string_open:
            return f.string_open;
        case fault_cell_short:
            return f.cell_short;
        case fault_degradation:
            return f.degradation;
        case fault_shadow:
            return f.shadow;
        case fault_shunt_switch:
            return f.shunt_switch;
        case fault_hall:
            return f.hall;
        case fault_appendage:
        default:
            return f.appendage;
    }
}

void check_faults(const FaultParameters& f, std::int32_t cells_in_series) {
    for (std::size_t k = 0; k < fault_kind_count; ++k) {
        const auto kind = static_cast<FaultKind>(k);
        const FaultWindow& w = window(f, kind);
        const std::string name = parameter_prefix[k];
        const std::int32_t max_face = kind == fault_degradation ? all_faces : 6;
        require(w.face >= 0 && w.face <= max_face,
                name + "_face must be 0 (none) or 1 ... 6 (+x, -x, +y, -y, +z, -z)" +
                    (kind == fault_degradation ? std::string(" or 7 (all faces)") : std::string()));
        require(std::isfinite(w.onset), name + "_onset must be finite");
        require(std::isfinite(w.end) && (w.end == 0.0 || w.end > w.onset),
                name + "_end must be 0 (never clears) or after " + name + "_onset");
    }
    require(f.degradation.end == 0.0, "a degradation never clears (its end must be 0)");
    require(f.shorted_cells >= 1 && f.shorted_cells < cells_in_series,
            "fault_cell_short_cells must be within 1 ... cells_in_series - 1");
    require(std::isfinite(f.degradation_rate) && f.degradation_rate >= 0.0 && f.degradation_rate <= 1.0,
            "fault_degradation_rate must be within 0 ... 1 per year");
    require(std::isfinite(f.shadow_fraction) && f.shadow_fraction >= 0.0 && f.shadow_fraction <= 1.0,
            "fault_shadow_fraction must be within 0 ... 1");
    require(f.switch_stuck == SwitchStuck::on || f.switch_stuck == SwitchStuck::off,
            "fault_switch_stuck must be 0 (on) or 1 (off)");
    require(f.hall_mode == HallFault::offset || f.hall_mode == HallFault::stuck,
            "fault_hall_mode must be 0 (offset) or 1 (stuck)");
    require(std::isfinite(f.hall_offset), "fault_hall_offset must be finite");
    for (std::size_t i = 0; i < 3; ++i) {
        require(std::isfinite(f.appendage_box[i]) && f.appendage_box[i] > 0.0, "fault_appendage_box must be > 0");
        require(std::isfinite(f.appendage_center[i]) && std::isfinite(f.appendage_side_a[i]) &&
                    std::isfinite(f.appendage_side_b[i]),
                "fault_appendage_center, _side_a and _side_b must be finite");
    }
}

std::uint32_t advance_faults(const FaultParameters& f, FaultState& s, double t) {
    std::uint32_t started = 0;
    for (std::size_t k = 0; k < fault_kind_count; ++k) {
        const FaultWindow& w = window(f, static_cast<FaultKind>(k));
        if (w.face == no_fault_face) continue;
        auto& phase = s.phase[k];
        if (phase == fault_pending && reached(t, w.onset)) {
            phase = fault_active;
            started |= 1u << k;
        }
        if (phase == fault_active && w.end != 0.0 && reached(t, w.end)) phase = fault_cleared;
    }
    return started;
}

double next_fault_event(const FaultParameters& f, const FaultState& s) {
    double next = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < fault_kind_count; ++k) {
        const FaultWindow& w = window(f, static_cast<FaultKind>(k));
        if (w.face == no_fault_face) continue;
        if (s.phase[k] == fault_pending) next = std::min(next, w.onset);
        if (s.phase[k] == fault_active && w.end != 0.0) next = std::min(next, w.end);
    }
    return next;
}

bool fault_on_face(const FaultParameters& f, const FaultState& s, FaultKind kind, std::size_t k) {
    if (s.phase[kind] != fault_active) return false;
    const std::int32_t face = window(f, kind).face;
    return face == static_cast<std::int32_t>(k) + 1 || (kind == fault_degradation && face == all_faces);
}

DiodeModel with_cells_shorted(const DiodeModel& m, std::int32_t cells_in_series, std::int32_t shorted) {
    if (!(shorted >= 1 && shorted < cells_in_series))
        throw ParameterError("shorted cells must be within 1 ... cells_in_series - 1");
    const double scale = static_cast<double>(cells_in_series - shorted) / cells_in_series;
    DiodeModel s = m;
    s.ideality_voltage = m.ideality_voltage * scale;
    s.series_resistance = m.series_resistance * scale;
    s.shunt_resistance = m.shunt_resistance * scale;
    return s;
}

double degradation_factor(double rate, double onset, double t) {
    if (!(t > onset)) return 1.0;
    return std::max(0.0, 1.0 - rate * (t - onset) / seconds_per_year);
}

}  // namespace ssr_plant
