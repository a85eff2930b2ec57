#include "attitude_estimator/onboard_sun.hpp"

#include <cmath>

#include "attitude_estimator/onboard_computer.hpp"  // kAstronomicalUnit
#include "ground/almanac_formulas.hpp"
#include "orbit/frames.hpp"  // IAU 1976 precession

namespace attitude_estimator {

namespace f = ground::formulas;

template <class T>
SunReference<T> onboard_sun(const OnboardClock<T>& clock, T t) noexcept {
    const T days = days_since_j2000(clock, t);
    const f::AlmanacSun<T> s = f::sun_almanac_of_date(days);
    const orbit::Matrix3<T> p = orbit::mod_from_j2000(days / T(36525));
    // J2000 = Pᵀ · of date.
    SunReference<T> out;
    for (int i = 0; i < 3; ++i)
        out.direction[i] = p(0, i) * s.direction[0] + p(1, i) * s.direction[1] + p(2, i) * s.direction[2];
    out.distance = s.distance_au * T(kAstronomicalUnit);
    return out;
}

template <class T>
Matrix3RowMajor<T> ecef_from_j2000(const OnboardClock<T>& clock, T t) noexcept {
    const orbit::Matrix3<T> p = orbit::mod_from_j2000(days_since_j2000(clock, t) / T(36525));
    const T a = gmst_at(clock, t);
    const T c = std::cos(a), s = std::sin(a);
    // R3(a) = [c s 0; −s c 0; 0 0 1] times P.
    Matrix3RowMajor<T> m;
    for (int j = 0; j < 3; ++j) {
        m[j] = c * p(0, j) + s * p(1, j);
        m[3 + j] = -s * p(0, j) + c * p(1, j);
        m[6 + j] = p(2, j);
    }
    return m;
}

template SunReference<float> onboard_sun(const OnboardClock<float>&, float) noexcept;
template SunReference<double> onboard_sun(const OnboardClock<double>&, double) noexcept;
template Matrix3RowMajor<float> ecef_from_j2000(const OnboardClock<float>&, float) noexcept;
template Matrix3RowMajor<double> ecef_from_j2000(const OnboardClock<double>&, double) noexcept;

}  // namespace attitude_estimator
