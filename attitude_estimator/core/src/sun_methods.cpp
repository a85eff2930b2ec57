// The dispatch entry and the eq. 5 difference method (docs/sun_methods.md).
#include "attitude_estimator/sun_methods.hpp"

#include <cmath>

#include "attitude_estimator/sun_vector.hpp"
#include "sun_methods_detail.hpp"

namespace attitude_estimator {

template <class T>
FaceReadings<T> face_readings(const std::array<T, 6>& i_face, const SunMethodConfig<T>& cfg) noexcept {
    FaceReadings<T> fr;
    for (int k = 0; k < 6; ++k) {
        if (!std::isfinite(i_face[k]) || !std::isfinite(cfg.i_face_norm[k]) || !(cfg.i_face_norm[k] > T(0))) return fr;
        fr.r[k] = i_face[k] / cfg.i_face_norm[k];
        if (fr.r[k] > cfg.dark_threshold) fr.lit |= detail::face_bit(k);
    }
    fr.ok = true;
    return fr;
}

template <class T>
SunMethodResult<T> sun_difference(const std::array<T, 6>& i_face, const SunMethodConfig<T>& cfg) noexcept {
    SunMethodResult<T> out;
    const FaceReadings<T> fr = face_readings(i_face, cfg);
    if (!fr.ok) return out;
    out.lit_faces = fr.lit;
    // 000 eq. 5 with the face currents: the differential current of axis k over the + face's norm.
    Vec3<T> i_sh{}, norm{};
    for (int ax = 0; ax < 3; ++ax) {
        i_sh[ax] = i_face[2 * ax] - i_face[2 * ax + 1];
        norm[ax] = cfg.i_face_norm[2 * ax];
    }
    const SunMeasurement<T> m = sun_vector_from_currents(i_sh, norm, cfg.min_sun_norm);
    out.unit = m.unit;
    out.valid = m.valid;
    out.norm = m.norm;
    out.residual = std::abs(m.norm - T(1));
    int s[3];
    for (int ax = 0; ax < 3; ++ax) {
        const bool lp = fr.lit & detail::face_bit(2 * ax), lm = fr.lit & detail::face_bit(2 * ax + 1);
        s[ax] = (lp || lm) ? (fr.r[2 * ax] >= fr.r[2 * ax + 1] ? 1 : -1) : 0;
    }
    out.cube_state = cube_state_of(s[0], s[1], s[2]);
    return out;
}

template <class T>
SunMethodResult<T> sun_from_faces(const std::array<T, 6>& i_face, const SunMethodConfig<T>& cfg,
                                  SunMethodState<T>& state) noexcept {
    switch (cfg.method) {
        case SunMethod::difference:
            return sun_difference(i_face, cfg);
        case SunMethod::inverse_response:
            return sun_inverse_response(i_face, cfg);
        case SunMethod::cones:
            return sun_cones(i_face, cfg, state);
        case SunMethod::three_faces:
            return sun_three_faces(i_face, cfg);
    }
    return SunMethodResult<T>{};
}

#define ATTITUDE_ESTIMATOR_SUN_METHODS_INSTANTIATE(T)                                                        \
    template FaceReadings<T> face_readings(const std::array<T, 6>&, const SunMethodConfig<T>&) noexcept;     \
    template SunMethodResult<T> sun_difference(const std::array<T, 6>&, const SunMethodConfig<T>&) noexcept; \
    template SunMethodResult<T> sun_from_faces(const std::array<T, 6>&, const SunMethodConfig<T>&,           \
                                               SunMethodState<T>&) noexcept;
ATTITUDE_ESTIMATOR_SUN_METHODS_INSTANTIATE(float)
ATTITUDE_ESTIMATOR_SUN_METHODS_INSTANTIATE(double)

}  // namespace attitude_estimator
