// The filter's field update with one magnetometer axis excluded (a stuck axis isolated on board, mekf.cpp
// keep_direction_only). Three axes tell a rotation from a change of the field's length; two cannot, so
// the update keeps only what a length change leaves alone. The scenes: the true attitude is the identity
// (body axes = reference axes), the spacecraft still, the sun exact, and the field read (1 + ε(t)) times
// its reference on the axes kept: a length error of up to 2 % that varies over a minute (the on-board
// model's magnitude error and the calibration's scale are of this kind; the offset state, left out in
// these still scenes, could not hold it).
// A length change is no rotation, so with every direction exact the truth is the only attitude that
// fits: the estimate must converge to it whatever ε does.
#include <cmath>

#include "attitude_estimator/mekf.hpp"
#include "fault_test_support.hpp"
#include "test_support.hpp"

namespace attitude_estimator::test {
namespace {

template <class T>
class EstimatorCoreMekfTwoAxes : public ::testing::Test {};
TYPED_TEST_SUITE(EstimatorCoreMekfTwoAxes, Scalars, ScalarName);

// The estimate's angle from the identity (rad): 2 |vec(q)|, q and −q alike.
template <class T>
double angle_from_identity(const Quaternion<T>& q) {
    const double v = std::sqrt(double(q.x) * q.x + double(q.y) * q.y + double(q.z) * q.z);
    return 2.0 * std::atan2(v, std::abs(double(q.w)));
}

// 200 s at 20 Hz from a 1° start error about (1, 1, 1)/√3: propagation, the sun, the field on `axes`
// with its length off by ε(t) = 0.02 sin(2π t / 60 s). Returns the final error (rad).
template <class T>
double final_error(const Vec3<T>& field_ref, std::uint8_t axes) {
    MekfConfig<T> c;
    // A still scene cannot tell the offset from a turn (both constant in body axes): no offset state here.
    c.estimate_offset = false;
    MekfState<T> s;
    const double half = 0.5 * 3.14159265358979 / 180.0, axis = 1.0 / std::sqrt(3.0);
    const Quaternion<T> start{T(std::sin(half) * axis), T(std::sin(half) * axis), T(std::sin(half) * axis),
                              T(std::cos(half))};
    mekf_start(s, start, Vec3<T>{}, T(0), c);
    const Vec3<T> sun{T(0.6), T(0.8), T(0)};
    for (int k = 1; k <= 4000; ++k) {
        const double t = k * kPeriod;
        mekf_propagate(s, T(kPeriod), c);
        mekf_update_sun(s, sun, sun, c);
        const T scale = T(1.0 + 0.02 * std::sin(2.0 * 3.14159265358979 * t / 60.0));
        const Vec3<T> read{scale * field_ref[0], scale * field_ref[1], scale * field_ref[2]};
        mekf_update_field(s, field_ref, read, T(1), c, axes);
    }
    return angle_from_identity(s.q);
}

constexpr double kConverged = 0.01 * 3.14159265358979 / 180.0;  // rad: 0.01°, against the 1° start

TYPED_TEST(EstimatorCoreMekfTwoAxes, ThreeAxesTellALengthChangeFromATurn) {
    using T = TypeParam;
    // The premise: on three axes the length's innovation lies outside the range of [B×].
    EXPECT_LT(final_error<T>(Vec3<T>{T(20e-6), T(-10e-6), T(30e-6)}, 0b111), kConverged);
}

TYPED_TEST(EstimatorCoreMekfTwoAxes, OnTwoAxesALengthErrorDoesNotTurnTheAttitude) {
    using T = TypeParam;
    // z excluded: a length error shows as ε (B_x, B_y) = ε (20, −10) µT on the axes kept. Taken as a turn
    // (both rows, the old update) it holds the estimate near 1° off; only the rows' component
    // perpendicular to (B_x, B_y) is kept, and that one a length change leaves at zero.
    EXPECT_LT(final_error<T>(Vec3<T>{T(20e-6), T(-10e-6), T(30e-6)}, 0b011), kConverged);
    // The same with x excluded (the pair y, z).
    EXPECT_LT(final_error<T>(Vec3<T>{T(20e-6), T(-10e-6), T(30e-6)}, 0b110), kConverged);
}

TYPED_TEST(EstimatorCoreMekfTwoAxes, AFieldAlongTheExcludedAxisKeepsBothRows) {
    using T = TypeParam;
    // B along z with z excluded: the pair reads zero whatever the length, and both rows still see a turn
    // about x or y (δB = B × δθ); the estimate converges and stays finite (no direction to divide by).
    EXPECT_LT(final_error<T>(Vec3<T>{T(0), T(0), T(40e-6)}, 0b011), kConverged);
}

}  // namespace
}  // namespace attitude_estimator::test
