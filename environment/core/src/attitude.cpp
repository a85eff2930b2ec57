#include "environment/attitude.hpp"

#include <cmath>

namespace environment {

Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& v) {
    Eigen::Matrix3d m;
    m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
    return m;
}

Eigen::Matrix3d attitude_matrix(const Quaternion& q) {
    const Eigen::Vector3d Q(q[0], q[1], q[2]);
    const double w = q[3];
    // A(q) = (w^2 - |Q|^2) I + 2 Q Q^T - 2 w [Q x]   (seed 000 Q-method section; design.md)
    return (w * w - Q.squaredNorm()) * Eigen::Matrix3d::Identity() + 2.0 * Q * Q.transpose() -
           2.0 * w * cross_matrix(Q);
}

Quaternion quaternion_from_attitude_matrix(const Eigen::Matrix3d& A) {
    // Shepperd's method: pick the largest of 4w^2, 4x^2, 4y^2, 4z^2 to divide by, for accuracy.
    // With A = A(q) above: trace = 4w^2 - 1, A(1,2) - A(2,1) = 4 w x, etc.
    const double tr = A.trace();
    const double d[4] = {1.0 + 2.0 * A(0, 0) - tr, 1.0 + 2.0 * A(1, 1) - tr, 1.0 + 2.0 * A(2, 2) - tr, 1.0 + tr};
    int k = 0;
    for (int i = 1; i < 4; ++i) {
        if (d[i] > d[k]) k = i;
    }
    Quaternion q{};
    const double s = 2.0 * std::sqrt(d[k]);  // = 4 |q_k|
    switch (k) {
        case 0:
            q = {s / 4.0, (A(0, 1) + A(1, 0)) / s, (A(0, 2) + A(2, 0)) / s, (A(1, 2) - A(2, 1)) / s};
            break;
        case 1:
            q = {(A(0, 1) + A(1, 0)) / s, s / 4.0, (A(1, 2) + A(2, 1)) / s, (A(2, 0) - A(0, 2)) / s};
            break;
        case 2:
            q = {(A(0, 2) + A(2, 0)) / s, (A(1, 2) + A(2, 1)) / s, s / 4.0, (A(0, 1) - A(1, 0)) / s};
            break;
        default:
            q = {(A(1, 2) - A(2, 1)) / s, (A(2, 0) - A(0, 2)) / s, (A(0, 1) - A(1, 0)) / s, s / 4.0};
            break;
    }
    if (q[3] < 0.0) {
        for (double& c : q) c = -c;
    }
    const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (double& c : q) c /= norm;
    return q;
}

}  // namespace environment
