// The fault parameters of the power system (what faults.hpp injects; its comment says what each does).
#pragma once

#include <array>
#include <cstdint>

namespace ssr_plant {

inline constexpr std::int32_t no_fault_face = 0;
inline constexpr std::int32_t all_faces = 7;                  // degradation only: every face at the same rate
inline constexpr double seconds_per_year = 365.25 * 86400.0;  // Julian year

enum class SwitchStuck : std::int32_t { on = 0, off = 1 };
enum class HallFault : std::int32_t { offset = 0, stuck = 1 };

// When a fault is in effect: from onset (s, simulation time) until end (s); end = 0 (the default): it
// never clears. face = 0: no fault of this kind.
struct FaultWindow {
    std::int32_t face = no_fault_face;
    double onset = 0.0;
    double end = 0.0;
    friend bool operator==(const FaultWindow&, const FaultWindow&) = default;
};

struct FaultParameters {
    FaultWindow string_open;
    FaultWindow cell_short;
    std::int32_t shorted_cells = 1;  // of cells_in_series; 1 … cells_in_series − 1
    FaultWindow degradation;         // no end: the loss accumulates (face 7: all faces)
    double degradation_rate = 0.0;   // 1/year, fraction of the photocurrent lost per year, 0 … 1
    FaultWindow shadow;
    double shadow_fraction = 0.0;  // 1, shadowed fraction of the face's area, 0 … 1
    FaultWindow shunt_switch;
    SwitchStuck switch_stuck = SwitchStuck::on;
    FaultWindow hall;
    HallFault hall_mode = HallFault::offset;
    double hall_offset = 0.0;  // A, added to the face's measured current (mode offset)
    // A body-fixed appendage (deployed at the onset, say) shadowing the face: a plate center + s side_a +
    // t side_b (s, t in [−1/2, 1/2]; m, body axes from the box's centre) over a box of edges appendage_box
    // whose face the panel covers (appendage_shadow.hpp). Zero sides: no shadow.
    FaultWindow appendage;
    std::array<double, 3> appendage_center = {};
    std::array<double, 3> appendage_side_a = {};
    std::array<double, 3> appendage_side_b = {};
    std::array<double, 3> appendage_box = {0.1, 0.1, 0.34};  // m, an assumed 3U box (as the magnetometer's layout)
    friend bool operator==(const FaultParameters&, const FaultParameters&) = default;
};

}  // namespace ssr_plant
