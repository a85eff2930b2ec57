// A(q) and its inverse against Eigen (independent implementation) and hand-computed matrices.
#include "attitude_estimator/attitude_matrix.hpp"

#include "test_support.hpp"

namespace attitude_estimator::test {
namespace {

template <class T>
class EstimatorCoreAttitudeMatrix : public ::testing::Test {};
TYPED_TEST_SUITE(EstimatorCoreAttitudeMatrix, Scalars, ScalarName);

TYPED_TEST(EstimatorCoreAttitudeMatrix, NinetyDegreesAboutZByHand) {
    using T = TypeParam;
    // q = (0, 0, sin 45°, cos 45°): w² − |Q|² = 0, 2 Q Qᵀ puts 1 at (2,2), −2w[Q×] puts +1 at (0,1) and −1 at
    // (1,0): A = [[0, 1, 0], [−1, 0, 0], [0, 0, 1]] (the frame turned +90°, so x_ref is seen along −y_body).
    const T h = static_cast<T>(std::sqrt(0.5));
    const auto a = attitude_matrix(Quaternion<T>{0, 0, h, h});
    const double expected[9] = {0, 1, 0, -1, 0, 0, 0, 0, 1};
    for (int i = 0; i < 9; ++i) EXPECT_NEAR(a[i], expected[i], tol<T>(1e-6, 1e-15)) << i;
}

TYPED_TEST(EstimatorCoreAttitudeMatrix, IsTheTransposeOfEigensActiveRotation) {
    using T = TypeParam;
    // The design's A is the passive (frame) rotation: A(q) = R(q)ᵀ with R Eigen's active rotation matrix of
    // the same Hamilton quaternion. Eigen's constructor order is (w, x, y, z).
    Random rng(11);
    for (int n = 0; n < 1000; ++n) {
        const Eigen::Quaterniond e = Eigen::Quaterniond::UnitRandom();
        const auto a = attitude_matrix(Quaternion<T>{T(e.x()), T(e.y()), T(e.z()), T(e.w())});
        const Eigen::Matrix3d r = e.toRotationMatrix().transpose();
        for (int i = 0; i < 9; ++i) ASSERT_NEAR(a[i], r(i / 3, i % 3), tol<T>(2e-6, 1e-14));
    }
}

TYPED_TEST(EstimatorCoreAttitudeMatrix, QuaternionFromMatrixRoundTripIncludingHalfTurns) {
    using T = TypeParam;
    Random rng(12);
    double worst = 0.0;
    for (int n = 0; n < 4000; ++n) {
        // A quarter of the cases within 1e-4 rad of 180°, where a trace-only formula divides by ~0.
        const double angle = n % 4 == 0 ? M_PI - rng.uniform(0.0, 1e-4) : rng.uniform(0.0, M_PI);
        const Eigen::Matrix3d r = rng.rotation(angle);
        Matrix3RowMajor<T> a;
        for (int i = 0; i < 9; ++i) a[i] = static_cast<T>(r(i / 3, i % 3));
        const Quaternion<T> q = quaternion_from_attitude_matrix(a);
        EXPECT_GE(q.w, T(0));
        worst = std::max(worst, attitude_angle(to_eigen(attitude_matrix(q)), r));
    }
    EXPECT_LT(worst, tol<T>(1e-6, 1e-14));
    std::printf("[%s] quaternion_from_attitude_matrix round trip, worst angle %.3g rad\n",
                std::is_same_v<T, float> ? "float" : "double", worst);
}

TEST(EstimatorCoreAttitudeMatrix, HalfTurnAboutXByHand) {
    // 180° about x: A = diag(1, −1, −1) → q = ±(1, 0, 0, 0).
    const auto q = quaternion_from_attitude_matrix<double>({1, 0, 0, 0, -1, 0, 0, 0, -1});
    EXPECT_NEAR(std::fabs(q.x), 1.0, 1e-15);
    EXPECT_NEAR(q.y, 0.0, 1e-15);
    EXPECT_NEAR(q.z, 0.0, 1e-15);
    EXPECT_NEAR(q.w, 0.0, 1e-15);
}

}  // namespace
}  // namespace attitude_estimator::test
