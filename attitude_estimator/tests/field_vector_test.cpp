// Field vector from the HMC2003 voltages (000 §5): B = (v − v_ref)/sensitivity; expected values by hand.
#include "attitude_estimator/field_vector.hpp"

#include "test_support.hpp"

namespace attitude_estimator::test {
namespace {

template <class T>
class EstimatorCoreFieldVector : public ::testing::Test {};
TYPED_TEST_SUITE(EstimatorCoreFieldVector, Scalars, ScalarName);

template <class T>
FieldMeasurement<T> measure(Vec3<T> v, T margin = kDefaultRailMargin<T>, T min_field = kDefaultMinField<T>) {
    return field_vector_from_voltages(v, T(2.5), kHmc2003Sensitivity<T>, Vec3<T>{0, 0, 0}, Vec3<T>{5, 5, 5}, margin,
                                      min_field);
}

TYPED_TEST(EstimatorCoreFieldVector, VoltsToTeslaAndDirection) {
    using T = TypeParam;
    // (2.9, 2.5, 2.1) V − 2.5 V = (0.4, 0, −0.4) V at 1e4 V/T → (40, 0, −40) µT, unit (0.70711, 0, −0.70711).
    const auto m = measure<T>({T(2.9), T(2.5), T(2.1)});
    ASSERT_TRUE(m.valid);
    EXPECT_FALSE(m.at_rail);
    EXPECT_NEAR(m.field[0], 4e-5, tol<T>(1e-11, 1e-17));
    EXPECT_NEAR(m.field[1], 0.0, tol<T>(1e-11, 1e-17));
    EXPECT_NEAR(m.field[2], -4e-5, tol<T>(1e-11, 1e-17));
    EXPECT_NEAR(m.unit[0], std::sqrt(0.5), tol<T>(1e-5, 1e-12));
    EXPECT_NEAR(m.unit[2], -std::sqrt(0.5), tol<T>(1e-5, 1e-12));
}

TYPED_TEST(EstimatorCoreFieldVector, RailMargin) {
    using T = TypeParam;
    // Rails 0 V and 5 V, margin 0.05 V: 4.96 and 0.04 are saturated, 4.94 and 0.06 are not.
    auto m = measure<T>({T(4.96), T(2.5), T(2.5)});
    EXPECT_TRUE(m.at_rail);
    EXPECT_FALSE(m.valid);
    m = measure<T>({T(2.5), T(0.04), T(2.5)});
    EXPECT_TRUE(m.at_rail);
    EXPECT_FALSE(m.valid);
    EXPECT_TRUE((measure<T>({T(4.94), T(2.5), T(2.5)}).valid));
    EXPECT_TRUE((measure<T>({T(2.5), T(2.5), T(0.06)}).valid));
    // A wider margin moves the limit: 4.94 V is saturated with 0.1 V.
    EXPECT_FALSE((measure<T>({T(4.94), T(2.5), T(2.5)}, T(0.1)).valid));
}

TYPED_TEST(EstimatorCoreFieldVector, TooWeakOrBadField) {
    using T = TypeParam;
    // 0.005 V → 0.5 µT < 1 µT: invalid; 0.02 V → 2 µT: valid.
    EXPECT_FALSE((measure<T>({T(2.505), T(2.5), T(2.5)}).valid));
    EXPECT_TRUE((measure<T>({T(2.52), T(2.5), T(2.5)}).valid));
    EXPECT_FALSE((measure<T>({std::numeric_limits<T>::quiet_NaN(), T(2.5), T(2.9)}).valid));
    EXPECT_FALSE(
        (field_vector_from_voltages<T>({T(2.9), T(2.5), T(2.5)}, T(2.5), T(0), Vec3<T>{0, 0, 0}, Vec3<T>{5, 5, 5})
             .valid));
}

}  // namespace
}  // namespace attitude_estimator::test
