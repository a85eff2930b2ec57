// attitude_estimator.fmu's block driven through the runtime's C++ layer (fmu::ModelRunner, fmu::CsSolver),
// without the FMI C API: sample timing and hold, attitude recovery from sensor signals built from a known
// attitude, Table 1 of seed 001, eclipse, solver selection and a saturated magnetometer.
// Truth comes from Eigen (AngleAxis, Quaterniond), never from the core; bounds are derived in comments.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>

#include "attitude_estimator/estimator_block.hpp"
#include "block_simulation.hpp"
#include "fmu/cs_solver.hpp"
#include "fmu/errors.hpp"
#include "fmu/model_runner.hpp"
#include "test_support.hpp"

namespace attitude_estimator {
namespace {

using test::attitude_angle;
using test::Random;

using test::Simulation;

Eigen::Matrix3d a_est(Simulation& sim) {
    Eigen::Matrix3d m;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) m(r, c) = sim.data().A_est[3 * r + c];
    return m;
}

Eigen::Vector3d vec(const Vec3d& v) {
    return {v[0], v[1], v[2]};
}

// The sensor signals an ideal sensor chain produces at attitude A (w_body = A v_ref):
//   i_sh = i_sc_norm ⊙ (A ŝ_ref)            (000 eq. 5 solved for the currents)
//   v_mag = v_ref + S (A m_ref)             (HMC2003: 2.5 V at zero field, S V/T)
void feed(Simulation& sim, const Eigen::Matrix3d& a, const Eigen::Vector3d& sun_ref, const Eigen::Vector3d& mag_ref) {
    auto& d = sim.data();
    const Eigen::Vector3d s = a * sun_ref.normalized();
    const Eigen::Vector3d b = a * mag_ref;
    for (int k = 0; k < 3; ++k) {
        d.i_sh[k] = d.i_sc_norm[k] * s[k];
        d.v_mag[k] = 2.5 + d.mag_sensitivity * b[k];
        d.sun_ref[k] = sun_ref[k];
        d.mag_ref[k] = mag_ref[k];
    }
    d.v_mag_ref = 2.5;
    sim.inputs_changed();
}

// The quaternion of A in the design's convention, by Eigen: A(q) = (w² − |Q|²)I + 2QQᵀ − 2w[Q×] is the
// transpose of Eigen's rotation matrix of (w, Q), so q is the conjugate of Eigen's quaternion of A; w >= 0.
std::array<double, 4> true_quaternion(const Eigen::Matrix3d& a) {
    const Eigen::Quaterniond e(a);
    const double s = e.w() < 0 ? -1.0 : 1.0;
    return {-s * e.x(), -s * e.y(), -s * e.z(), s * e.w()};
}

double max_abs_diff(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
    return (a - b).cwiseAbs().maxCoeff();
}

// A random test case: attitude, unit sun reference scaled by 3 (the block must normalize), a 40 µT field
// reference, the two references at least 60° from (anti)parallel.
struct Case {
    Eigen::Matrix3d a;
    Eigen::Vector3d sun_ref, mag_ref;
    double separation;  // angle between the references, rad
};
Case random_case(Random& rng) {
    Case c;
    c.a = rng.rotation();
    do {
        c.sun_ref = rng.unit();
        c.mag_ref = rng.unit();
        c.separation = std::acos(std::clamp(c.sun_ref.dot(c.mag_ref), -1.0, 1.0));
    } while (std::fabs(std::cos(c.separation)) > 0.5);
    c.sun_ref *= 3.0;
    c.mag_ref *= 40e-6;
    return c;
}

// ---------------------------------------------------------------------------------------------------
// Timing

Eigen::Matrix3d about_z(double angle) {
    return Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix().transpose();
}

TEST(EstimatorFmuTiming, SamplesExactlyEveryPeriodAndHoldsBetween) {
    Simulation sim;
    auto& d = sim.data();
    d.adc_bits = 0;
    const double t0 = 0.3, period = 0.05, eps = 1e-7;
    const Eigen::Vector3d sun_ref(1, 0, 0), mag_ref(0.6e-5, 3e-5, 1e-5);
    auto angle = [](int k) { return 0.1 * k; };  // the attitude presented for sample k
    feed(sim, about_z(angle(0)), sun_ref, mag_ref);
    sim.start(t0);
    EXPECT_EQ(d.samples, 1);  // the sample at the start time is taken in initialization
    EXPECT_LT(attitude_angle(a_est(sim), about_z(angle(0))), 1e-9);
    for (int k = 1; k <= 40; ++k) {
        const double tk = t0 + k * period;
        EXPECT_DOUBLE_EQ(sim.runner.next_time_event(), tk);
        // Just before t_k: still the previous sample, although the inputs changed half a period ago.
        sim.advance_to(tk - eps);
        ASSERT_EQ(d.samples, k);
        EXPECT_LT(attitude_angle(a_est(sim), about_z(angle(k - 1))), 1e-9) << "k = " << k;
        feed(sim, about_z(angle(k)), sun_ref, mag_ref);
        // Just after t_k: the new sample, of the inputs present at t_k.
        sim.advance_to(tk + eps);
        ASSERT_EQ(d.samples, k + 1);
        EXPECT_LT(attitude_angle(a_est(sim), about_z(angle(k))), 1e-9) << "k = " << k;
        // A distracting input in the middle of the interval changes nothing until t_{k+1}.
        feed(sim, about_z(-1.0), sun_ref, mag_ref);
        sim.advance_to(tk + 0.5 * period);
        EXPECT_EQ(d.samples, k + 1);
        EXPECT_LT(attitude_angle(a_est(sim), about_z(angle(k))), 1e-9) << "k = " << k;
    }
}

TEST(EstimatorFmuTiming, InstantsComeFromTheCountAndNeverDrift) {
    // 2000 samples at 20 Hz from t0 = 0.3 s, one communication step per sample: every instant must be
    // t0 + k·0.05 to the last bit (a running sum of 0.05 would be off by many ulps after 2000 steps).
    Simulation sim;
    const double t0 = 0.3, period = 0.05;
    sim.start(t0);
    double running_sum = t0;
    for (int k = 1; k <= 2000; ++k) {
        const double tk = t0 + k * period;
        ASSERT_EQ(sim.runner.next_time_event(), tk) << "k = " << k;
        sim.advance_to(tk);
        ASSERT_EQ(sim.data().samples, k + 1);
        running_sum += period;
    }
    std::printf("after 2000 samples: t = %.17g, running sum of the period = %.17g\n", t0 + 2000 * period, running_sum);
}

TEST(EstimatorFmuTiming, CommunicationStepsNotAlignedWithSamples) {
    // Samples by t = number of instants t0 + k·P <= t (k >= 0); a step of 13 ms meets most instants
    // inside a step and some exactly at its end.
    Simulation sim;
    const double t0 = 0.0, period = 0.05, h = 0.013;
    sim.start(t0);
    for (int n = 1; n <= 800; ++n) {
        const double t = t0 + n * h;
        sim.advance_to(t);
        const auto expected = static_cast<std::int32_t>(std::floor((t - t0) / period + 1e-9)) + 1;
        ASSERT_EQ(sim.data().samples, expected) << "t = " << t;
    }
}

TEST(EstimatorFmuTiming, InitializationSampleSeesTheLastInputsSet) {
    Simulation sim;
    auto& d = sim.data();
    d.adc_bits = 0;
    const Eigen::Vector3d sun_ref(0, 1, 0), mag_ref(3e-5, 0, 1e-5);
    sim.enter_initialization();
    feed(sim, about_z(0.4), sun_ref, mag_ref);
    sim.runner.ensure_evaluated();
    EXPECT_LT(attitude_angle(a_est(sim), about_z(0.4)), 1e-9);
    feed(sim, about_z(0.9), sun_ref, mag_ref);  // a host setting the inputs again in initialization mode
    sim.runner.ensure_evaluated();
    EXPECT_EQ(d.samples, 1);  // initialize() from scratch each time: still one sample
    sim.exit_initialization();
    EXPECT_EQ(d.samples, 1);
    EXPECT_LT(attitude_angle(a_est(sim), about_z(0.9)), 1e-9);
}

// ---------------------------------------------------------------------------------------------------
// A known attitude

TEST(EstimatorFmuKnownAttitude, IdealConverterRecoversTheAttitudeTo1e9) {
    Random rng(2024);
    double worst_a = 0.0, worst_q = 0.0;
    for (const char* solver : {"qmethod", "fast"}) {
        for (int n = 0; n < 50; ++n) {
            const Case c = random_case(rng);
            Simulation sim;
            sim.data().adc_bits = 0;
            sim.set_choice("solver", solver);
            feed(sim, c.a, c.sun_ref, c.mag_ref);
            sim.start();
            sim.advance_to(0.07);  // two samples: at 0 and at 0.05
            const auto& d = sim.data();
            ASSERT_TRUE(d.valid) << solver << " case " << n;
            ASSERT_EQ(d.samples, 2);
            const double da = max_abs_diff(a_est(sim), c.a);
            const auto q = true_quaternion(c.a);
            double dq = 0.0;
            for (int i = 0; i < 4; ++i) dq = std::max(dq, std::fabs(d.q_est[i] - q[i]));
            EXPECT_LT(da, 1e-9) << solver << " case " << n;
            EXPECT_LT(dq, 1e-9) << solver << " case " << n;
            EXPECT_LT(d.loss, 1e-15);  // the data fit exactly: L = 0 (000 eq. 8)
            EXPECT_LT((vec(d.sun_meas) - c.a * c.sun_ref.normalized()).norm(), 1e-12);
            EXPECT_LT((vec(d.mag_field) - c.a * c.mag_ref).norm(), 1e-15);
            worst_a = std::max(worst_a, da);
            worst_q = std::max(worst_q, dq);
        }
    }
    std::printf("ideal ADC, 100 attitudes: max |A_est - A| = %.2g, max |q_est - q| = %.2g\n", worst_a, worst_q);
}

// Bound of the attitude error with 12-bit converters, derived here (not from the code under test).
//  Sun: each current is off by at most half an LSB, δi = (i_max − i_min)/(2^12 − 1)/2, so s = u + δ with
//    |δ| <= √3 δi / i_sc_norm; the direction chord |s/|s| − u| <= ||s| − 1| + |δ| <= 2|δ| =: ε_sun.
//  Field: each channel and the reference channel are off by at most half an LSB of the voltage range,
//    so each component of B is off by at most one LSB / S and |δB| <= √3 LSB / S; chord ε_mag <= 2|δB|/|B|.
//  Attitude: with weights ½ and the optimum A*, L(A*) <= L(A), and
//    Σ a_i |(A − A*) v_i|² <= 2 Σ a_i (|A v_i − w_i|² + |w_i − A* v_i|²) <= 8 L(A) = 4 Σ a_i ε_i²,
//    while for the rotation R = A* Aᵀ of angle φ, |(R − I) u| = 2 sin(φ/2) |n × u| and
//    min over axes n of |n × u1|² + |n × u2|² = 1 − |cos θ| (θ the angle between u1 and u2).
//    So sin(φ/2) <= sqrt((ε_sun² + ε_mag²) / (1 − |cos θ|)).
double twelve_bit_bound(const EstimatorData& d, const Case& c) {
    const double lsb_i = (d.i_adc_max - d.i_adc_min) / 4095.0;
    const double lsb_v = (d.v_adc_max - d.v_adc_min) / 4095.0;
    const double eps_sun = 2.0 * std::sqrt(3.0) * 0.5 * lsb_i / d.i_sc_norm[0];
    const double eps_mag = 2.0 * std::sqrt(3.0) * lsb_v / d.mag_sensitivity / c.mag_ref.norm();
    const double s = std::sqrt((eps_sun * eps_sun + eps_mag * eps_mag) / (1.0 - std::fabs(std::cos(c.separation))));
    return 2.0 * std::asin(std::min(1.0, s));
}

TEST(EstimatorFmuKnownAttitude, TwelveBitConverterStaysWithinTheDerivedBound) {
    Random rng(77);
    double worst = 0.0, worst_ratio = 0.0, loosest_bound = 0.0;
    for (const char* solver : {"qmethod", "fast"}) {
        for (int n = 0; n < 200; ++n) {
            const Case c = random_case(rng);
            Simulation sim;
            sim.set_choice("solver", solver);  // default converters: 12 bits, ±1.2 A, 0…5 V
            ASSERT_EQ(sim.data().adc_bits, 12);
            feed(sim, c.a, c.sun_ref, c.mag_ref);
            sim.start();
            ASSERT_TRUE(sim.data().valid);
            const double bound = twelve_bit_bound(sim.data(), c);
            const double err = attitude_angle(a_est(sim), c.a);
            EXPECT_LE(err, bound) << solver << " case " << n;
            worst = std::max(worst, err);
            worst_ratio = std::max(worst_ratio, err / bound);
            loosest_bound = std::max(loosest_bound, bound);
        }
    }
    std::printf(
        "12-bit ADC, 400 runs, 40 uT: worst attitude error %.3g rad (%.3g deg), worst error/bound %.3g, "
        "bound up to %.3g rad\n",
        worst, worst * 180.0 / std::numbers::pi, worst_ratio, loosest_bound);
}

// ---------------------------------------------------------------------------------------------------
// Table 1 of seed 001 through the FMU layer: v1 (sun_ref), w1 (sun, body), v2 (mag_ref), w2 (field,
// body) as printed, turned into panel currents and magnetometer voltages; the theoretical matrices
// as printed (4–5 digits), hence the 1e-4 tolerance.

struct Table1Case {
    const char* name;
    double v1[3], w1[3], v2[3], w2[3];
    double a[9];
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

TEST(EstimatorFmuTable1, ReproducesThePrintedMatricesThroughTheBlock) {
    for (const char* solver : {"qmethod", "fast"}) {
        for (const auto& c : kTable1) {
            Simulation sim;
            auto& d = sim.data();
            d.adc_bits = 0;
            sim.set_choice("solver", solver);
            const double field = 30e-6;  // T, |B| of the case; the printed w2 is the direction
            for (int k = 0; k < 3; ++k) {
                d.i_sh[k] = d.i_sc_norm[k] * c.w1[k];  // |w1| = √2 for the 45° case: the block normalizes
                d.v_mag[k] = 2.5 + d.mag_sensitivity * field * c.w2[k];
                d.sun_ref[k] = c.v1[k];
                d.mag_ref[k] = field * c.v2[k];
            }
            d.v_mag_ref = 2.5;
            sim.start();
            ASSERT_TRUE(d.valid) << solver << " " << c.name;
            double worst = 0.0;
            for (int i = 0; i < 9; ++i) {
                EXPECT_NEAR(d.A_est[i], c.a[i], 1e-4) << solver << " " << c.name << " element " << i;
                worst = std::max(worst, std::fabs(d.A_est[i] - c.a[i]));
            }
            std::printf("[%s] Table 1 '%s' through the FMU: worst |A - A_table| = %.2g, loss %.3g\n", solver, c.name,
                        worst, d.loss);
        }
    }
}

// ---------------------------------------------------------------------------------------------------
// Validity

TEST(EstimatorFmuValidity, EclipseIsInvalidAndSamplesAreStillCounted) {
    Simulation sim;
    auto& d = sim.data();
    const Eigen::Matrix3d a = about_z(0.3);
    const Eigen::Vector3d sun_ref(1, 0, 0), mag_ref(1e-5, 2e-5, 3e-5);
    feed(sim, a, sun_ref, mag_ref);
    sim.start();
    ASSERT_TRUE(d.valid);
    // Eclipse: the panels deliver (almost) nothing.
    d.i_sh = {1e-4, -2e-4, 0.0};
    sim.inputs_changed();
    sim.advance_to(1.01);  // samples at 0.05 … 1.0: 20 more
    EXPECT_EQ(d.samples, 21);
    EXPECT_FALSE(d.valid);
    EXPECT_FALSE(d.sun_valid);
    EXPECT_TRUE(d.mag_valid);
    EXPECT_EQ(d.q_est, (std::array<double, 4>{0, 0, 0, 1}));  // documented: identity when invalid
    EXPECT_EQ(d.loss, 0.0);
    // Albedo only: a third of full sun, below min_sun_norm = 0.5.
    const Eigen::Vector3d s = a * sun_ref;
    for (int k = 0; k < 3; ++k) d.i_sh[k] = 0.33 * d.i_sc_norm[k] * s[k];
    sim.inputs_changed();
    sim.advance_to(1.06);
    EXPECT_EQ(d.samples, 22);
    EXPECT_FALSE(d.valid);
    EXPECT_NEAR(d.sun_norm, 0.33, 2e-3);  // 12-bit: ½ LSB = 2.9e-4 A per channel, 3.5e-4 relative
    // Out of eclipse: valid again at the next sample.
    feed(sim, a, sun_ref, mag_ref);
    sim.advance_to(1.11);
    EXPECT_EQ(d.samples, 23);
    EXPECT_TRUE(d.valid);
}

TEST(EstimatorFmuValidity, SaturatedMagnetometerChannelIsInvalid) {
    for (double v : {5.0, 4.97, 5.4, 0.0, 0.03}) {  // at, within 0.05 V of, and beyond the rails
        Simulation sim;
        auto& d = sim.data();
        feed(sim, about_z(0.2), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 2e-5, 3e-5));
        d.v_mag[1] = v;
        sim.start();
        EXPECT_FALSE(d.mag_valid) << v;
        EXPECT_FALSE(d.valid) << v;
        EXPECT_TRUE(d.sun_valid) << v;
        EXPECT_EQ(d.samples, 1);
    }
    // 0.1 V inside the rail is not saturated.
    Simulation sim;
    feed(sim, about_z(0.2), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 2e-5, 3e-5));
    sim.data().v_mag[1] = 4.9;
    sim.start();
    EXPECT_TRUE(sim.data().mag_valid);
}

TEST(EstimatorFmuValidity, ParallelReferencesAreInvalid) {
    Simulation sim;
    feed(sim, about_z(0.2), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(3e-5, 1e-6, 0));  // 1.9° apart
    sim.start();
    EXPECT_TRUE(sim.data().sun_valid);
    EXPECT_TRUE(sim.data().mag_valid);
    EXPECT_FALSE(sim.data().valid);
}

TEST(EstimatorFmuValidity, DefaultInputsGiveTheIdentityAttitude) {
    // The start values describe +x towards the sun and 30 µT along +z in both frames: A = I. The 12-bit
    // converters put zero current ½ LSB off (2.9e-4 A, 3.5e-4 relative): a bound of 1e-3 rad.
    Simulation sim;
    sim.start();
    EXPECT_TRUE(sim.data().valid);
    EXPECT_LT(attitude_angle(a_est(sim), Eigen::Matrix3d::Identity()), 1e-3);
}

// ---------------------------------------------------------------------------------------------------
// Solver selection

TEST(EstimatorFmuSolver, SelectionChangesNothingOnConsistentData) {
    Random rng(5);
    double worst_ideal = 0.0, worst_12 = 0.0;
    for (int bits : {0, 12}) {
        for (int n = 0; n < 100; ++n) {
            const Case c = random_case(rng);
            Simulation q, f;
            q.set_choice("solver", "qmethod");
            f.set_choice("solver", "fast");
            q.data().adc_bits = f.data().adc_bits = bits;
            feed(q, c.a, c.sun_ref, c.mag_ref);
            feed(f, c.a, c.sun_ref, c.mag_ref);
            q.start();
            f.start();
            double diff = 0.0;
            for (int i = 0; i < 9; ++i) diff = std::max(diff, std::fabs(q.data().A_est[i] - f.data().A_est[i]));
            for (int i = 0; i < 4; ++i) diff = std::max(diff, std::fabs(q.data().q_est[i] - f.data().q_est[i]));
            EXPECT_LT(diff, 1e-9) << "bits " << bits << " case " << n;
            EXPECT_NEAR(q.data().loss, f.data().loss, 1e-12);
            (bits == 0 ? worst_ideal : worst_12) = std::max(bits == 0 ? worst_ideal : worst_12, diff);
        }
    }
    std::printf("qmethod vs fast: max difference %.2g (ideal ADC), %.2g (12-bit ADC)\n", worst_ideal, worst_12);
}

TEST(EstimatorFmuSolver, UnknownSolverNameIsRefused) {
    Simulation sim;
    EXPECT_NO_THROW(sim.set_choice("solver", "fast"));
    EXPECT_EQ(sim.data().solver, SolverKind::fast);
    EXPECT_THROW(sim.set_choice("solver", "quest"), fmu::Error);
}

// ---------------------------------------------------------------------------------------------------
// Table and parameters

TEST(EstimatorFmuTable, OutputsAreDiscreteWithNoDirectDependencies) {
    const auto& table = EstimatorBlock::static_table();
    EXPECT_TRUE(table.states().empty());
    int outputs = 0;
    for (const auto& v : table.variables()) {
        EXPECT_FALSE(v.description.empty()) << v.name;
        if (v.type == fmu::ValueType::Real) {
            EXPECT_FALSE(v.unit.empty()) << v.name;
        }
        if (v.causality != fmu::Causality::output) continue;
        ++outputs;
        EXPECT_EQ(v.variability, fmu::Variability::discrete) << v.name;
        ASSERT_TRUE(v.dependencies.has_value()) << v.name;
        EXPECT_TRUE(v.dependencies->empty()) << v.name;
    }
    // q, A, sun, mag, field, sun_norm, loss, 3 flags + samples; faces (lit, rejected, cube); spin (5); rate (3);
    // set/reset command and offset (1 + 3); filter (q 4, omega 3, offset 3, scale, bound, valid, resets);
    // the filter's attitude covariance factor (6); the in-flight magnetometer calibration applies (1); the
    // references used (sun 3, field 3); the declared faults (face words and times 6 + 6, axis words and times
    // 3 + 3, norm word and time 2); the face scales of the panel faults (6); the magnetometer's spikes and
    // mean innovation per axis (3 + 3), when a failed strap cleared (1). 103 in all: a hardware-bridge
    // frame carries up to 128 (bridge::max_values).
    EXPECT_EQ(outputs, 4 + 9 + 3 + 3 + 3 + 1 + 1 + 4 + 3 + 5 + 3 + 4 + 14 + 6 + 1 + 6 + 20 + 6 + 3 + 3 + 1);
    const auto& solver = table.by_name("solver");
    EXPECT_EQ(solver.type, fmu::ValueType::Enumeration);
    EXPECT_EQ(solver.item_names(), "qmethod, fast");
    EXPECT_EQ(EstimatorData{}.solver, SolverKind::qmethod);  // the brief's default, also the core's
    EXPECT_EQ(EstimatorData{}.solver, EstimatorConfig<double>{}.solver);
    // Defaults shared with the plant (ssr_plant panels, HMC2003): fixed by the brief, not by this code.
    const EstimatorData d;
    for (double i : d.i_sc_norm) EXPECT_EQ(i, 0.84754);               // ssr_plant's README figure
    EXPECT_EQ(d.i_face_norm, SunMethodConfig<double>{}.i_face_norm);  // the core's default
    EXPECT_EQ(d.sun_method, SunMethodConfig<double>{}.method);
    EXPECT_EQ(d.min_sun_norm, EstimatorConfig<double>{}.min_sun_norm);
    EXPECT_EQ(d.mag_sensitivity, EstimatorConfig<double>{}.mag_sensitivity);
    EXPECT_EQ(d.i_adc_min, -1.2);
    EXPECT_EQ(d.i_adc_max, 1.2);
    EXPECT_EQ(d.v_adc_min, 0.0);
    EXPECT_EQ(d.v_adc_max, 5.0);
    EXPECT_EQ(d.mag_sensitivity, 1e4);
    EXPECT_EQ(d.adc_bits, 12);
    EXPECT_EQ(d.sample_period, 0.05);
    EXPECT_EQ(table.by_name("mag_ref[1]").unit, "T");
    EXPECT_EQ(table.by_name("sun_ref[3]").unit, "1");
}

TEST(EstimatorFmuTable, ValidateRefusesInconsistentParameters) {
    auto refuses = [](auto change) {
        Simulation sim;
        change(sim.data());
        EXPECT_THROW(sim.runner.model().validate(), fmu::Error);
    };
    refuses([](EstimatorData& d) { d.i_adc_max = d.i_adc_min; });
    refuses([](EstimatorData& d) { d.v_adc_max = 0.08; });  // narrower than twice the 0.05 V rail margin
    refuses([](EstimatorData& d) { d.weight_sun = d.weight_mag = 0.0; });
    Simulation sim;
    EXPECT_NO_THROW(sim.runner.model().validate());
}

}  // namespace
}  // namespace attitude_estimator
