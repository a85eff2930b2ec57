// Table 1 of seed 001 (Rocha et al., "Evaluation of sun position using the photovoltaic generation"),
// all digits as printed there: for each case the Q-method on the printed v1, w1, v2, w2 (normalized, equal
// weights) must give the printed theoretical (MATLAB) attitude matrix to 1e-4. The table's matrices are in
// the design's convention w = A v (its first column is A applied to v1 = x). The fast solver must too.
#include "attitude_estimator/fast_solver.hpp"
#include "attitude_estimator/q_method.hpp"

#include "test_support.hpp"

namespace attitude_estimator::test {
namespace {

struct Table1Case {
    const char* name;
    double v1[3], w1[3], v2[3], w2[3];
    double a[9];  // theoretical attitude matrix, row-major
};

const Table1Case kTable1[] = {
    {"aligned", {0, 1, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 1}, {1, 0, 0, 0, 1, 0, 0, 0, 1}},
    {"w1 inclined 45 deg",
     {1, 0, 0},
     {1, 1, 0},
     {0, 0, 1},
     {0, 0, 1},
     {0.7071, -0.7071, 0.0000, 0.7071, 0.7071, 0.0000, 0.0000, 0.0000, 1.0000}},
    {"measured vectors",
     {1.0000, 0.0000, 0.0000},
     {0.70523, 0.70884, -0.01353},
     {0.0000, 1.0000, 0.0000},
     {-0.00793, 0.00881, 0.99999},
     {0.70522, -0.00338, 0.70897, 0.70894, 0.01337, -0.70513, -0.00709, 0.99990, 0.01183}},
};

template <class T>
class EstimatorCoreTable1 : public ::testing::Test {};
TYPED_TEST_SUITE(EstimatorCoreTable1, Scalars, ScalarName);

template <class T>
void check_table1(SolverKind kind) {
    for (const Table1Case& c : kTable1) {
        ObservationSet<T> set;
        set.add({T(c.v1[0]), T(c.v1[1]), T(c.v1[2])}, {T(c.w1[0]), T(c.w1[1]), T(c.w1[2])}, T(0.5));
        set.add({T(c.v2[0]), T(c.v2[1]), T(c.v2[2])}, {T(c.w2[0]), T(c.w2[1]), T(c.w2[2])}, T(0.5));
        const WahbaSolution<T> s = solve_wahba(set, kind);
        ASSERT_TRUE(s.valid) << c.name;
        double worst = 0.0;
        for (int i = 0; i < 9; ++i) {
            EXPECT_NEAR(s.a[i], c.a[i], 1e-4) << c.name << " element " << i;
            worst = std::max(worst, std::fabs(static_cast<double>(s.a[i]) - c.a[i]));
        }
        std::printf("[%s %s] Table 1 '%s': worst |A - A_table| = %.2g, loss %.3g\n",
                    std::is_same_v<T, float> ? "float" : "double", kind == SolverKind::qmethod ? "qmethod" : "fast",
                    c.name, worst, static_cast<double>(s.loss));
    }
}

TYPED_TEST(EstimatorCoreTable1, QMethodReproducesTheoreticalMatrices) {
    check_table1<TypeParam>(SolverKind::qmethod);
}
TYPED_TEST(EstimatorCoreTable1, FastSolverReproducesTheoreticalMatrices) {
    check_table1<TypeParam>(SolverKind::fast);
}

TYPED_TEST(EstimatorCoreTable1, FortyFiveDegreeCaseLossByHand) {
    using T = TypeParam;
    // w1 ⟂ w2 and v1 ⟂ v2 with the same angle: an exact fit exists, so L = 0 (000 eq. 8).
    ObservationSet<T> set;
    set.add({1, 0, 0}, {1, 1, 0}, T(1));
    set.add({0, 0, 1}, {0, 0, 1}, T(1));
    EXPECT_NEAR(solve_q_method(set).loss, 0.0, tol<T>(1e-6, 1e-14));
}

}  // namespace
}  // namespace attitude_estimator::test
