// MeanAngularRate (004 eq. 4–5) on a torque-free tumble of an asymmetric box (not a pure spin).
// Truth: Euler's equations J ω̇ = −ω × Jω with the quaternion kinematics q̇ (scalar-last, A(q) inertial to
// body: Q̇ = ½(w ω − ω × Q), ẇ = −½ ω·Q), integrated here by classical RK4 at h = 0.05 s, independent of
// the code under test. Aims of issue 8: from the TRUE attitudes, eq. 4 recovers the mean |ω| within 10 %
// at one sample a minute (Aist's telemetry) and within 2 % at one sample every 2 s (004's recommendation).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "attitude_estimator/angular_rate.hpp"
#include "attitude_estimator/attitude_matrix.hpp"
#include "attitude_estimator/vec3_math.hpp"
#include "ordered_draws.hpp"

namespace attitude_estimator::test {
namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr double kH = 0.05;  // s, integration step and finest sampling

struct Tumble {
    std::vector<Quaternion<double>> q;                        // at t = i h
    std::vector<double> rate;                                 // |ω(t_i)|
    std::vector<Eigen::Vector3d> omega;                       // ω(t_i), body axes
    double mean_rate(std::size_t i0, std::size_t i1) const {  // time average of |ω| over [t_i0, t_i1], trapezoid
        double s = 0.0;
        for (std::size_t i = i0; i < i1; ++i) s += 0.5 * (rate[i] + rate[i + 1]);
        return s / static_cast<double>(i1 - i0);
    }
};

// Aist-like inertia: a 53 kg box of Aist's size class, principal moments about 2.9 … 3.6 kg m² with
// products of inertia (environment's RigidBodyParams default). Nearly cubic: ω stays within a few degrees
// of the fixed angular momentum, so the tumble is close to a rotation about one inertial axis.
Eigen::Matrix3d aist_inertia() {
    Eigen::Matrix3d j;
    j << 3.2, 0.05, -0.02, 0.05, 2.9, 0.03, -0.02, 0.03, 3.6;
    return j;
}
// A strongly asymmetric body (principal moments 1 : 2 : 3, a slab): ω nutates far from the angular
// momentum and the body tumbles in earnest (the harder case for a chord-over-time rate).
Eigen::Matrix3d slab_inertia() {
    return Eigen::Vector3d(1.0, 2.0, 3.0).asDiagonal();
}

// Initial rate of magnitude w0 along dir (chosen away from every principal axis).
Tumble simulate(double w0, const Eigen::Vector3d& dir, double duration, const Eigen::Matrix3d& j = aist_inertia()) {
    const Eigen::Matrix3d j_inv = j.inverse();
    using State = Eigen::Matrix<double, 7, 1>;  // x, y, z, w, ωx, ωy, ωz
    auto f = [&](const State& s) {
        const Eigen::Vector3d qv = s.segment<3>(0), w = s.segment<3>(4);
        const double qw = s[3];
        State d;
        d.segment<3>(0) = 0.5 * (qw * w - w.cross(qv));
        d[3] = -0.5 * w.dot(qv);
        d.segment<3>(4) = j_inv * (-w.cross(j * w));
        return d;
    };
    State s;
    s << 0.1, -0.2, 0.3, 0.927361849549570, (w0 * dir.normalized());
    s.head<4>().normalize();
    const auto steps = static_cast<std::size_t>(std::llround(duration / kH));
    Tumble tb;
    tb.q.reserve(steps + 1);
    tb.rate.reserve(steps + 1);
    for (std::size_t i = 0;; ++i) {
        tb.q.push_back({s[0], s[1], s[2], s[3]});
        tb.rate.push_back(s.segment<3>(4).norm());
        tb.omega.push_back(s.segment<3>(4));
        if (i == steps) break;
        const State k1 = f(s), k2 = f(s + 0.5 * kH * k1), k3 = f(s + 0.5 * kH * k2), k4 = f(s + kH * k3);
        s += kH / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        s.head<4>().normalize();
    }
    return tb;
}

const Eigen::Vector3d kDirs[] = {{1.0, -0.8, 1.0}, {0.2, 1.0, -0.4}, {-0.6, 0.3, 0.9}};
constexpr double kRatesDeg[] = {0.3, 0.94, 1.3};  // °/s, the range of 004 §4

// A random small rotation applied to q: rotation vector with per-axis sigma (rms angle sigma √3).
Quaternion<double> perturb(const Quaternion<double>& q, double sigma, std::mt19937_64& gen) {
    std::normal_distribution<double> n(0.0, sigma);
    const Eigen::Vector3d e = ordered_draws::vector3(n, gen);
    const Eigen::Quaterniond dq(Eigen::AngleAxisd(e.norm(), e.norm() > 0 ? e.normalized() : Eigen::Vector3d::UnitX()));
    // Compose in the Hamilton product on the raw components (the metric is convention-blind).
    const Eigen::Quaterniond qe(q.w, q.x, q.y, q.z);  // Eigen's constructor order is (w, x, y, z)
    const Eigen::Quaterniond r = dq * qe;
    return {r.x(), r.y(), r.z(), r.w()};
}

struct Stats {
    double worst = 0.0;  // worst |relative error| of a window
    double mean = 0.0;   // mean relative error (bias) over windows
};

// Eq. 4 every `stride` steps, averaged over `window` increments, compared with the true mean |ω| over the
// same span, for consecutive non-overlapping windows along the whole run.
Stats compare(const Tumble& tb, std::size_t stride, std::size_t window, RateMeasure measure, double noise_sigma,
              std::uint64_t seed) {
    std::mt19937_64 gen(seed);
    MeanAngularRateConfig<double> cfg;
    cfg.measure = measure;
    cfg.window = window;
    const Vec3<double> sun_eci{0.6, -0.48, 0.64};
    Stats st;
    int windows = 0;
    for (std::size_t i0 = 0; i0 + stride * window < tb.q.size(); i0 += stride * window) {
        MeanAngularRate<double> est(cfg);
        for (std::size_t k = 0; k <= window; ++k) {
            const std::size_t i = i0 + k * stride;
            const double t = static_cast<double>(i) * kH;
            const Quaternion<double> q = noise_sigma > 0 ? perturb(tb.q[i], noise_sigma, gen) : tb.q[i];
            if (measure == RateMeasure::attitude_angle)
                est.push(t, q);
            else
                est.push(t, multiply(attitude_matrix(q), sun_eci));
        }
        const MeanRate<double> r = est.result();
        EXPECT_TRUE(r.valid);
        EXPECT_NEAR(r.window_seconds, static_cast<double>(stride * window) * kH, 1e-9);
        const double truth = tb.mean_rate(i0, i0 + stride * window);
        const double err = r.rate / truth - 1.0;
        st.worst = std::max(st.worst, std::fabs(err));
        st.mean += err;
        ++windows;
    }
    st.mean /= windows;
    return st;
}

TEST(AngularRate, RelativeRotationAngleOfKnownRotations) {
    for (double angle : {1e-6, 0.01, 0.5, 1.0, 2.0, 3.0}) {
        const Eigen::Quaterniond a(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
        const Eigen::Quaterniond b = Eigen::AngleAxisd(angle, Eigen::Vector3d(-1, 0.5, 2).normalized()) * a;
        const Quaternion<double> qa{a.x(), a.y(), a.z(), a.w()}, qb{b.x(), b.y(), b.z(), b.w()};
        EXPECT_NEAR(relative_rotation_angle(qa, qb), angle, 1e-12 + 1e-12 * angle);
        EXPECT_NEAR(relative_rotation_angle(qb, qa), angle, 1e-12 + 1e-12 * angle);
        const Quaternion<double> nb{-2 * qb.x, -2 * qb.y, -2 * qb.z, -2 * qb.w};  // −2 q: same attitude
        EXPECT_NEAR(relative_rotation_angle(qa, nb), angle, 1e-12 + 1e-12 * angle);
        const Quaternion<float> fa{float(qa.x), float(qa.y), float(qa.z), float(qa.w)};
        const Quaternion<float> fb{float(qb.x), float(qb.y), float(qb.z), float(qb.w)};
        EXPECT_NEAR(relative_rotation_angle(fa, fb), angle, 1e-6 + 1e-6 * angle);
    }
    EXPECT_EQ(relative_rotation_angle(Quaternion<double>{0, 0, 0, 0}, Quaternion<double>{}), 0.0);
}

TEST(AngularRate, VectorAngles) {
    EXPECT_NEAR(vector_angle(Vec3<double>{1, 0, 0}, Vec3<double>{0, 2, 0}), M_PI / 2, 1e-15);
    EXPECT_NEAR(vector_angle(Vec3<double>{1, 0, 0}, Vec3<double>{std::cos(1e-7), std::sin(1e-7), 0}), 1e-7, 1e-20);
    // Direction angles: (1,0,0) → (0,1,0): K = π/2, L = −π/2, M = 0 → π/√2 (more than the 90° turned).
    EXPECT_NEAR(direction_angle_distance(Vec3<double>{1, 0, 0}, Vec3<double>{0, 1, 0}), M_PI / std::sqrt(2.0), 1e-15);
    EXPECT_EQ(direction_angle_distance(Vec3<double>{0, 0, 0}, Vec3<double>{0, 1, 0}), 0.0);
}

TEST(AngularRate, EqFourAndFiveBookkeeping) {
    // Constant rate 0.02 rad/s about z, samples every 1 s, window 3: eq. 5 mean of eq. 4 increments.
    MeanAngularRate<double> est({.measure = RateMeasure::attitude_angle, .window = 3});
    auto q_at = [](double t) { return Quaternion<double>{0, 0, std::sin(0.01 * t), std::cos(0.01 * t)}; };
    EXPECT_FALSE(est.push(0.0, q_at(0.0)));
    EXPECT_TRUE(est.push(1.0, q_at(1.0)));
    EXPECT_FALSE(est.result().valid);
    EXPECT_EQ(est.result().increments, 1u);
    EXPECT_FALSE(est.push(1.0, q_at(1.0)));  // same time: ignored
    EXPECT_TRUE(est.push(2.0, q_at(2.0)));
    EXPECT_TRUE(est.push(4.0, q_at(4.0)));
    const MeanRate<double> r = est.result();
    EXPECT_TRUE(r.valid);
    EXPECT_NEAR(r.rate, 0.02, 1e-14);
    EXPECT_NEAR(r.window_seconds, 4.0, 1e-14);
    // Invalid sample: the chain breaks, the window keeps its increments.
    EXPECT_FALSE(est.push(5.0, q_at(5.0), false));
    EXPECT_FALSE(est.push(6.0, q_at(6.0)));
    EXPECT_TRUE(est.push(7.0, q_at(7.0)));
    EXPECT_NEAR(est.result().window_seconds, 4.0, 1e-14);  // 1 + 2 + 1 (the 1-s increment replaced one of 1 s)
    // Wrong kind of input is ignored.
    EXPECT_FALSE(est.push(8.0, Vec3<double>{1, 0, 0}));
    est.reset();
    EXPECT_EQ(est.result().increments, 0u);
}

TEST(AngularRate, AngleTripleIsEqFourAsPrinted) {
    // Two ε triples 60 s apart: |Δε| = sqrt(0.3² + 0.4² + 1.2²) = 1.3 rad → 1.3/60 rad/s.
    MeanAngularRate<double> est({.measure = RateMeasure::angle_triple});
    EXPECT_FALSE(est.push(0.0, Vec3<double>{0.1, 0.2, 0.3}));
    EXPECT_TRUE(est.push(60.0, Vec3<double>{0.4, -0.2, 1.5}));
    EXPECT_TRUE(est.result().valid);
    EXPECT_NEAR(est.result().rate, 1.3 / 60.0, 1e-15);
    EXPECT_NEAR(angle_triple_distance(Vec3<float>{0, 0, 0}, Vec3<float>{3, 4, 0}), 5.0f, 1e-6f);
    EXPECT_EQ(angle_triple_distance(Vec3<double>{NAN, 0, 0}, Vec3<double>{3, 4, 0}), 0.0);
}

TEST(AngularRate, DecimationAndGaps) {
    MeanAngularRate<float> est(
        {.measure = RateMeasure::vector_angle, .window = 2, .min_interval = 2.0f, .max_interval = 10.0f});
    auto v = [](float t) { return Vec3<float>{std::cos(0.1f * t), std::sin(0.1f * t), 0.0f}; };
    int increments = 0;
    for (int i = 0; i <= 80; ++i) increments += est.push(0.05f * static_cast<float>(i), v(0.05f * i)) ? 1 : 0;
    EXPECT_EQ(increments, 2);  // t = 2, 4 (the 20 Hz stream decimated to 2 s)
    EXPECT_NEAR(est.result().rate, 0.1f, 1e-4f);
    EXPECT_FALSE(est.push(30.0f, v(30.0f)));  // 26 s gap > max_interval: new chain
    EXPECT_TRUE(est.push(32.0f, v(32.0f)));
}

TEST(AngularRate, TumbleFromTrueAttitudes) {
    // One hour of tumble per case; windows of 10 increments (10 min at 1/min, 20 s at 1/2 s).
    for (double w_deg : kRatesDeg) {
        for (const auto& dir : kDirs) {
            for (const bool slab : {false, true}) {
                const Tumble tb = simulate(w_deg * kDeg, dir, 3600.0, slab ? slab_inertia() : aist_inertia());
                const Stats minute = compare(tb, 1200, 10, RateMeasure::attitude_angle, 0.0, 1);
                const Stats minute1 = compare(tb, 1200, 1, RateMeasure::attitude_angle, 0.0, 1);
                const Stats two_s = compare(tb, 40, 10, RateMeasure::attitude_angle, 0.0, 1);
                EXPECT_LT(minute.worst, 0.10) << w_deg << " deg/s";
                EXPECT_LT(minute1.worst, 0.10) << w_deg << " deg/s";
                EXPECT_LT(two_s.worst, 0.02) << w_deg << " deg/s";
                // How much |ω| itself varies over the run (a tumble, not a constant spin).
                const auto [lo, hi] = std::minmax_element(tb.rate.begin(), tb.rate.end());
                std::printf(
                    "[rates] tumble %s |w0| %.2f deg/s dir (%.1f,%.1f,%.1f), |w| %.3f..%.3f deg/s: eq.4 true "
                    "attitudes, worst rel err: 60 s x10 %.4f, 60 s x1 %.4f, 2 s x10 %.5f\n",
                    slab ? "slab" : "aist", w_deg, dir.x(), dir.y(), dir.z(), *lo / kDeg, *hi / kDeg, minute.worst,
                    minute1.worst, two_s.worst);
            }
        }
    }
}

TEST(AngularRate, TumbleFromNoisyAttitudes) {
    // Estimated attitudes: each true attitude turned by a random rotation of rms angle 0.5° (per-axis
    // sigma 0.5°/√3). The increment then carries the difference of two errors (rms 0.71°): the rate gets
    // noise/Δt, mostly in quadrature with the true step, hence a positive bias that grows as |ω|Δt shrinks.
    const double sigma = 0.5 * kDeg / std::sqrt(3.0);
    for (double w_deg : kRatesDeg) {
        const Tumble tb = simulate(w_deg * kDeg, kDirs[0], 3600.0);
        const Stats minute = compare(tb, 1200, 10, RateMeasure::attitude_angle, sigma, 11);
        const Stats two_s = compare(tb, 40, 10, RateMeasure::attitude_angle, sigma, 12);
        const Stats fast = compare(tb, 1, 10, RateMeasure::attitude_angle, sigma, 13);
        EXPECT_LT(minute.worst, 0.10) << w_deg;
        // Small-noise model of the bias: E|δ + Δe| ≈ δ + E|Δe⊥|²/(2δ) with Δe⊥ the two components of the error
        // difference across the step δ = |ω|Δt (variance 2σ² each): relative bias 2σ²/δ². Holds when δ ≫ σ.
        const double delta2 = w_deg * kDeg * 40 * kH;
        if (delta2 > 5.0 * sigma) {
            const double model = 2.0 * sigma * sigma / (delta2 * delta2);
            EXPECT_NEAR(two_s.mean, model, 0.3 * model) << w_deg;
        }
        // At 20 Hz the rate is the noise: E|Δe|/Δt with Δe the difference of two isotropic errors
        // (chi, 3 dof, per-axis sigma √2): mean 2√(2/π) · √2 sigma = 0.65° → 13 °/s at Δt = 0.05 s.
        const double noise_rate = 2.0 * std::sqrt(2.0 / M_PI) * std::sqrt(2.0) * sigma / kH;
        const double truth = tb.mean_rate(0, tb.rate.size() - 1);
        EXPECT_NEAR((1.0 + fast.mean) * truth, noise_rate, 0.15 * noise_rate) << w_deg;
        std::printf(
            "[rates] noisy 0.5 deg rms, |w0| %.2f deg/s: bias (mean rel err) 60 s %+.4f (worst %.4f), "
            "2 s %+.4f (worst %.4f), 0.05 s %+.1f (rate %.2f deg/s, noise/dt model %.2f deg/s)\n",
            w_deg, minute.mean, minute.worst, two_s.mean, two_s.worst, fast.mean, (1.0 + fast.mean) * truth / kDeg,
            noise_rate / kDeg);
    }
}

TEST(AngularRate, TumbleFromOneVectorUnderestimates) {
    // A single vector (the sun, fixed in inertial space) sees only |ω × s|: eq. 4 on vector angles measures
    // that, not |ω|. The direction-angle form of eq. 5 overweights (K, L, M each ≥ the component's turn).
    for (double w_deg : kRatesDeg) {
        const Tumble tb = simulate(w_deg * kDeg, kDirs[0], 3600.0);
        const Stats va2 = compare(tb, 40, 10, RateMeasure::vector_angle, 0.0, 1);
        const Stats da2 = compare(tb, 40, 10, RateMeasure::direction_angles, 0.0, 1);
        const Stats va60 = compare(tb, 1200, 10, RateMeasure::vector_angle, 0.0, 1);
        const Stats da60 = compare(tb, 1200, 10, RateMeasure::direction_angles, 0.0, 1);
        EXPECT_LT(va2.mean, 0.0);  // never more than |ω|: |ω × s| ≤ |ω|
        // What it does measure: the time mean of |ω × s| (the rate component perpendicular to the sun), here
        // compared with the mean |ω| as sin β, β the angle between ω and the sun.
        const Vec3<double> sun_eci{0.6, -0.48, 0.64};
        double perp = 0.0, full = 0.0;
        for (std::size_t i = 0; i < tb.q.size(); ++i) {
            const Vec3<double> sb = multiply(attitude_matrix(tb.q[i]), sun_eci);
            const Eigen::Vector3d s(sb[0], sb[1], sb[2]);
            perp += tb.omega[i].cross(s.normalized()).norm();
            full += tb.rate[i];
        }
        const double sin_beta = perp / full;
        EXPECT_NEAR(1.0 + va2.mean, sin_beta, 0.02);
        std::printf(
            "[rates] one vector, |w0| %.2f deg/s: mean |w x s|/|w| %.3f; mean rel err vector_angle 2 s %+.3f "
            "60 s %+.3f; direction_angles 2 s %+.3f 60 s %+.3f\n",
            w_deg, sin_beta, va2.mean, va60.mean, da2.mean, da60.mean);
    }
}

}  // namespace
}  // namespace attitude_estimator::test
