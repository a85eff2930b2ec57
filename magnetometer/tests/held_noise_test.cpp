// The counter-based held noise: reference values, the hold-interval index and its limits, and the
// statistics a Gaussian white sequence must have.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "fmu/errors.hpp"
#include "magnetometer/held_noise.hpp"

namespace magnetometer {
namespace {

TEST(HeldNoise, MatchesAnIndependentImplementation) {
    // Reference values from a separate Python transcription of the generator (arbitrary-precision
    // integers masked to 64 bits, math.log/cos), not from this code:
    //   key = mix(seed + 0x9E3779B97F4A7C15); c = 2(3k + a);
    //   u = ((mix(key ^ mix(c)) >> 11) + 0.5) 2^-53, likewise for c + 1; z = sqrt(-2 ln u1) cos(2π u2)
    EXPECT_NEAR(held_normal(1, 0, 0), 0.08359937294590762, 1e-14);
    EXPECT_NEAR(held_normal(1, 0, 1), -0.07892058778528543, 1e-14);
    EXPECT_NEAR(held_normal(1, 0, 2), 1.4009120286544916, 1e-14);
    EXPECT_NEAR(held_normal(1, 1, 0), -0.7412925122837931, 1e-14);
    EXPECT_NEAR(held_normal(7, 123456, 2), 0.21675962638206261, 1e-14);
    EXPECT_NEAR(held_normal(1, -1, 0), 0.8160914977827779, 1e-14);
}

TEST(HeldNoise, IndexCountsWholeIntervalsAndForgivesTheHostsRounding) {
    EXPECT_EQ(noise_index(0.0, 0.0, 0.01), 0);
    EXPECT_EQ(noise_index(0.0099, 0.0, 0.01), 0);
    EXPECT_EQ(noise_index(0.0101, 0.0, 0.01), 1);
    // 0.3/0.1 = 2.9999999999999996 in binary floating point: the host meant the start of interval 3.
    EXPECT_EQ(noise_index(0.3, 0.0, 0.1), 3);
    double t = 0.0;
    for (int i = 0; i < 7; ++i) t += 0.1;  // 0.7000000000000001 as a sum of steps
    EXPECT_EQ(noise_index(t, 0.0, 0.1), 7);
    EXPECT_EQ(noise_index(10.005, 10.0, 0.01), 0);  // counted from the start time
    EXPECT_EQ(noise_index(9.995, 10.0, 0.01), -1);
}

TEST(HeldNoise, IndexRefusesTimesBeyondItsLimitInsteadOfOverflowing) {
    EXPECT_THROW(noise_index(1e300, 0.0, 1e-5), fmu::Error);  // (t - t0)/period = 1e305: no int64 holds it
    EXPECT_THROW(noise_index(std::numeric_limits<double>::quiet_NaN(), 0.0, 0.01), fmu::Error);
    EXPECT_THROW(noise_index(std::numeric_limits<double>::infinity(), 0.0, 0.01), fmu::Error);
    EXPECT_THROW(noise_index(0.0, 0.0, 0.0), fmu::Error);       // 0/0
    EXPECT_THROW(noise_index(1e11, 0.0, 1e-5), fmu::Error);     // 1e16 > 2^53 ≈ 9.007e15 intervals
    EXPECT_EQ(noise_index(9e10, 0.0, 1e-5), 9000000000000000);  // 9e15 < 2^53: still exact
}

TEST(HeldNoise, SamplesAreStandardNormalAndUncorrelated) {
    // For N = 100000 independent N(0,1) draws: the mean has σ = 0.0032, the variance σ = 0.0045, a
    // correlation coefficient σ = 0.0032, the fraction inside ±1σ (0.682689) σ = 0.0015. Bounds ≈ 5σ.
    constexpr int n = 100000;
    double sum = 0, sum2 = 0, lag = 0, cross = 0, prev = 0;
    int inside = 0;
    for (int k = 0; k < n; ++k) {
        const double z = held_normal(3, k, 0);
        const double w = held_normal(3, k, 1);
        sum += z;
        sum2 += z * z;
        lag += z * prev;
        cross += z * w;
        inside += std::fabs(z) < 1.0;
        prev = z;
    }
    EXPECT_NEAR(sum / n, 0.0, 0.016);
    EXPECT_NEAR(sum2 / n, 1.0, 0.023);
    EXPECT_NEAR(lag / n, 0.0, 0.016);
    EXPECT_NEAR(cross / n, 0.0, 0.016);
    EXPECT_NEAR(static_cast<double>(inside) / n, 0.682689, 0.0075);
    // Different seeds give unrelated sequences.
    double seeds = 0;
    for (int k = 0; k < n; ++k) seeds += held_normal(3, k, 0) * held_normal(4, k, 0);
    EXPECT_NEAR(seeds / n, 0.0, 0.016);
}

}  // namespace
}  // namespace magnetometer
