// Faults of the power system, injected as physical changes of the circuit (issue 28): each fault acts on
// one face (+x, −x, +y, −y, +z, −z = 1 … 6; 0 = no fault) from its onset time, and most of them clear at
// an end time. Onsets and ends are time events (next_fault_event): the discrete state says which faults
// are in effect, so an integrator never steps across the discontinuity.
//
//   string open     the face's string is interrupted: no current flows in it, to the bus or through its
//                   shunt switch (its Hall channel reads 0, the bus and the battery lose its share)
//   cell short      `shorted_cells` of the string's cells are shorted: the string has fewer cells in series,
//                   its I–V curve is the same panel's with the voltage scaled (with_cells_shorted)
//   degradation     the face's photocurrent (and so its Isc) falls by `degradation_rate` per year from the
//                   onset (face 7: all six faces), to zero at most
//   shadow          `shadow_fraction` of the face's area is in the shadow of an appendage: the direct sun's
//                   photocurrent falls by that fraction (albedo, from the Earth's side, is not shadowed)
//   shunt switch    the face's shunt MOSFET is stuck on (the panel always shorted: nothing to the bus, the
//                   Hall channel always sees the short-circuit current) or off (the panel always on the bus:
//                   the regulator cannot shunt it, its Hall channel sees nothing)
//   appendage       a body-fixed plate shadows the face, from its geometry (appendage_shadow.hpp): the direct
//                   sun's photocurrent falls by the shadowed fraction, which moves with the sun (with a shadow
//                   fault on the same face, the larger fraction counts)
//   Hall sensor     the face's Hall channel (the measured current i_face_sh, not the physical current) reads
//                   `hall_offset` amperes too much, or stays stuck at the value it read at the onset
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "ssr_plant/fault_parameters.hpp"
#include "ssr_plant/pv_panel.hpp"

namespace ssr_plant {

// The kinds, in the order of FaultState::phase.
enum FaultKind : std::size_t {
    fault_string_open = 0,
    fault_cell_short,
    fault_degradation,
    fault_shadow,
    fault_shunt_switch,
    fault_hall,
    fault_appendage,
    fault_kind_count
};

// Phase of each kind: pending (before its onset, or no fault), active, cleared (after its end).
inline constexpr std::int32_t fault_pending = 0;
inline constexpr std::int32_t fault_active = 1;
inline constexpr std::int32_t fault_cleared = 2;

// The faults' part of the discrete state. Trivially copyable.
struct FaultState {
    std::array<std::int32_t, fault_kind_count> phase = {};
    double hall_stuck_value = 0.0;  // A, what the stuck Hall channel reads (captured at the onset)
    friend bool operator==(const FaultState&, const FaultState&) = default;
};

// Throws ParameterError naming the parameter for faces out of range, an end not after its onset, a
// shorted cell count that leaves no cell, a rate or fraction outside 0 … 1, non-finite values.
void check_faults(const FaultParameters& f, std::int32_t cells_in_series);

const FaultWindow& window(const FaultParameters& f, FaultKind kind);

// Moves every phase on to where it is at time t (onsets and ends reached within the runtime's time
// tolerance, 1e-12 relative). Returns the kinds that became active at t (a bit per kind).
std::uint32_t advance_faults(const FaultParameters& f, FaultState& s, double t);

// The next onset or end after the phases of s: no more = +infinity.
double next_fault_event(const FaultParameters& f, const FaultState& s);

// True when the fault of this kind is in effect on face k (0 … 5).
bool fault_on_face(const FaultParameters& f, const FaultState& s, FaultKind kind, std::size_t k);

// The same panel with `shorted` of its `cells_in_series` cells shorted: a string of N' = N − shorted cells
// of the same cell. Per cell nothing changes (photocurrent, saturation current, ideality); the string's
// diode voltage a = n N' V_T and its series and shunt resistances (sums over the cells) scale by N'/N. So the
// curve is the healthy one with its voltage scaled: I'(V N'/N) = I(V), and Voc' = Voc N'/N.
DiodeModel with_cells_shorted(const DiodeModel& m, std::int32_t cells_in_series, std::int32_t shorted);

// The fraction of the photocurrent left at time t after a loss of `rate` per year from `onset`:
// max(0, 1 − rate (t − onset) / year), 1 before the onset.
double degradation_factor(double rate, double onset, double t);

}  // namespace ssr_plant
