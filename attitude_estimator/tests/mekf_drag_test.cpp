// The MEKF's propagation with the drag torque (MekfConfig::drag; docs/filter.md, "Drag") against a fine RK4
// integration written here of the rigid body in a fixed inertial wind: ω̇ = J⁻¹(τ − ω × J ω), Ȧ = −[ω×] A,
// τ = Σ_k c_k × (−½ ρ C_D A_k |v| max(0, n_k·v) v), v = A v_I, the 3U's box (docs/design.md) at a density of
// 2e-11 kg/m³ (the table near 300 km: the drag is made large so that 120 s shows it). And the density's
// uncertainty in the process noise: the rate covariance grows by (σ |τ|)² 2 τ_c J⁻¹J⁻ᵀ per second.
#include <cmath>

#include "attitude_estimator/mekf.hpp"
#include "test_support.hpp"

namespace attitude_estimator::test {
namespace {

template <class T>
class EstimatorCoreMekfDrag : public ::testing::Test {};
TYPED_TEST_SUITE(EstimatorCoreMekfDrag, Scalars, ScalarName);

const Eigen::Vector3d kSize(0.1, 0.1, 0.34);
const Eigen::Vector3d kCom(0.004, -0.003, -0.012);
constexpr double kCd = 2.2;
constexpr double kRho = 2e-11;

Eigen::Matrix3d three_u_inertia() {
    Eigen::Matrix3d j;
    j << 0.0405, 0.00015, -0.0002, 0.00015, 0.0398, 0.0001, -0.0002, 0.0001, 0.0072;
    return j;
}

// The box's drag torque, face by face (the six faces written out, none of drag_torque.cpp's shortcuts).
Eigen::Vector3d box_drag(const Eigen::Vector3d& v) {
    Eigen::Vector3d torque = Eigen::Vector3d::Zero();
    for (int axis = 0; axis < 3; ++axis) {
        for (double side : {1.0, -1.0}) {
            Eigen::Vector3d n = Eigen::Vector3d::Zero();
            n(axis) = side;
            const double area = kSize((axis + 1) % 3) * kSize((axis + 2) % 3);
            const Eigen::Vector3d centroid = 0.5 * kSize(axis) * n - kCom;
            const double cos_v = n.dot(v);
            if (cos_v > 0.0) torque += centroid.cross(-0.5 * kRho * kCd * area * cos_v * v);  // |v|² cos α v̂
        }
    }
    return torque;
}

template <class T>
MekfConfig<T> config(bool drag) {
    MekfConfig<T> c;
    const Eigen::Matrix3d j = three_u_inertia();
    for (int i = 0; i < 9; ++i) c.inertia[static_cast<std::size_t>(i)] = static_cast<T>(j(i / 3, i % 3));
    if (drag) {
        c.drag.size = {T(kSize.x()), T(kSize.y()), T(kSize.z())};
        c.drag.centre_of_mass = {T(kCom.x()), T(kCom.y()), T(kCom.z())};
        c.drag.drag_coefficient = T(kCd);
    }
    return c;
}

TYPED_TEST(EstimatorCoreMekfDrag, PropagationFollowsARigidBodyInTheWind) {
    using T = TypeParam;
    const Eigen::Matrix3d j = three_u_inertia();
    const Eigen::Matrix3d j_inv = j.inverse();
    const Eigen::Vector3d wind(-2100.0, 6900.0, 2600.0);  // m/s, inertial (7.6 km/s)
    auto wdot = [&](const Eigen::Vector3d& w, const Eigen::Matrix3d& a) {
        return Eigen::Vector3d(j_inv * (box_drag(a * wind) - w.cross(j * w)));
    };
    Random rng(17);
    const Eigen::Matrix3d a0 = rng.rotation();
    const Eigen::Vector3d w0 = 0.01 * rng.unit();  // a slow tumble (0.6 deg/s): the drag does not average out
    Eigen::Vector3d w = w0;
    Eigen::Matrix3d a = a0;
    rk4_rate_and_attitude(w, a, 1e-3, 120000, wdot);
    ASSERT_LT((a * a.transpose() - Eigen::Matrix3d::Identity()).norm(), 1e-9);

    auto propagate = [&](bool modelled) {
        const MekfConfig<T> c = config<T>(modelled);
        MekfState<T> s;
        mekf_start(s, quaternion_of<T>(a0), to_vec<T>(w0), T(0), c);
        s.torque_air_velocity = to_vec<T>(wind);
        s.torque_air_density = T(kRho);
        for (int k = 0; k < 2400; ++k) mekf_propagate(s, T(0.05), c);
        return std::make_pair(Eigen::Vector3d(s.omega[0], s.omega[1], s.omega[2]), matrix_of(s.q));
    };
    const auto [w_filter, a_filter] = propagate(true);
    EXPECT_LT((w_filter - w).norm(), tol<T>(2e-5, 5e-6)) << "rad/s";
    EXPECT_LT(attitude_angle(a_filter, a), tol<T>(2e-3, 2e-4)) << "rad";
    // Without the drag model the propagation misses it (what the filter did before): not trivially met.
    const auto [w_free, a_free] = propagate(false);
    EXPECT_GT((w_free - w).norm(), 5e-4);
    EXPECT_GT(attitude_angle(a_free, a), 0.02);
}

TYPED_TEST(EstimatorCoreMekfDrag, DensityUncertaintyEntersTheRateNoiseThroughTheInertia) {
    using T = TypeParam;
    // At rest (no gyroscopic coupling), identity attitude, wind along +x: τ = (0, −qA·0.012, qA·0.003) with
    // qA = ½ ρ C_D V² A_x = 0.5 · 2e-11 · 2.2 · 7600² · 0.034 = 4.3204e-5 N: |τ| = 5.344e-7 N m. With σ = 0.8 and
    // τ_c = 60 s over 1 s the rate covariance grows by (0.8 · 5.344e-7)² · 120 · J⁻¹J⁻ᵀ beyond the drag-free case.
    const Eigen::Vector3d wind(7600.0, 0.0, 0.0);
    auto rate_covariance = [&](T sigma) {
        MekfConfig<T> c = config<T>(true);
        c.drag_density_sigma = sigma;
        c.drag_correlation_time = T(60);
        MekfState<T> s;
        mekf_start(s, Quaternion<T>{}, Vec3<T>{}, T(0), c);
        s.torque_air_velocity = to_vec<T>(wind);
        s.torque_air_density = T(kRho);
        mekf_propagate(s, T(1), c);
        Eigen::Matrix3d p;
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k < 3; ++k)
                p(i, k) =
                    static_cast<double>(s.p[static_cast<std::size_t>(kMekfStates * (kMekfRate + i) + kMekfRate + k)]);
        return p;
    };
    const Eigen::Matrix3d added = rate_covariance(T(0.8)) - rate_covariance(T(0));
    const Eigen::Matrix3d j_inv = three_u_inertia().inverse();
    const double torque = 4.3204e-5 * std::hypot(0.012, 0.003);
    const Eigen::Matrix3d expected = std::pow(0.8 * torque, 2) * 120.0 * j_inv * j_inv.transpose();
    EXPECT_LT((added - expected).norm(), tol<T>(2e-3, 1e-4) * expected.norm()) << "added\n"
                                                                               << added << "\nexpected\n"
                                                                               << expected;
}

}  // namespace
}  // namespace attitude_estimator::test
