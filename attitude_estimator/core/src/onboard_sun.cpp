#include "attitude_estimator/onboard_sun.hpp"

#include <cmath>

#include "attitude_estimator/onboard_computer.hpp"  // kAstronomicalUnit
#include "environment/almanac_formulas.hpp"

namespace attitude_estimator {

namespace f = environment::formulas;

template <class T>
SunReference<T> onboard_sun(const OnboardClock<T>& clock, T t) noexcept {
    const T days = days_since_j2000(clock, t);
    const f::AlmanacSun<T> s = f::sun_almanac_of_date(days);
    const std::array<T, 9> p = f::precession_matrix(days / T(36525));
    // J2000 = Pᵀ · of date.
    SunReference<T> out;
    for (int i = 0; i < 3; ++i)
        out.direction[i] = p[i] * s.direction[0] + p[3 + i] * s.direction[1] + p[6 + i] * s.direction[2];
    out.distance = s.distance_au * T(kAstronomicalUnit);
    return out;
}

template <class T>
Matrix3RowMajor<T> ecef_from_j2000(const OnboardClock<T>& clock, T t) noexcept {
    const std::array<T, 9> p = f::precession_matrix(days_since_j2000(clock, t) / T(36525));
    const T a = gmst_at(clock, t);
    const T c = std::cos(a), s = std::sin(a);
    // R3(a) = [c s 0; −s c 0; 0 0 1] times P.
    Matrix3RowMajor<T> m;
    for (int j = 0; j < 3; ++j) {
        m[j] = c * p[j] + s * p[3 + j];
        m[3 + j] = -s * p[j] + c * p[3 + j];
        m[6 + j] = p[6 + j];
    }
    return m;
}

template SunReference<float> onboard_sun(const OnboardClock<float>&, float) noexcept;
template SunReference<double> onboard_sun(const OnboardClock<double>&, double) noexcept;
template Matrix3RowMajor<float> ecef_from_j2000(const OnboardClock<float>&, float) noexcept;
template Matrix3RowMajor<double> ecef_from_j2000(const OnboardClock<double>&, double) noexcept;

}  // namespace attitude_estimator
