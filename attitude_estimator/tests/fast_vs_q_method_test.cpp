// The flight solver against the reference Q-method on 100,000 random problems per scalar type, in four
// families: noise-free, noisy, near-180° rotations, nearly parallel observations. Both minimize the same
// L(A) (000 eq. 8), so they must agree on the attitude (up to the problem's own conditioning) and on the
// loss. The worst differences are printed for the report.
#include "attitude_estimator/fast_solver.hpp"
#include "attitude_estimator/q_method.hpp"

#include "test_support.hpp"

namespace attitude_estimator::test {
namespace {

enum class Family { noise_free, noisy, near_half_turn, nearly_parallel };

struct Worst {
    double angle = 0.0;        // attitude angle between the fast and the Q-method solution (same scalar)
    double scaled = 0.0;       // the same × sin²(separation of the first pair): the problem's conditioning
    double fast_vs_ref = 0.0;  // fast (scalar T) against the Q-method in double on the same numbers
    double q_vs_ref = 0.0;     // Q-method (scalar T) against the Q-method in double
    double fast_excess = 0.0;  // L(A_fast) − L(A_ref), both evaluated in double (000 eq. 8)
    double q_excess = 0.0;     // L(A_q) − L(A_ref)
};

// L(A) = ½ Σ a_i |w_i − A v_i|² in double, weights normalized, vectors normalized (000 eq. 8), written
// out here independently of the core.
template <class T>
double loss_double(const ObservationSet<T>& set, const Eigen::Matrix3d& a) {
    double sum_a = 0.0, l = 0.0;
    for (std::size_t i = 0; i < set.count; ++i) sum_a += static_cast<double>(set.items[i].weight);
    for (std::size_t i = 0; i < set.count; ++i) {
        const auto& o = set.items[i];
        const Eigen::Vector3d v = Eigen::Vector3d(o.ref[0], o.ref[1], o.ref[2]).normalized();
        const Eigen::Vector3d w = Eigen::Vector3d(o.obs[0], o.obs[1], o.obs[2]).normalized();
        l += static_cast<double>(o.weight) / sum_a * (w - a * v).squaredNorm();
    }
    return 0.5 * l;
}

template <class T>
Worst run_family(Family family, int count, std::uint64_t seed) {
    Random rng(seed);
    Worst worst;
    WahbaOptions<T> options;
    options.min_separation_sin = T(0);  // solve and compare everything, including nearly parallel pairs
    for (int trial = 0; trial < count; ++trial) {
        const int n = 2 + trial % 5;
        double angle = rng.uniform(0.0, M_PI);
        double noise = 0.0;
        double separation_deg = 20.0;  // smallest angle between the first two reference directions
        switch (family) {
            case Family::noise_free:
                break;
            case Family::noisy:
                noise = std::pow(10.0, rng.uniform(-4.0, -1.3));
                break;  // 1e-4 … 0.05 rad
            case Family::near_half_turn:
                angle = trial % 10 == 0 ? M_PI : M_PI - std::pow(10.0, rng.uniform(-8.0, -2.0));
                noise = trial % 2 == 0 ? 0.0 : 1e-3;
                break;
            case Family::nearly_parallel:
                separation_deg = rng.uniform(0.5, 5.0);
                noise = 1e-4;
                break;
        }
        const Eigen::Matrix3d a_true = rng.rotation(angle);
        const Eigen::Vector3d v0 = rng.unit();
        double sep_sin = 1.0;
        ObservationSet<T> set;
        for (int i = 0; i < n; ++i) {
            Eigen::Vector3d v;
            if (i == 0) {
                v = v0;
            } else if (family == Family::nearly_parallel) {
                // Every direction within separation_deg of v0: the whole set is nearly parallel.
                const Eigen::Vector3d perp = v0.cross(rng.unit()).normalized();
                const double s = separation_deg * M_PI / 180.0 * (i == 1 ? 1.0 : rng.uniform(0.2, 1.0));
                v = (std::cos(s) * v0 + std::sin(s) * perp).normalized();
            } else {
                do {
                    v = rng.unit();
                } while (i == 1 && v.cross(v0).norm() < std::sin(separation_deg * M_PI / 180.0));
            }
            if (i == 1) sep_sin = v.cross(v0).norm();
            Eigen::Vector3d w = a_true * v;
            if (noise > 0.0) w = (w + noise * rng.gauss3()).normalized();
            set.add(to_vec<T>(v), to_vec<T>(w), static_cast<T>(rng.uniform(0.1, 1.0)));
        }
        const auto q = solve_q_method(set, options);
        const auto f = solve_fast(set, options);
        ObservationSet<double> set_d;  // the same rounded numbers, solved in double
        for (std::size_t i = 0; i < set.count; ++i) {
            const auto& o = set.items[i];
            set_d.add({o.ref[0], o.ref[1], o.ref[2]}, {o.obs[0], o.obs[1], o.obs[2]}, o.weight);
        }
        const auto r = solve_q_method(set_d, WahbaOptions<double>{0.0});
        EXPECT_TRUE(q.valid && f.valid && r.valid);
        const Eigen::Matrix3d aq = to_eigen(q.a), af = to_eigen(f.a), ar = to_eigen(r.a);
        const double d = attitude_angle(aq, af);
        worst.angle = std::max(worst.angle, d);
        worst.scaled = std::max(worst.scaled, d * sep_sin * sep_sin);
        worst.fast_vs_ref = std::max(worst.fast_vs_ref, attitude_angle(af, ar));
        worst.q_vs_ref = std::max(worst.q_vs_ref, attitude_angle(aq, ar));
        const double lr = loss_double(set, ar);
        worst.fast_excess = std::max(worst.fast_excess, loss_double(set, af) - lr);
        worst.q_excess = std::max(worst.q_excess, loss_double(set, aq) - lr);
    }
    return worst;
}

template <class T>
class EstimatorCoreFastVsQMethod : public ::testing::Test {
protected:
    static void report(const char* family, const Worst& w) {
        std::printf(
            "[%s] %-15s 25000 problems: fast vs qmethod worst %.3g rad (x sin^2 sep: %.3g); vs double "
            "qmethod: fast %.3g rad, qmethod %.3g rad; loss excess: fast %.3g, qmethod %.3g\n",
            std::is_same_v<T, float> ? "float" : "double", family, w.angle, w.scaled, w.fast_vs_ref, w.q_vs_ref,
            w.fast_excess, w.q_excess);
    }
};
TYPED_TEST_SUITE(EstimatorCoreFastVsQMethod, Scalars, ScalarName);

// Tolerances: double agrees to rounding of well-posed problems (first pair >= 20° apart); float, the DSP's
// only type, to a few 1e-5 rad (a few arcseconds, the float Q-method's own error), far below the sensors'
// errors. The loss excess over the double-precision optimum bounds how far from optimal the fast solution
// is, whatever the direction of its error.
TYPED_TEST(EstimatorCoreFastVsQMethod, NoiseFree) {
    const Worst w = run_family<TypeParam>(Family::noise_free, 25000, 101);
    this->report("noise-free", w);
    EXPECT_LT(w.angle, tol<TypeParam>(5e-5, 1e-11));
    EXPECT_LT(w.fast_vs_ref, tol<TypeParam>(1e-5, 1e-11));
    EXPECT_LT(w.fast_excess, tol<TypeParam>(1e-8, 1e-14));
}

TYPED_TEST(EstimatorCoreFastVsQMethod, Noisy) {
    const Worst w = run_family<TypeParam>(Family::noisy, 25000, 102);
    this->report("noisy", w);
    EXPECT_LT(w.angle, tol<TypeParam>(5e-5, 1e-11));
    EXPECT_LT(w.fast_vs_ref, tol<TypeParam>(1e-5, 1e-11));
    EXPECT_LT(w.fast_excess, tol<TypeParam>(1e-8, 1e-14));
}

TYPED_TEST(EstimatorCoreFastVsQMethod, NearHalfTurn) {
    const Worst w = run_family<TypeParam>(Family::near_half_turn, 25000, 103);
    this->report("near-180deg", w);
    EXPECT_LT(w.angle, tol<TypeParam>(5e-5, 1e-11));
    EXPECT_LT(w.fast_vs_ref, tol<TypeParam>(1e-5, 1e-11));
    EXPECT_LT(w.fast_excess, tol<TypeParam>(1e-8, 1e-14));
}

TYPED_TEST(EstimatorCoreFastVsQMethod, NearlyParallel) {
    // 0.5°…5° between the directions: the attitude about them is determined only to ~ε/sin²(sep), for
    // both solvers; the comparison is scaled by sin²(sep) accordingly.
    const Worst w = run_family<TypeParam>(Family::nearly_parallel, 25000, 104);
    this->report("nearly-parallel", w);
    EXPECT_LT(w.scaled, tol<TypeParam>(5e-5, 1e-11));
    EXPECT_LT(w.fast_excess, tol<TypeParam>(1e-8, 1e-14));
}

}  // namespace
}  // namespace attitude_estimator::test
