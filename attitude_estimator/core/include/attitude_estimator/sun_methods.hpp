// Sun direction in body axes from the six per-face short-circuit currents (project issue 8, "sun sensing
// beyond eq. 5"). One dispatch entry, sun_from_faces, over four methods:
//   difference        000 eq. 5: s_k = (i_face[2k] − i_face[2k+1]) / i_face_norm[2k], normalized
//   inverse_response  per axis the lit face's cos β from the inverse angular response, unit-norm least squares
//   cones             002 eq. 13–20: orthogonal pairs of lit-face cones, mirror and albedo rejection, the
//                     27-state panel cube
//   three_faces       004 eq. 2–3 as printed, with the consistent form beside it (docs/sun_methods.md)
// Face order everywhere: +x, −x, +y, −y, +z, −z; bit k of a face mask is face k. Allocation-free, noexcept,
// float and double (the core is built with -fno-exceptions).
#pragma once

#include <array>
#include <cstdint>

#include "attitude_estimator/cone_albedo_shape.hpp"
#include "attitude_estimator/types.hpp"
#include "panel_response/kelly.hpp"

namespace attitude_estimator {

enum class SunMethod { difference, inverse_response, cones, three_faces };

constexpr const char* sun_method_name(SunMethod m) noexcept {
    switch (m) {
        case SunMethod::difference:
            return "difference";
        case SunMethod::inverse_response:
            return "inverse_response";
        case SunMethod::cones:
            return "cones";
        case SunMethod::three_faces:
            return "three_faces";
    }
    return "unknown";
}

// The 27-state panel cube of seed 002: per axis −1 (the − face directly lit), 0 (neither), +1 (the + face);
// encoded 9(x+1) + 3(y+1) + (z+1), so 0…26; kCubeDark = 13 is [0, 0, 0] (no panel lit: eclipse or unknown).
inline constexpr int kCubeDark = 13;
constexpr int cube_state_of(int x, int y, int z) noexcept {
    return 9 * (x + 1) + 3 * (y + 1) + (z + 1);
}
constexpr int cube_axis(int state, int axis) noexcept {
    return axis == 0 ? state / 9 - 1 : (axis == 1 ? (state / 3) % 3 - 1 : state % 3 - 1);
}
// The seed's graph: a transition is forbidden when some axis jumps between its two opposite faces (−1 ↔ +1)
// without passing through 0. Every transition out of kCubeDark is allowed (darkness = lights off, cube turned).
constexpr bool cube_transition_allowed(int from, int to) noexcept {
    if (from == kCubeDark) return true;
    for (int a = 0; a < 3; ++a)
        if (cube_axis(from, a) * cube_axis(to, a) < 0) return false;
    return true;
}

// A: one face's short-circuit current facing the sun squarely at 1367 W/m² (1 AU): ssr_plant's fitted
// 10 Wp panel (its README). The default of every panel normalization of the core and the block.
template <class T>
inline constexpr T kPanelCurrentAt1Au = T(0.84754);

template <class T>
struct SunMethodConfig {
    SunMethod method = SunMethod::difference;
    // A: the face's short-circuit current facing the sun squarely in full sun (ssr_plant at 1367 W/m²).
    std::array<T, 6> i_face_norm{kPanelCurrentAt1Au<T>, kPanelCurrentAt1Au<T>, kPanelCurrentAt1Au<T>,
                                 kPanelCurrentAt1Au<T>, kPanelCurrentAt1Au<T>, kPanelCurrentAt1Au<T>};
    // The panels' angular response used to invert currents into cos β: panel_response::cosine<T>() (000 eq. 1,
    // the default, as ssr_plant's default) or panel_response::kelly<T>() (the Kelly table of fig. 4).
    panel_response::Response<T> response = panel_response::cosine<T>();
    // A face is lit when i_face / i_face_norm > dark_threshold (relative).
    T dark_threshold = T(0.02);
    // difference: |s| of eq. 5 below this is invalid (eclipse, albedo only), as sun_vector_from_currents.
    // inverse_response / cones / three_faces: the largest norm the lit-face cosines plus the dark bound of the
    // unlit axes can reach must be at least this (albedo alone cannot look like the sun).
    T min_sun_norm = T(0.5);
    // inverse_response: valid only with at least this many axes lit (1…3).
    int min_lit_axes = 2;
    // cones: a face agrees with a candidate when |R(candidate·n) − measured r| ≤ this (relative response);
    // a face reading more than this above the candidate's prediction is albedo-polluted and rejected; a face
    // reading more than this below it (light cannot be removed) makes the candidate impossible.
    T cone_tolerance = T(0.03);
    // cones: candidates within this angle (rad) of the chosen one are averaged.
    T cone_cluster_angle = T(0.05);
    // cones: after this many consecutive samples refused by the cube graph the new state is accepted anyway
    // (recovery from a missed sample); 0 = refuse until darkness.
    int cube_refusals_before_reset = 4;
    // cones: a graph-forbidden transition is allowed anyway when the new direction is within this angle (rad)
    // of the last accepted one (a spin too fast for the sampling to catch the narrow single-face states);
    // 0 (default) = the seed's graph alone.
    T cube_max_step = T(0);
    // three_faces: the consistent admissibility |c1² + c2² + c3² − 1| ≤ this (the normalization of eq. 3).
    T normalization_tolerance = T(0.05);
    // three_faces: the printed admissibility |3c1 + c2 − c3 − 2| ≤ this (eq. 3 as printed; reported only).
    T printed_tolerance = T(0.05);
    // cones, albedo model (docs/sun_methods.md): each per-axis face hypothesis is fitted with the sun plus the
    // Earth as a uniformly bright sphere seen from the orbit (plate-to-sphere view factor): sin of the Earth's
    // angular radius R_E/(R_E + h) (0.91788 = 570 km); a fit is accepted when its RMS response misfit over the
    // six faces is at most cone_fit_tolerance (else the model-free candidates above decide); the fitted albedo
    // of a face squarely toward the Earth is bounded by cone_albedo_max (relative). cone_fit_tolerance = 0 turns
    // the model off.
    T cone_earth_sin_radius = T(0.91788);
    T cone_fit_tolerance = T(0.01);
    T cone_albedo_max = T(0.4);
    // cones, albedo model: the sphere's light as the faces' response weighs it. Invalid (default): the
    // cosine closed form; build it with cone_albedo_shape_table(response, cone_earth_sin_radius) whenever
    // the response is not the cosine (the Kelly panels see the grazing part of the disc weaker).
    ConeAlbedoShape<T> cone_albedo_shape{};
};

// Caller-owned memory between samples (cones' cube state). Default-constructed = after darkness.
template <class T>
struct SunMethodState {
    int cube_state = kCubeDark;
    int refusals = 0;       // consecutive refused samples (see cube_refusals_before_reset)
    Vec3<T> last_unit{};    // cones: the last accepted direction (continuity tie-break, seed 002)
    bool has_last = false;  // false after darkness
};

template <class T>
struct SunMethodResult {
    Vec3<T> unit{};  // unit sun direction, body axes (zero when no direction at all)
    bool valid = false;
    std::uint8_t lit_faces = 0;       // faces above the dark threshold
    std::uint8_t rejected_faces = 0;  // lit faces not used: albedo (the dimmer of an opposite pair, cones' outliers)
    int cube_state = kCubeDark;       // this sample's panel-cube state (cube_state_of)
    T residual = T(0);                // method's consistency measure (docs/sun_methods.md); 0 when exact
    T norm = T(0);                    // difference: |s| of eq. 5; others: |c| of the lit-face cosines used
    // cones with its albedo model: the albedo the fit puts on each face, relative to full sun (what the
    // orbit filter's panel-scale update takes out of a face's reading); zero otherwise.
    std::array<T, 6> face_albedo{};
};

// Per-face relative responses r_k = i_face[k] / i_face_norm[k] and the lit mask.
template <class T>
struct FaceReadings {
    std::array<T, 6> r{};
    std::uint8_t lit = 0;
    bool ok = false;  // every value finite, every norm > 0
};
template <class T>
FaceReadings<T> face_readings(const std::array<T, 6>& i_face, const SunMethodConfig<T>& cfg) noexcept;

// The four methods; sun_from_faces dispatches on cfg.method.
template <class T>
SunMethodResult<T> sun_difference(const std::array<T, 6>& i_face, const SunMethodConfig<T>& cfg) noexcept;
template <class T>
SunMethodResult<T> sun_inverse_response(const std::array<T, 6>& i_face, const SunMethodConfig<T>& cfg) noexcept;
template <class T>
SunMethodResult<T> sun_cones(const std::array<T, 6>& i_face, const SunMethodConfig<T>& cfg,
                             SunMethodState<T>& state) noexcept;

// Seed 004 eq. 2–3 from the three lit faces (one per axis, the brighter of each opposite pair).
template <class T>
struct ThreeFacesResult {
    Vec3<T> c{};                // cos α1..3 of the faces used (≥ 0), from the inverse response
    std::array<int, 3> face{};  // face index used on each axis (0…5)
    bool three_lit = false;     // one face lit on every axis
    // As printed (004 eq. 2): sin ε1 = √(2 − c1 − c2 − c3), sin ε2 = √(1 − c1 − c2 + c3),
    // sin ε3 = √(1 − c1 + c2 − c3); an angle is defined only when its radicand is in [0, 1].
    Vec3<T> printed_epsilon{};  // rad (0 where undefined)
    std::array<bool, 3> printed_defined{};
    T printed_check = T(0);  // 3c1 + c2 − c3 − 2 (004 eq. 3 as printed: admissible when ≈ 0)
    bool printed_admissible = false;
    // Consistent form: the direction cosines obey c1² + c2² + c3² = 1 (the normalization condition);
    // the sun's angles in the seed-000 parametrization s = (sin φ sin θ, cos φ sin θ, cos θ).
    T consistent_check = T(0);  // c1² + c2² + c3² − 1
    bool consistent_admissible = false;
    T theta = T(0);  // rad, acos s_z
    T phi = T(0);    // rad, atan2(s_x, s_y)
    Vec3<T> unit{};  // signed, normalized cosines: the sun vector
};
template <class T>
ThreeFacesResult<T> three_faces(const std::array<T, 6>& i_face, const SunMethodConfig<T>& cfg) noexcept;
template <class T>
SunMethodResult<T> sun_three_faces(const std::array<T, 6>& i_face, const SunMethodConfig<T>& cfg) noexcept;

// The single entry the FMU and the studies call.
template <class T>
SunMethodResult<T> sun_from_faces(const std::array<T, 6>& i_face, const SunMethodConfig<T>& cfg,
                                  SunMethodState<T>& state) noexcept;

#define ATTITUDE_ESTIMATOR_SUN_METHODS_EXTERN(T)                                                                     \
    extern template FaceReadings<T> face_readings(const std::array<T, 6>&, const SunMethodConfig<T>&) noexcept;      \
    extern template SunMethodResult<T> sun_difference(const std::array<T, 6>&, const SunMethodConfig<T>&) noexcept;  \
    extern template SunMethodResult<T> sun_inverse_response(const std::array<T, 6>&,                                 \
                                                            const SunMethodConfig<T>&) noexcept;                     \
    extern template SunMethodResult<T> sun_cones(const std::array<T, 6>&, const SunMethodConfig<T>&,                 \
                                                 SunMethodState<T>&) noexcept;                                       \
    extern template ThreeFacesResult<T> three_faces(const std::array<T, 6>&, const SunMethodConfig<T>&) noexcept;    \
    extern template SunMethodResult<T> sun_three_faces(const std::array<T, 6>&, const SunMethodConfig<T>&) noexcept; \
    extern template SunMethodResult<T> sun_from_faces(const std::array<T, 6>&, const SunMethodConfig<T>&,            \
                                                      SunMethodState<T>&) noexcept;
ATTITUDE_ESTIMATOR_SUN_METHODS_EXTERN(float)
ATTITUDE_ESTIMATOR_SUN_METHODS_EXTERN(double)
#undef ATTITUDE_ESTIMATOR_SUN_METHODS_EXTERN

}  // namespace attitude_estimator
