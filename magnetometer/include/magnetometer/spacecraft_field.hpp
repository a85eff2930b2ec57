// The spacecraft's own magnetic field at the magnetometer: a residual dipole and the currents of the
// power system (each face's cell string, the shunt switches, the battery, the load), each current run
// around a rectangular loop of straight wires. Plain C++ (no FMI types).
//
// Physics (free space, SI; μ0/4π = 1e-7 T·m/A):
//   straight segment from a to b carrying I, at point p, with r1 = a − p, r2 = b − p (exact closed form of
//   the Biot–Savart integral ∫ μ0 I dl × (p − l) / (4π |p − l|³); e.g. Hanson & Hirshman, "Compact
//   expressions for the Biot–Savart fields of a filamentary segment", Phys. Plasmas 9, 4410 (2002)):
//     B = μ0 I / 4π · (r1 × r2) (|r1| + |r2|) / (|r1| |r2| (|r1| |r2| + r1 · r2))
//   point dipole m at q, at p, r = p − q:  B = μ0 / 4π · (3 r̂ (m · r̂) − m) / |r|³
// A loop is the sum of its four segments. The field is linear in the currents and the geometry is fixed,
// so SpacecraftField computes once, from the layout, the field at the sensor per ampere of each circuit.
#pragma once

#include <array>
#include <cstddef>

#include "magnetometer/hmc2003.hpp"

namespace magnetometer {

inline constexpr double mu0_over_4pi = 1e-7;  // T·m/A
// No wire and no dipole may come closer to the sensor than this: the formulas hold for thin wires and
// a point dipole, neither of which is a description of anything within a millimetre of the sensor.
inline constexpr double min_source_distance = 1e-3;  // m
inline constexpr std::size_t face_count = 6;         // +x, −x, +y, −y, +z, −z

// A rectangular current loop (any parallelogram is accepted): corners center ± side_a/2 ± side_b/2, the
// current running along side_a, then side_b, then back: a positive current's moment is I (side_a × side_b),
// so side_a × side_b is the loop's normal times its area. Metres, body axes. Zero sides: no loop.
struct CurrentLoop {
    Vec3 center{};
    Vec3 side_a{};
    Vec3 side_b{};
};

// Where the currents run, where the dipole sits and where the sensor is: metres and A·m², body axes.
struct SpacecraftLayout {
    Vec3 sensor_position{};
    Vec3 dipole_moment{};  // A·m²
    Vec3 dipole_position{};
    std::array<CurrentLoop, face_count> string_loop{};  // each face's cell string, its whole current
    CurrentLoop shunt_loop{};    // the shunt switches' path, the sum of the faces' shunt currents
    CurrentLoop battery_loop{};  // the battery's current path, positive charging
    CurrentLoop load_loop{};     // the bus to the load and back
};

// The currents of the plant (ssr_plant's outputs of the same names), amperes, averaged over the shunt
// regulator's PWM period (5 kHz, above the sensor's 1 kHz bandwidth).
struct PlantCurrents {
    std::array<double, face_count> string{};  // each face's cell current (i_string)
    std::array<double, face_count> shunt{};   // each face's current through its shunt switch (i_shunt)
    double battery = 0.0;                     // into the battery, positive charging (i_batt)
    double load = 0.0;                        // through the load (i_load)
};

// An assumed 3U layout (100 × 100 × 340 mm, long axis z, origin at the box's centre; the magnetometer's
// README has the sketch). Assumed, not from the papers. Residual dipole zero here (the bundled systems set
// 0.05 A·m²).
//  - each face's cell string: a back-wired string whose out and return legs leave a 5 mm wide loop down the
//    middle of the face (long faces 300 × 5 mm, end faces 80 × 5 mm), in the face's plane, normal outward;
//  - the shunt switches: a 40 × 10 mm power-trace loop on the power board, a plane at z = −80 mm;
//  - the battery: its current path, a 60 × 20 mm loop in an x–z plane at z = −120 mm, normal +y;
//  - the load: an untwisted bus pair 10 mm apart from the power board up the stack to z = +40 mm, at x = 30 mm;
//  - the magnetometer: at (10, 10, 110) mm, near the axis of the top unit, 60 mm below the +z face;
//  - the dipole (when set): at the box's centre.
inline constexpr SpacecraftLayout default_layout() {
    SpacecraftLayout l;
    l.sensor_position = {0.01, 0.01, 0.11};
    l.dipole_position = {0.0, 0.0, 0.0};
    l.string_loop = {{
        {{0.05, 0.0, 0.0}, {0.0, 0.0, 0.30}, {0.0, -0.005, 0.0}},   // +x: 300 mm along z, normal +x
        {{-0.05, 0.0, 0.0}, {0.0, 0.0, 0.30}, {0.0, 0.005, 0.0}},   // −x
        {{0.0, 0.05, 0.0}, {0.0, 0.0, 0.30}, {0.005, 0.0, 0.0}},    // +y
        {{0.0, -0.05, 0.0}, {0.0, 0.0, 0.30}, {-0.005, 0.0, 0.0}},  // −y
        {{0.0, 0.0, 0.17}, {0.08, 0.0, 0.0}, {0.0, 0.005, 0.0}},    // +z: 80 mm along x, normal +z
        {{0.0, 0.0, -0.17}, {0.08, 0.0, 0.0}, {0.0, -0.005, 0.0}},  // −z
    }};
    l.shunt_loop = {{0.0, 0.0, -0.08}, {0.04, 0.0, 0.0}, {0.0, 0.01, 0.0}};
    l.battery_loop = {{0.0, 0.0, -0.12}, {0.0, 0.0, 0.02}, {0.06, 0.0, 0.0}};
    l.load_loop = {{0.03, 0.0, -0.02}, {0.0, 0.0, 0.12}, {0.0, 0.01, 0.0}};
    return l;
}

// Field at p of current I flowing straight from a to b (the closed form above). p on the segment
// itself is the caller's to avoid (SpacecraftField refuses it); p on the line outside gives zero.
Vec3 segment_field(const Vec3& a, const Vec3& b, double current, const Vec3& p);
// Field at p of the closed loop, current in the direction of its corners' order (see CurrentLoop).
Vec3 loop_field(const CurrentLoop& loop, double current, const Vec3& p);
std::array<Vec3, 4> loop_corners(const CurrentLoop& loop);
// Magnetic moment of the loop carrying `current`: I (side_a × side_b), A·m².
Vec3 loop_moment(const CurrentLoop& loop, double current);
// Field of a point dipole of moment m at separation r (from the dipole to the field point).
Vec3 dipole_field(const Vec3& moment, const Vec3& r);
// Distance from p to the closed segment [a, b].
double distance_to_segment(const Vec3& a, const Vec3& b, const Vec3& p);

class SpacecraftField {
public:
    // Throws std::invalid_argument for a non-finite number or a wire or dipole closer to the sensor than
    // min_source_distance (naming the circuit).
    explicit SpacecraftField(const SpacecraftLayout& layout);
    // Field at the sensor, body axes, tesla: the dipole's plus each circuit's current times its field per
    // ampere. Zero currents and a zero dipole give exactly zero.
    Vec3 at_sensor(const PlantCurrents& i) const;

private:
    std::array<Vec3, face_count> per_amp_string_{};  // T/A
    Vec3 per_amp_shunt_{};
    Vec3 per_amp_battery_{};
    Vec3 per_amp_load_{};
    Vec3 dipole_{};  // T
};

}  // namespace magnetometer
