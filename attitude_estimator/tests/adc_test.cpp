// ADC model: codes and values computed by hand from the documented transfer function
// code = floor((x − min)(2^bits − 1)/(max − min) + ½), value = min + code (max − min)/(2^bits − 1).
#include "attitude_estimator/adc.hpp"

#include "test_support.hpp"

namespace attitude_estimator::test {
namespace {

template <class T>
class EstimatorCoreAdc : public ::testing::Test {};
TYPED_TEST_SUITE(EstimatorCoreAdc, Scalars, ScalarName);

TYPED_TEST(EstimatorCoreAdc, TwelveBitsZeroToFiveVolts) {
    using T = TypeParam;
    const AdcConfig<T> adc{12, T(0), T(5)};
    // 1.0 V: 1.0 · 4095 / 5 = 819 exactly → code 819 → 819 · 5 / 4095 = 1.0 V.
    auto r = convert(adc, T(1.0));
    EXPECT_EQ(r.code, 819u);
    EXPECT_NEAR(r.value, 1.0, tol<T>(1e-6, 1e-12));
    EXPECT_FALSE(r.clipped);
    // 1.001 V: 819.819 → 820 → 4100/4095 = 1.0012210012 V.
    r = convert(adc, T(1.001));
    EXPECT_EQ(r.code, 820u);
    EXPECT_NEAR(r.value, 1.0012210012, tol<T>(1e-6, 1e-9));
    // 2.5 V (the HMC2003 zero-field reference): 2047.5 → half rounds up → 2048 → 2.5006105006 V.
    r = convert(adc, T(2.5));
    EXPECT_EQ(r.code, 2048u);
    EXPECT_NEAR(r.value, 2.5006105006, tol<T>(1e-6, 1e-9));
    // 0.0006 V: 0.49140 → code 0; 0.0007 V: 0.5733 → code 1 → 5/4095 = 0.00122100 V.
    EXPECT_EQ(convert(adc, T(0.0006)).code, 0u);
    r = convert(adc, T(0.0007));
    EXPECT_EQ(r.code, 1u);
    EXPECT_NEAR(r.value, 0.001221001221, tol<T>(1e-8, 1e-12));
}

TYPED_TEST(EstimatorCoreAdc, ClipsAtBothEnds) {
    using T = TypeParam;
    const AdcConfig<T> adc{12, T(0), T(5)};
    auto r = convert(adc, T(-0.3));
    EXPECT_EQ(r.code, 0u);
    EXPECT_EQ(r.value, T(0));
    EXPECT_TRUE(r.clipped);
    r = convert(adc, T(7));
    EXPECT_EQ(r.code, 4095u);
    EXPECT_EQ(r.value, T(5));
    EXPECT_TRUE(r.clipped);
    r = convert(adc, T(5));  // the end itself is in range and exact
    EXPECT_EQ(r.code, 4095u);
    EXPECT_EQ(r.value, T(5));
    EXPECT_FALSE(r.clipped);
}

TYPED_TEST(EstimatorCoreAdc, ThreeBitsSymmetricRange) {
    using T = TypeParam;
    // 3 bits over −1…1: 7 steps of 2/7.
    const AdcConfig<T> adc{3, T(-1), T(1)};
    // 0: u = 3.5 → 4 → −1 + 8/7 = 1/7.
    auto r = convert(adc, T(0));
    EXPECT_EQ(r.code, 4u);
    EXPECT_NEAR(r.value, 1.0 / 7.0, tol<T>(1e-6, 1e-14));
    // 0.2: u = 4.2 → 4 → 1/7;  0.3: u = 4.55 → 5 → 3/7;  −0.95: u = 0.175 → 0 → −1.
    EXPECT_EQ(convert(adc, T(0.2)).code, 4u);
    r = convert(adc, T(0.3));
    EXPECT_EQ(r.code, 5u);
    EXPECT_NEAR(r.value, 3.0 / 7.0, tol<T>(1e-6, 1e-14));
    EXPECT_EQ(convert(adc, T(-0.95)).value, T(-1));
}

TYPED_TEST(EstimatorCoreAdc, IdealConverterPassesValuesButStillClips) {
    using T = TypeParam;
    const AdcConfig<T> adc{0, T(0), T(5)};
    auto r = convert(adc, T(1.2345));
    EXPECT_EQ(r.value, T(1.2345));
    EXPECT_FALSE(r.clipped);
    r = convert(adc, T(6));
    EXPECT_EQ(r.value, T(5));
    EXPECT_TRUE(r.clipped);
}

TYPED_TEST(EstimatorCoreAdc, NanAndBadRangeGiveMinFlagged) {
    using T = TypeParam;
    auto r = convert(AdcConfig<T>{12, T(0), T(5)}, std::numeric_limits<T>::quiet_NaN());
    EXPECT_EQ(r.code, 0u);
    EXPECT_EQ(r.value, T(0));
    EXPECT_TRUE(r.clipped);
    r = convert(AdcConfig<T>{12, T(5), T(5)}, T(1));
    EXPECT_EQ(r.value, T(5));
    EXPECT_TRUE(r.clipped);
}

TYPED_TEST(EstimatorCoreAdc, ErrorWithinHalfAnLsbAcrossTheRange) {
    using T = TypeParam;
    const AdcConfig<T> adc{12, T(-2), T(2)};
    const double lsb = 4.0 / 4095.0;
    double worst = 0.0;
    for (int i = 0; i <= 100000; ++i) {
        const T x = static_cast<T>(-2.0 + 4.0 * i / 100000.0);
        worst = std::max(worst, std::fabs(static_cast<double>(convert(adc, x).value) - static_cast<double>(x)));
    }
    EXPECT_LE(worst, 0.5 * lsb * (1.0 + tol<T>(1e-3, 1e-9)));
    EXPECT_GE(worst, 0.49 * lsb);  // and it does quantize
}

}  // namespace
}  // namespace attitude_estimator::test
