// Angles from three lit faces, seed 004 eq. 2–3 as printed, and the consistent form beside them
// (docs/sun_methods.md explains where the printed equations fail).
#include <cmath>

#include "attitude_estimator/sun_methods.hpp"
#include "sun_methods_detail.hpp"

namespace attitude_estimator {

namespace {

// 004 eq. 2–3 and the consistent form from the per-axis choice of lit faces.
template <class T>
ThreeFacesResult<T> three_faces_of(const detail::AxisChoice<T>& a, const SunMethodConfig<T>& cfg) noexcept {
    ThreeFacesResult<T> out;
    Vec3<T> s{};
    for (int ax = 0; ax < 3; ++ax) {
        out.face[ax] = a.face[ax];
        out.c[ax] = a.c[ax];  // cos α_k from eq. 1 inverted (or the Kelly table)
        if (a.face[ax] >= 0) s[ax] = T(detail::face_sign(a.face[ax])) * a.c[ax];
    }
    out.three_lit = a.lit_axes == 3;
    const T c1 = out.c[0], c2 = out.c[1], c3 = out.c[2];
    // 004 eq. 2 as printed.
    const T radicand[3] = {T(2) - c1 - c2 - c3, T(1) - c1 - c2 + c3, T(1) - c1 + c2 - c3};
    for (int k = 0; k < 3; ++k) {
        out.printed_defined[k] = out.three_lit && radicand[k] >= T(0) && radicand[k] <= T(1);
        out.printed_epsilon[k] = out.printed_defined[k] ? std::asin(std::sqrt(radicand[k])) : T(0);
    }
    // 004 eq. 3 as printed.
    out.printed_check = T(3) * c1 + c2 - c3 - T(2);
    out.printed_admissible = out.three_lit && std::abs(out.printed_check) <= cfg.printed_tolerance;
    // Consistent form: three direction cosines of one unit vector obey c1² + c2² + c3² = 1.
    const T n2 = c1 * c1 + c2 * c2 + c3 * c3;
    out.consistent_check = n2 - T(1);
    out.consistent_admissible = out.three_lit && std::abs(out.consistent_check) <= cfg.normalization_tolerance;
    if (n2 > T(0)) {
        const T n = std::sqrt(n2);
        out.unit = {s[0] / n, s[1] / n, s[2] / n};
        const T z = out.unit[2] > T(1) ? T(1) : (out.unit[2] < T(-1) ? T(-1) : out.unit[2]);
        out.theta = std::acos(z);  // s = (sin φ sin θ, cos φ sin θ, cos θ)   (000 eq. 5)
        out.phi = std::atan2(out.unit[0], out.unit[1]);
    }
    return out;
}

}  // namespace

template <class T>
ThreeFacesResult<T> three_faces(const std::array<T, 6>& i_face, const SunMethodConfig<T>& cfg) noexcept {
    const FaceReadings<T> fr = face_readings(i_face, cfg);
    if (!fr.ok) return {};
    return three_faces_of(detail::choose_axes(fr, cfg), cfg);
}

template <class T>
SunMethodResult<T> sun_three_faces(const std::array<T, 6>& i_face, const SunMethodConfig<T>& cfg) noexcept {
    SunMethodResult<T> out;
    detail::AxisChoice<T> a;
    if (!detail::start_from_axes(i_face, cfg, out, a)) return out;
    const ThreeFacesResult<T> t = three_faces_of(a, cfg);  // the readings and the choice taken once
    out.unit = t.unit;
    out.norm = std::sqrt(t.consistent_check + T(1));
    out.residual = std::abs(t.consistent_check);
    out.valid = t.three_lit && t.consistent_admissible && out.norm >= cfg.min_sun_norm;
    return out;
}

template ThreeFacesResult<float> three_faces(const std::array<float, 6>&, const SunMethodConfig<float>&) noexcept;
template ThreeFacesResult<double> three_faces(const std::array<double, 6>&, const SunMethodConfig<double>&) noexcept;
template SunMethodResult<float> sun_three_faces(const std::array<float, 6>&, const SunMethodConfig<float>&) noexcept;
template SunMethodResult<double> sun_three_faces(const std::array<double, 6>&, const SunMethodConfig<double>&) noexcept;

}  // namespace attitude_estimator
