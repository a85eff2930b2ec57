// Sun vector from the sample/hold currents (000 eq. 5); expected values by hand.
#include "attitude_estimator/sun_vector.hpp"

#include "test_support.hpp"

namespace attitude_estimator::test {
namespace {

template <class T>
class EstimatorCoreSunVector : public ::testing::Test {};
TYPED_TEST_SUITE(EstimatorCoreSunVector, Scalars, ScalarName);

TYPED_TEST(EstimatorCoreSunVector, DividesByEachAxisNormAndNormalizes) {
    using T = TypeParam;
    // (0.3/0.6, −0.4/0.8, 0/1) = (0.5, −0.5, 0): |s| = 0.70711, unit (0.70711, −0.70711, 0).
    const auto m = sun_vector_from_currents<T>({T(0.3), T(-0.4), T(0)}, {T(0.6), T(0.8), T(1)});
    ASSERT_TRUE(m.valid);
    EXPECT_NEAR(m.norm, std::sqrt(0.5), tol<T>(1e-6, 1e-14));
    EXPECT_NEAR(m.unit[0], std::sqrt(0.5), tol<T>(1e-6, 1e-14));
    EXPECT_NEAR(m.unit[1], -std::sqrt(0.5), tol<T>(1e-6, 1e-14));
    EXPECT_NEAR(m.unit[2], 0.0, tol<T>(1e-7, 1e-15));
}

TYPED_TEST(EstimatorCoreSunVector, RecoversTheSeedParametrization) {
    using T = TypeParam;
    // 000 eq. 5 left side: s = (sin φ sin θ, cos φ sin θ, cos θ); ideal cosine panels make
    // i_sh[k] = i_sc_norm[k] s_k, so the measurement must return s itself with |s| = 1.
    const Vec3<T> norm{T(0.8), T(0.9), T(1.1)};
    for (double phi = 0.05; phi < 6.28; phi += 0.37) {
        for (double theta = 0.02; theta < 3.14; theta += 0.29) {
            const double s[3] = {std::sin(phi) * std::sin(theta), std::cos(phi) * std::sin(theta), std::cos(theta)};
            Vec3<T> i_sh;
            for (int k = 0; k < 3; ++k) i_sh[k] = static_cast<T>(static_cast<double>(norm[k]) * s[k]);
            const auto m = sun_vector_from_currents(i_sh, norm);
            ASSERT_TRUE(m.valid);
            EXPECT_NEAR(m.norm, 1.0, tol<T>(1e-6, 1e-14));
            for (int k = 0; k < 3; ++k) EXPECT_NEAR(m.unit[k], s[k], tol<T>(1e-6, 1e-14));
        }
    }
}

TYPED_TEST(EstimatorCoreSunVector, InvalidBelowTheNormThreshold) {
    using T = TypeParam;
    const Vec3<T> ones{T(1), T(1), T(1)};
    // Default threshold 0.5: |s| = 0.49 rejected, 0.51 accepted, darkness rejected.
    EXPECT_FALSE((sun_vector_from_currents<T>({T(0.49), T(0), T(0)}, ones).valid));
    EXPECT_TRUE((sun_vector_from_currents<T>({T(0), T(0), T(-0.51)}, ones).valid));
    EXPECT_FALSE((sun_vector_from_currents<T>({T(0), T(0), T(0)}, ones).valid));
    // |(0.3, 0.3, 0.3)| = 0.5196: valid at the default, invalid with threshold 0.6.
    EXPECT_TRUE((sun_vector_from_currents<T>({T(0.3), T(0.3), T(0.3)}, ones).valid));
    EXPECT_FALSE((sun_vector_from_currents<T>({T(0.3), T(0.3), T(0.3)}, ones, T(0.6)).valid));
}

TYPED_TEST(EstimatorCoreSunVector, InvalidForBadNumbers) {
    using T = TypeParam;
    const T nan = std::numeric_limits<T>::quiet_NaN();
    EXPECT_FALSE((sun_vector_from_currents<T>({T(1), T(0), T(0)}, {T(0), T(1), T(1)}).valid));
    EXPECT_FALSE((sun_vector_from_currents<T>({T(1), T(0), T(0)}, {T(-1), T(1), T(1)}).valid));
    EXPECT_FALSE((sun_vector_from_currents<T>({nan, T(0), T(0)}, {T(1), T(1), T(1)}).valid));
    EXPECT_FALSE((sun_vector_from_currents<T>({T(1), T(0), T(0)}, {T(1), nan, T(1)}).valid));
}

}  // namespace
}  // namespace attitude_estimator::test
