// Sun vector from the inverse angular response of each axis's lit face (docs/sun_methods.md).
#include <cmath>

#include "attitude_estimator/sun_methods.hpp"
#include "sun_methods_detail.hpp"

namespace attitude_estimator {

template <class T>
SunMethodResult<T> sun_inverse_response(const std::array<T, 6>& i_face, const SunMethodConfig<T>& cfg) noexcept {
    SunMethodResult<T> out;
    detail::AxisChoice<T> a;
    if (!detail::start_from_axes(i_face, cfg, out, a) || a.lit_axes == 0) return out;
    // s_k = ±cos β_k on each lit axis (sign of the lit face), 0 on an unlit axis (only |s_k| ≤ dark is known).
    Vec3<T> c{};
    for (int ax = 0; ax < 3; ++ax)
        if (a.face[ax] >= 0) c[ax] = T(detail::face_sign(a.face[ax])) * a.c[ax];
    const T n2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
    out.norm = std::sqrt(n2);
    if (!(out.norm > T(0))) return out;
    // Least squares on the lit components under |s| = 1 (unlit components held at 0): s = c/|c|; the
    // distance from c to that unit vector is ||c| − 1|.
    out.unit = {c[0] / out.norm, c[1] / out.norm, c[2] / out.norm};
    out.residual = std::abs(out.norm - T(1));
    const T dark = panel_response::dark_cos(cfg.response, cfg.dark_threshold);
    out.valid = a.lit_axes >= cfg.min_lit_axes && detail::reaches_min_norm(n2, 3 - a.lit_axes, dark, cfg.min_sun_norm);
    return out;
}

template SunMethodResult<float> sun_inverse_response(const std::array<float, 6>&,
                                                     const SunMethodConfig<float>&) noexcept;
template SunMethodResult<double> sun_inverse_response(const std::array<double, 6>&,
                                                      const SunMethodConfig<double>&) noexcept;

}  // namespace attitude_estimator
