// Helpers shared by the sun-method sources (not installed).
#pragma once

#include <cmath>
#include <cstdint>

#include "attitude_estimator/sun_methods.hpp"

namespace attitude_estimator::detail {

constexpr int face_axis(int k) noexcept {
    return k / 2;
}
constexpr int face_sign(int k) noexcept {
    return (k % 2 == 0) ? 1 : -1;
}
constexpr std::uint8_t face_bit(int k) noexcept {
    return static_cast<std::uint8_t>(1u << k);
}

// Per axis, the lit face to use: the brighter of the opposite pair (the dimmer one cannot be sunlit at the
// same time: albedo), or −1 when neither is lit.
template <class T>
struct AxisChoice {
    std::array<int, 3> face{-1, -1, -1};
    std::array<T, 3> c{};  // cos β of the chosen face (≥ 0), 0 when none
    int lit_axes = 0;
    std::uint8_t rejected = 0;
};

template <class T>
AxisChoice<T> choose_axes(const FaceReadings<T>& fr, const SunMethodConfig<T>& cfg) noexcept {
    AxisChoice<T> a;
    for (int ax = 0; ax < 3; ++ax) {
        const int p = 2 * ax, m = 2 * ax + 1;
        const bool lp = fr.lit & face_bit(p), lm = fr.lit & face_bit(m);
        int f = -1;
        if (lp && lm) {
            f = fr.r[p] >= fr.r[m] ? p : m;
            a.rejected |= face_bit(f == p ? m : p);
        } else if (lp) {
            f = p;
        } else if (lm) {
            f = m;
        }
        a.face[ax] = f;
        if (f >= 0) {
            a.c[ax] = panel_response::cos_from_response(cfg.response, fr.r[f]);
            ++a.lit_axes;
        }
    }
    return a;
}

template <class T>
int cube_of_choice(const AxisChoice<T>& a) noexcept {
    int s[3];
    for (int ax = 0; ax < 3; ++ax) s[ax] = a.face[ax] < 0 ? 0 : face_sign(a.face[ax]);
    return cube_state_of(s[0], s[1], s[2]);
}

// The start every per-axis method shares: the readings, the lit faces, the per-axis choice, the faces it
// rejects and the cube state, written into `out`. False (out left as is) when the readings are unusable.
template <class T>
bool start_from_axes(const std::array<T, 6>& i_face, const SunMethodConfig<T>& cfg, SunMethodResult<T>& out,
                     AxisChoice<T>& a) noexcept {
    const FaceReadings<T> fr = face_readings(i_face, cfg);
    if (!fr.ok) return false;
    out.lit_faces = fr.lit;
    a = choose_axes(fr, cfg);
    out.rejected_faces = a.rejected;
    out.cube_state = cube_of_choice(a);
    return true;
}

// The largest |s| the lit-face cosines c and the unlit axes (each |s_k| ≤ dark) can make; albedo alone
// (eclipse) stays well below min_sun_norm.
template <class T>
bool reaches_min_norm(T c_norm2, int unlit_axes, T dark, T min_norm) noexcept {
    return c_norm2 + T(unlit_axes) * dark * dark >= min_norm * min_norm;
}

}  // namespace attitude_estimator::detail
