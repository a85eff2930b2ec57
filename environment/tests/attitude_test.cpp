#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>

#include "environment/attitude.hpp"

namespace env = environment;

TEST(EnvironmentCoreAttitude, NinetyDegreesAboutZByHand) {
    // q = [0, 0, sin 45, cos 45]: the body is turned +90 deg about z, so the inertial x axis is seen
    // along body -y and inertial y along body +x. Hand evaluation of A(q) = (w^2-|Q|^2)I + 2QQ^T - 2w[Qx].
    const double s = std::sqrt(0.5);
    const Eigen::Matrix3d A = env::attitude_matrix({0.0, 0.0, s, s});
    Eigen::Matrix3d expected;
    expected << 0, 1, 0, -1, 0, 0, 0, 0, 1;
    EXPECT_LT((A - expected).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(EnvironmentCoreAttitude, MatchesTransposeOfEigenActiveRotation) {
    // Independent implementation: Eigen's quaternion (constructor order w, x, y, z) gives the active
    // rotation matrix, which is A(q)^T in the project's convention.
    const env::Quaternion samples[] = {{0.1, -0.2, 0.3, 0.927361849549570},
                                       {0.7, 0.1, -0.1, 0.6999999999999999},
                                       {-0.5, 0.5, 0.5, 0.5},
                                       {0.0, 0.9, 0.3, 0.316227766016838}};
    for (const auto& q : samples) {
        const Eigen::Quaterniond e(q[3], q[0], q[1], q[2]);
        const Eigen::Matrix3d A = env::attitude_matrix(q);
        EXPECT_LT((A - e.normalized().toRotationMatrix().transpose()).cwiseAbs().maxCoeff(), 1e-14);
    }
}

TEST(EnvironmentCoreAttitude, QuaternionRoundTripCoversAllBranches) {
    // Each sample has a different largest component so every branch of Shepperd's method runs.
    const env::Quaternion samples[] = {
        {0.9, 0.3, 0.1, 0.3}, {0.1, -0.95, 0.2, 0.2}, {0.2, 0.1, 0.97, -0.1}, {0.1, 0.1, 0.1, 0.98}};
    for (auto q : samples) {
        double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        for (double& c : q) c /= n;
        if (q[3] < 0)
            for (double& c : q) c = -c;
        const env::Quaternion back = env::quaternion_from_attitude_matrix(env::attitude_matrix(q));
        for (int i = 0; i < 4; ++i) EXPECT_NEAR(back[i], q[i], 1e-14);
    }
}
