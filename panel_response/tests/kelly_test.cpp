// The angular response laws and their inverse. The Kelly curve is checked against the printed table and the
// cosine (ssr_plant's own tests check the same curve through the plant); the inverse against std::cos of the
// angle the response was made from.
#include "panel_response/kelly.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace panel_response {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

using Scalars = ::testing::Types<float, double>;
struct ScalarName {
    template <class T>
    static std::string GetName(int) {
        return std::is_same_v<T, float> ? "float" : "double";
    }
};
template <class T>
constexpr double tol(double for_float, double for_double) {
    return std::is_same_v<T, float> ? for_float : for_double;
}

template <class T>
class PanelResponse : public ::testing::Test {};
TYPED_TEST_SUITE(PanelResponse, Scalars, ScalarName);

// The knot data is a compile-time constant (constexpr table construction).
static_assert(kelly<double>().n == 5);
static_assert(kelly<double>().law == Law::table);
static_assert(cosine<float>().law == Law::cosine);

TYPED_TEST(PanelResponse, KellyPassesThroughThePrintedTable) {
    using T = TypeParam;
    const auto k = kelly<T>();
    // Patel's table (seed 000 fig. 4): 50° 0.635, 60° 0.450, 80° 0.100, 85° 0; cos β up to 30°; 0 beyond 85°.
    EXPECT_NEAR(response_from_angle(k, T(50 * kDeg)), 0.635, tol<T>(1e-6, 1e-14));
    EXPECT_NEAR(response_from_angle(k, T(60 * kDeg)), 0.450, tol<T>(1e-6, 1e-14));
    EXPECT_NEAR(response_from_angle(k, T(80 * kDeg)), 0.100, tol<T>(1e-6, 1e-14));
    EXPECT_EQ(response_from_angle(k, T(85 * kDeg)), T(0));
    EXPECT_EQ(response_from_angle(k, T(89 * kDeg)), T(0));
    EXPECT_EQ(response_from_cos(k, T(-0.5)), T(0));
    for (double b : {0.0, 10.0, 29.9})
        EXPECT_NEAR(response_from_cos(k, T(std::cos(b * kDeg))), std::cos(b * kDeg), tol<T>(1e-7, 1e-15));
    EXPECT_NEAR(response_from_angle(k, T(30 * kDeg)), std::sqrt(3.0) / 2, tol<T>(1e-6, 1e-15));
    // Below the cosine between the knots (the Kelly curve is the cosine trimmed at grazing incidence).
    for (double b : {40.0, 55.0, 70.0, 82.0}) EXPECT_LT(response_from_angle(k, T(b * kDeg)), std::cos(b * kDeg));
}

TYPED_TEST(PanelResponse, InverseRecoversTheAngleOfBothLaws) {
    using T = TypeParam;
    const auto k = kelly<T>();
    const auto c = cosine<T>();
    double worst_kelly = 0.0;
    for (double b = 0.0; b <= 84.9; b += 0.013) {
        const double want = std::cos(b * kDeg);
        const T rk = response_from_angle(k, T(b * kDeg));
        const double got = cos_from_response(k, rk);
        worst_kelly = std::max(worst_kelly, std::abs(got - want));
        // Near 85° the curve flattens (slope 0 at the knot): the angle is less determined by the response.
        const double bound = b < 80.0 ? tol<T>(2e-6, 1e-12) : tol<T>(2e-3, 1e-9);
        ASSERT_NEAR(got, want, bound) << b;
        ASSERT_NEAR(cos_from_response(c, T(want)), want, tol<T>(1e-7, 1e-15)) << b;
        ASSERT_NEAR(angle_from_response(k, rk), b * kDeg, b < 80.0 ? tol<T>(2e-3, 1e-9) : tol<T>(5e-2, 1e-7)) << b;
    }
    this->RecordProperty("worst_kelly_cos", std::to_string(worst_kelly));
}

TYPED_TEST(PanelResponse, InverseIsMonotoneAndHandlesTheEnds) {
    using T = TypeParam;
    const auto k = kelly<T>();
    T prev = T(-1);
    for (int j = -10; j <= 12000; ++j) {
        const T r = T(j) / T(10000);
        const T cb = cos_from_response(k, r);
        ASSERT_GE(cb, prev) << r;
        ASSERT_GE(cb, T(0));
        ASSERT_LE(cb, T(1));
        prev = cb;
    }
    EXPECT_EQ(cos_from_response(k, T(0)), T(0));
    EXPECT_EQ(cos_from_response(k, T(-0.1)), T(0));
    EXPECT_EQ(cos_from_response(k, std::numeric_limits<T>::quiet_NaN()), T(0));
    EXPECT_EQ(cos_from_response(k, T(1.3)), T(1));
    // A faint but non-zero reading lies inside the Hermite tail, just below 85°.
    const double tiny = cos_from_response(k, T(1e-4));
    EXPECT_GT(tiny, std::cos(85 * kDeg));
    EXPECT_LT(tiny, std::cos(83 * kDeg));
}

TYPED_TEST(PanelResponse, DarkBoundOfEachLaw) {
    using T = TypeParam;
    // Cosine: a face reading ≤ t has cos β ≤ t. Kelly: the flat tail makes it at least cos 85°.
    EXPECT_NEAR(dark_cos(cosine<T>(), T(0.02)), 0.02, tol<T>(1e-7, 1e-15));
    EXPECT_NEAR(dark_cos(kelly<T>(), T(0)), std::cos(85 * kDeg), tol<T>(1e-7, 1e-15));
    const double d = dark_cos(kelly<T>(), T(0.02));
    EXPECT_GT(d, std::cos(85 * kDeg));
    EXPECT_LT(d, std::cos(80 * kDeg));
    // Consistency: the response at that cos is the threshold itself.
    EXPECT_NEAR(response_from_cos(kelly<T>(), T(d)), 0.02, tol<T>(1e-5, 1e-12));
}

TEST(PanelResponseTable, BadTablesFallBackToTheCosine) {
    constexpr std::array<Knot<double>, 3> decreasing = {{{0, 1}, {40, 0.7}, {30, 0.0}}};
    EXPECT_EQ(table<double>(decreasing).law, Law::cosine);
    constexpr std::array<Knot<double>, 3> too_far = {{{0, 1}, {40, 0.7}, {95, 0.0}}};
    EXPECT_EQ(table<double>(too_far).law, Law::cosine);
    constexpr std::array<Knot<double>, 3> ok = {{{0, 1}, {40, 0.7}, {80, 0.0}}};
    EXPECT_EQ(table<double>(ok).law, Law::table);
}

}  // namespace
}  // namespace panel_response
