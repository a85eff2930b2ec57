// The computer's side of the HMC2003 set/reset (AN-213): the field from a set or reset reading, the
// offset from set/reset pairs, the pulse schedule. Expected values by hand.
#include "attitude_estimator/set_reset.hpp"

#include <cmath>

#include "attitude_estimator/estimator.hpp"
#include "attitude_estimator/field_vector.hpp"
#include "test_support.hpp"

namespace attitude_estimator::test {
namespace {

template <class T>
class EstimatorCoreSetReset : public ::testing::Test {};
TYPED_TEST_SUITE(EstimatorCoreSetReset, Scalars, ScalarName);

TYPED_TEST(EstimatorCoreSetReset, ReadingAfterAResetGivesTheFieldWithItsSignRestored) {
    using T = TypeParam;
    // Field (30, −20, 10) µT at 1 V/gauss with a 20 mV offset, after a reset: v = 2.5 − S·B + 0.02 =
    // (2.22, 2.72, 2.42) V. B = −(v − 2.5 − 0.02)/S = (30, −20, 10) µT.
    const auto m = field_vector_from_set_reset<T>({T(2.22), T(2.72), T(2.42)}, T(2.5), kHmc2003Sensitivity<T>, T(-1),
                                                  {T(0.02), T(0.02), T(0.02)}, {T(0), T(0), T(0)}, {T(5), T(5), T(5)});
    ASSERT_TRUE(m.valid);
    EXPECT_NEAR(m.field[0], 30e-6, tol<T>(1e-10, 1e-16));
    EXPECT_NEAR(m.field[1], -20e-6, tol<T>(1e-10, 1e-16));
    EXPECT_NEAR(m.field[2], 10e-6, tol<T>(1e-10, 1e-16));
    // A polarity that is not ±1 is refused, not scaled.
    EXPECT_FALSE((field_vector_from_set_reset<T>({T(2.22), T(2.72), T(2.42)}, T(2.5), kHmc2003Sensitivity<T>, T(0.5),
                                                 {}, {T(0), T(0), T(0)}, {T(5), T(5), T(5)})
                      .valid));
}

TYPED_TEST(EstimatorCoreSetReset, AStillFieldGivesTheOffsetFromThreeAlternatingReadings) {
    using T = TypeParam;
    // v − v_ref after a set: S·B + o = (0.30 + 0.02, −0.20 + 0.02, 0.10 + 0.02); after a reset:
    // (−0.30 + 0.02, 0.20 + 0.02, −0.10 + 0.02). (set + 2 reset + set)/4 = 0.02 on every axis.
    SetResetState<T> s;
    const SetResetConfig c{.period_samples = 1, .offset_window = 2};
    const Vec3<T> set{T(0.32), T(-0.18), T(0.12)}, reset{T(-0.28), T(0.22), T(-0.08)};
    EXPECT_EQ(s.polarity, T(1));
    EXPECT_TRUE(set_reset_after_sample<T>(s, set, true, c));
    EXPECT_EQ(s.polarity, T(-1));  // the next reading is a reset one
    EXPECT_TRUE(set_reset_after_sample<T>(s, reset, true, c));
    EXPECT_EQ(s.pairs, 0);  // a lone pair does not enter the mean when pulsing every sample
    EXPECT_TRUE(set_reset_after_sample<T>(s, set, true, c));
    EXPECT_EQ(s.pairs, 1);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(s.offset[k], T(0.02), tol<T>(1e-6, 1e-15));
    EXPECT_EQ(applied_offset(s, c)[0], T(0));  // one estimate of a window of two: not applied yet
    EXPECT_TRUE(set_reset_after_sample<T>(s, reset, true, c));
    EXPECT_EQ(s.pairs, 2);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(applied_offset(s, c)[k], T(0.02), tol<T>(1e-6, 1e-15));
}

TYPED_TEST(EstimatorCoreSetReset, TheMeanOverPairsCancelsTheFieldsTurnBetweenReadings) {
    using T = TypeParam;
    // Field of 0.3 V (30 µT) turning at 2 rad/s in the x-y plane, sampled at 20 Hz: 0.1 rad between
    // readings. One pair's half sum errs by p·S·(B_k − B_{k−1})/2, up to 0.3·0.1/2 = 15 mV; the three-reading
    // estimate by p·S·(B_k − 2B_{k−1} + B_{k−2})/4, up to 0.3·0.1²/4 = 0.75 mV, with a sign that alternates
    // from one estimate to the next; a mean with weight 1/20 keeps α/(2 − α) = 1/39 of an alternating error:
    // 0.02 mV. After 200 samples the estimate must be within 0.1 mV of the true 20 mV, while the last single
    // pair alone is off by about 15 mV.
    const T offset = T(0.02), amplitude = T(0.3), turn = T(0.1);
    SetResetState<T> s;
    const SetResetConfig c{.period_samples = 1, .offset_window = 20};
    Vec3<T> previous{};
    T last_pair_error = 0;
    for (int k = 0; k < 200; ++k) {
        const T a = turn * static_cast<T>(k);
        const Vec3<T> reading{s.polarity * amplitude * std::cos(a) + offset,
                              s.polarity * amplitude * std::sin(a) + offset, offset};
        if (k > 0) last_pair_error = T(0.5) * (reading[0] + previous[0]) - offset;
        previous = reading;
        set_reset_after_sample<T>(s, reading, true, c);
    }
    EXPECT_GT(std::fabs(last_pair_error), T(0.01));
    EXPECT_NEAR(s.offset[0], offset, T(1e-4));
    EXPECT_NEAR(s.offset[1], offset, T(1e-4));
    EXPECT_NEAR(s.offset[2], offset, T(1e-6));
}

TYPED_TEST(EstimatorCoreSetReset, NoPulsesMeansNoOffsetAndASaturatedReadingPairsWithNothing) {
    using T = TypeParam;
    SetResetState<T> s;
    for (int k = 0; k < 5; ++k)
        EXPECT_FALSE(set_reset_after_sample<T>(s, {T(0.32), T(0.02), T(0.02)}, true, {.period_samples = 0}));
    EXPECT_EQ(s.polarity, T(1));
    EXPECT_EQ(s.pairs, 0);
    EXPECT_EQ(s.offset[0], T(0));

    SetResetState<T> t;
    const SetResetConfig every_other{.period_samples = 2, .offset_window = 4};
    EXPECT_FALSE(set_reset_after_sample<T>(t, {T(0.32), T(0.02), T(0.02)}, true, every_other));  // set
    EXPECT_TRUE(set_reset_after_sample<T>(t, {T(0.32), T(0.02), T(0.02)}, true, every_other));   // set, then pulse
    EXPECT_FALSE(set_reset_after_sample<T>(t, {T(2.5), T(0), T(0)}, false, every_other));        // reset, saturated
    EXPECT_EQ(t.pairs, 0);  // the saturated reset reading did not pair with the set one
    EXPECT_TRUE(set_reset_after_sample<T>(t, {T(-0.28), T(0.02), T(0.02)}, true, every_other));  // reset
    EXPECT_EQ(t.pairs, 0);  // and the next reset reading has no set neighbour
    EXPECT_FALSE(set_reset_after_sample<T>(t, {T(0.32), T(0.02), T(0.02)}, true, every_other));  // set
    EXPECT_EQ(t.pairs, 1);
    EXPECT_NEAR(t.offset[0], T(0.02), tol<T>(1e-6, 1e-15));
}

TYPED_TEST(EstimatorCoreSetReset, EstimateSampleUsesThePolarityAndOffsetItIsGiven) {
    using T = TypeParam;
    EstimatorConfig<T> config;
    for (auto& a : config.mag_adc) a.bits = 0;  // ideal converters: the hand values are exact
    config.mag_ref_adc.bits = 0;
    SampleInputs<T> in;
    in.v_mag = {T(2.22), T(2.72), T(2.42)};  // the reset reading of the first test
    in.v_mag_ref = T(2.5);
    in.mag_polarity = T(-1);
    in.mag_offset = {T(0.02), T(0.02), T(0.02)};
    const auto r = estimate_sample(in, config);
    ASSERT_TRUE(r.mag_valid);
    EXPECT_NEAR(r.mag_field[0], 30e-6, tol<T>(1e-10, 1e-16));
    EXPECT_NEAR(r.mag_field[1], -20e-6, tol<T>(1e-10, 1e-16));
    EXPECT_TRUE(r.mag_reading_usable);
    EXPECT_NEAR(r.mag_reading[0], T(-0.28), tol<T>(1e-6, 1e-15));
}

}  // namespace
}  // namespace attitude_estimator::test
