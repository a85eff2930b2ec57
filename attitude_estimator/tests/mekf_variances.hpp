// What the field-update tests of the filter read and compare: the attitude covariance's diagonal, and its closed
// form after one field update from an isotropic start σ₀² I with the field along z (x and y:
// 1 / (1/σ₀² + |B|²/σ²); z keeps σ₀²). Used by mekf_phase_sigma_test.cpp, mekf_turning_field_test.cpp and
// mekf_sun_turn_test.cpp (a unit sun for |B|).
#pragma once

#include <array>

#include "attitude_estimator/mekf.hpp"

namespace attitude_estimator::test {

template <class T>
std::array<double, 3> attitude_variances(const MekfState<T>& s) {
    return {static_cast<double>(s.p[0]), static_cast<double>(s.p[kMekfStates + 1]),
            static_cast<double>(s.p[2 * kMekfStates + 2])};
}

inline double variance_after_one_field(double start_sigma, double field, double sigma) {
    return 1.0 / (1.0 / (start_sigma * start_sigma) + field * field / (sigma * sigma));
}

}  // namespace attitude_estimator::test
