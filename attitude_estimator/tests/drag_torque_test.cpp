// The on-board aerodynamic torque (drag_torque.hpp) against closed forms worked by hand for the bundled 3U
// (docs/design.md, "The spacecraft": 0.1 × 0.1 × 0.34 m, centre of mass (4, −3, −12) mm from the centre,
// C_D 2.2) at the table's 400 km density (3.725e-12 kg/m³, Vallado 2013 table 8-4) and 7600 m/s, and its
// derivative by the wind against central differences of the torque.
#include <cmath>

#include "attitude_estimator/drag_torque.hpp"
#include "test_support.hpp"

namespace attitude_estimator::test {
namespace {

template <class T>
class EstimatorCoreDragTorque : public ::testing::Test {};
TYPED_TEST_SUITE(EstimatorCoreDragTorque, Scalars, ScalarName);

template <class T>
DragGeometry<T> three_u() {
    DragGeometry<T> g;
    g.size = {T(0.1), T(0.1), T(0.34)};
    g.centre_of_mass = {T(0.004), T(-0.003), T(-0.012)};
    g.drag_coefficient = T(2.2);
    return g;
}

constexpr double kDensity = 3.725e-12;  // kg/m³
constexpr double kSpeed = 7600.0;       // m/s

TYPED_TEST(EstimatorCoreDragTorque, OneFaceInTheWindMatchesTheFlatPlateByHand) {
    using T = TypeParam;
    // Wind along +x: only the +x face (0.1 × 0.34 = 0.034 m²) meets it, its centroid at (0.05 − 0.004,
    // 0.003, 0.012) m from the centre of mass. F = −½ ρ C_D A V² e_x = −0.5 · 3.725e-12 · 2.2 · 0.034 · 7600²
    // = −8.0468e-6 N e_x and c × e_x = (0, c_z, −c_y), so τ = c × F = −|F| (0, 0.012, −0.003)
    // = (0, −9.6562e-8, 2.4140e-8) N m.
    const T torque_y = T(-9.6562e-8), torque_z = T(2.4140e-8);
    const Vec3<T> tau = drag_torque(three_u<T>(), T(kDensity), Vec3<T>{T(kSpeed), T(0), T(0)});
    EXPECT_NEAR(tau[0], T(0), T(1e-15));
    EXPECT_NEAR(tau[1], torque_y, T(2e-12));
    EXPECT_NEAR(tau[2], torque_z, T(2e-12));
    // The wind along −x meets the −x face: centroid (−0.05 − 0.004, 0.003, 0.012), F = +|F| e_x,
    // τ = |F| (0, 0.012, −0.003): the same torque with the opposite sign (the x offset does not enter).
    const Vec3<T> back = drag_torque(three_u<T>(), T(kDensity), Vec3<T>{T(-kSpeed), T(0), T(0)});
    EXPECT_NEAR(back[1], -torque_y, T(2e-12));
    EXPECT_NEAR(back[2], -torque_z, T(2e-12));
    // Along +z the end face (0.01 m²): |F| = 2.3667e-6 N, c = (−0.004, 0.003, 0.17 + 0.012),
    // c × e_z = (c_y, −c_x, 0): τ = −|F| (0.003, 0.004, 0) = (−7.100e-9, −9.467e-9, 0) N m.
    const Vec3<T> end = drag_torque(three_u<T>(), T(kDensity), Vec3<T>{T(0), T(0), T(kSpeed)});
    EXPECT_NEAR(end[0], T(-7.100e-9), T(2e-12));
    EXPECT_NEAR(end[1], T(-9.467e-9), T(2e-12));
    EXPECT_NEAR(end[2], T(0), T(1e-15));
}

TYPED_TEST(EstimatorCoreDragTorque, ObliqueWindAddsTheFacesAndACentredBoxFeelsNone) {
    using T = TypeParam;
    // Wind (1, 1, 0)/√2: the +x and +y faces each meet it at cos 1/√2, each force −q A cos v̂ with
    // q = ½ ρ C_D V² = 2.3667e-4 N/m² and A = 0.034 m²: |F_k| = 5.6899e-6 N along −v̂ = −(1, 1, 0)/√2.
    // The two centroids, (0.046, 0.003, 0.012) and (−0.004, 0.053, 0.012) m from the centre of mass, sum to
    // (0.042, 0.056, 0.024), so τ = (c_x + c_y) × F = −|F_k| (0.042, 0.056, 0.024) × (1, 1, 0)/√2
    // = −|F_k|/√2 (−0.024, 0.024, −0.014) = (9.6562e-8, −9.6562e-8, 5.6328e-8) N m.
    const T s = T(kSpeed / std::sqrt(2.0));
    const Vec3<T> tau = drag_torque(three_u<T>(), T(kDensity), Vec3<T>{s, s, T(0)});
    EXPECT_NEAR(tau[0], T(9.6562e-8), T(3e-12));
    EXPECT_NEAR(tau[1], T(-9.6562e-8), T(3e-12));
    EXPECT_NEAR(tau[2], T(5.6328e-8), T(3e-12));
    // With the centre of mass at the centre every wind leaves the box without torque (disturbance_torques.hpp).
    DragGeometry<T> centred = three_u<T>();
    centred.centre_of_mass = {};
    const Vec3<T> none = drag_torque(centred, T(kDensity), Vec3<T>{T(3000), T(-5000), T(4000)});
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(none[static_cast<std::size_t>(i)], T(0), T(1e-14));
    // No geometry (the default), no air, no wind: no torque.
    const Vec3<T> off = drag_torque(DragGeometry<T>{}, T(kDensity), Vec3<T>{s, s, T(0)});
    EXPECT_EQ(off[0], T(0));
    EXPECT_EQ(drag_torque(three_u<T>(), T(0), Vec3<T>{s, s, T(0)})[1], T(0));
    EXPECT_EQ(drag_torque(three_u<T>(), T(kDensity), Vec3<T>{})[2], T(0));
}

TYPED_TEST(EstimatorCoreDragTorque, DerivativeByTheWindMatchesCentralDifferences) {
    using T = TypeParam;
    Random rng(7);
    for (int trial = 0; trial < 20; ++trial) {
        const Eigen::Vector3d v = kSpeed * rng.unit();
        Matrix3RowMajor<T> d{};
        (void)drag_torque(three_u<T>(), T(kDensity), to_vec<T>(v), &d);
        const double step = 1.0;  // m/s: the torque is smooth away from a face edge-on (none within 1 m/s here)
        for (int j = 0; j < 3; ++j) {
            Eigen::Vector3d plus = v, minus = v;
            plus(j) += step;
            minus(j) -= step;
            const Vec3<double> tp = drag_torque(three_u<double>(), kDensity, to_vec<double>(plus));
            const Vec3<double> tm = drag_torque(three_u<double>(), kDensity, to_vec<double>(minus));
            for (int i = 0; i < 3; ++i) {
                const double numeric = (tp[static_cast<std::size_t>(i)] - tm[static_cast<std::size_t>(i)]) / (2 * step);
                EXPECT_NEAR(static_cast<double>(d[static_cast<std::size_t>(3 * i + j)]), numeric, tol<T>(1e-15, 1e-16))
                    << "trial " << trial << " (" << i << ", " << j << ")";
            }
        }
    }
}

}  // namespace
}  // namespace attitude_estimator::test
