// Noise-free observations of a known rotation (truth from Eigen's AngleAxis): both solvers must return it,
// with zero loss, for 2…6 observations, any angle up to and including 180°.
#include "attitude_estimator/fast_solver.hpp"
#include "attitude_estimator/q_method.hpp"

#include "test_support.hpp"

namespace attitude_estimator::test {
namespace {

template <class T>
class EstimatorCoreKnownRotation : public ::testing::Test {};
TYPED_TEST_SUITE(EstimatorCoreKnownRotation, Scalars, ScalarName);

TYPED_TEST(EstimatorCoreKnownRotation, QuarterTurnAboutZByHand) {
    using T = TypeParam;
    // A = [[0, 1, 0], [−1, 0, 0], [0, 0, 1]]: x_ref → (0, −1, 0), y_ref → (1, 0, 0); by hand q = (0, 0, √½, √½).
    for (SolverKind kind : {SolverKind::qmethod, SolverKind::fast}) {
        ObservationSet<T> set;
        set.add({1, 0, 0}, {0, -1, 0}, T(1));
        set.add({0, 1, 0}, {1, 0, 0}, T(3));
        const auto s = solve_wahba(set, kind);
        ASSERT_TRUE(s.valid);
        EXPECT_NEAR(s.q.x, 0.0, tol<T>(1e-6, 1e-14));
        EXPECT_NEAR(s.q.y, 0.0, tol<T>(1e-6, 1e-14));
        EXPECT_NEAR(s.q.z, std::sqrt(0.5), tol<T>(1e-6, 1e-14));
        EXPECT_NEAR(s.q.w, std::sqrt(0.5), tol<T>(1e-6, 1e-14));
    }
}

TYPED_TEST(EstimatorCoreKnownRotation, HalfTurnAboutXByHand) {
    using T = TypeParam;
    // A = diag(1, −1, −1): q = ±(1, 0, 0, 0). Two observations (closed form) and three (λmax + null vector).
    for (SolverKind kind : {SolverKind::qmethod, SolverKind::fast}) {
        for (int n = 2; n <= 3; ++n) {
            ObservationSet<T> set;
            set.add({1, 0, 0}, {1, 0, 0}, T(1));
            set.add({0, 1, 0}, {0, -1, 0}, T(1));
            if (n == 3) set.add({0, 0, 1}, {0, 0, -1}, T(1));
            const auto s = solve_wahba(set, kind);
            ASSERT_TRUE(s.valid);
            EXPECT_NEAR(std::fabs(s.q.x), 1.0, tol<T>(1e-6, 1e-14));
            EXPECT_NEAR(s.q.w, 0.0, tol<T>(1e-3, 1e-7));
            EXPECT_NEAR(s.loss, 0.0, tol<T>(1e-6, 1e-14));
        }
    }
}

TYPED_TEST(EstimatorCoreKnownRotation, RandomRotationsTwoToSixObservations) {
    using T = TypeParam;
    Random rng(21);
    double worst[2] = {0, 0};
    double worst_loss[2] = {0, 0};
    for (int trial = 0; trial < 20000; ++trial) {
        const int n = 2 + trial % 5;
        // Every fifth rotation is within 1e-3 rad of a half turn.
        const double angle = trial % 5 == 0 ? M_PI - rng.uniform(0.0, 1e-3) : rng.uniform(0.0, M_PI);
        const Eigen::Matrix3d a_true = rng.rotation(angle);
        ObservationSet<T> set;
        Eigen::Vector3d v0 = rng.unit();
        for (int i = 0; i < n; ++i) {
            Eigen::Vector3d v = rng.unit();
            // Keep the first pair at least 20° apart so the problem is well posed.
            while (i == 1 && v.cross(v0).norm() < std::sin(20.0 * M_PI / 180.0)) v = rng.unit();
            if (i == 0) v = v0;
            // The weight first, then the length: the order GCC evaluated them in when they were the call's arguments.
            const double weight = rng.uniform(0.1, 1.0);
            const double length = rng.uniform(0.5, 2.0);
            set.add(to_vec<T>(v * length), to_vec<T>(a_true * v), static_cast<T>(weight));
        }
        for (int k = 0; k < 2; ++k) {
            const auto s = k == 0 ? solve_q_method(set) : solve_fast(set);
            ASSERT_TRUE(s.valid);
            worst[k] = std::max(worst[k], attitude_angle(to_eigen(s.a), a_true));
            worst_loss[k] = std::max(worst_loss[k], static_cast<double>(s.loss));
        }
    }
    const char* name = std::is_same_v<T, float> ? "float" : "double";
    std::printf(
        "[%s] known rotations, 20000 problems: worst angle qmethod %.3g rad, fast %.3g rad; "
        "worst loss qmethod %.3g, fast %.3g\n",
        name, worst[0], worst[1], worst_loss[0], worst_loss[1]);
    for (int k = 0; k < 2; ++k) {
        EXPECT_LT(worst[k], tol<T>(2e-5, 1e-12));
        EXPECT_LT(worst_loss[k], tol<T>(1e-9, 1e-20));
    }
}

TYPED_TEST(EstimatorCoreKnownRotation, UnsolvableSetsGiveInvalidIdentity) {
    using T = TypeParam;
    for (SolverKind kind : {SolverKind::qmethod, SolverKind::fast}) {
        ObservationSet<T> one;
        one.add({1, 0, 0}, {0, 1, 0}, T(1));
        EXPECT_FALSE(solve_wahba(one, kind).valid);
        ObservationSet<T> zero_vec;
        zero_vec.add({1, 0, 0}, {0, 1, 0}, T(1));
        zero_vec.add({0, 0, 0}, {0, 0, 1}, T(1));
        const auto s = solve_wahba(zero_vec, kind);
        EXPECT_FALSE(s.valid);
        EXPECT_EQ(s.q.w, T(1));
        ObservationSet<T> negative;
        negative.add({1, 0, 0}, {0, 1, 0}, T(1));
        negative.add({0, 1, 0}, {1, 0, 0}, T(-1));
        EXPECT_FALSE(solve_wahba(negative, kind).valid);
        ObservationSet<T> parallel;
        parallel.add({1, 0, 0}, {0, 1, 0}, T(1));
        parallel.add({2, 0, 0}, {0, 3, 0}, T(1));
        EXPECT_FALSE(solve_wahba(parallel, kind).valid);
        ObservationSet<T> full;
        for (std::size_t i = 0; i < kMaxObservations; ++i) EXPECT_TRUE(full.add({1, 0, 0}, {1, 0, 0}, T(1)));
        EXPECT_FALSE(full.add({1, 0, 0}, {1, 0, 0}, T(1)));
    }
}

TYPED_TEST(EstimatorCoreKnownRotation, SeparationThresholdDecidesValidity) {
    using T = TypeParam;
    // Two directions 4° apart are below the default 5° (sin 5° = 0.08716); 6° apart is above it.
    for (double deg : {4.0, 6.0}) {
        const double r = deg * M_PI / 180.0;
        ObservationSet<T> set;
        set.add({1, 0, 0}, {1, 0, 0}, T(1));
        set.add({T(std::cos(r)), T(std::sin(r)), 0}, {T(std::cos(r)), T(std::sin(r)), 0}, T(1));
        for (SolverKind kind : {SolverKind::qmethod, SolverKind::fast}) {
            const auto s = solve_wahba(set, kind);
            EXPECT_EQ(s.valid, deg > 5.0) << deg;
            EXPECT_NEAR(s.q.w, 1.0, tol<T>(1e-4, 1e-10));  // still solved: identity
        }
    }
}

}  // namespace
}  // namespace attitude_estimator::test
