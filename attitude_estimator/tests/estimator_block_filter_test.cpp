// attitude_estimator.fmu's recursive filter (filter = mekf) through the runtime's C++ layer: the choice
// and its table entries, a tumbling body whose attitude is known exactly (A(t) = exp(−[ω×] t) A0, Eigen's
// AngleAxis) read through 12-bit converters, and a bit-identical replay from a saved and restored FMU state.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <vector>

#include "attitude_estimator/estimator_block.hpp"
#include "block_simulation.hpp"
#include "fmu/errors.hpp"

namespace attitude_estimator {
namespace {

using test::Simulation;

constexpr double kIsc0 = 0.84754;  // A, ssr_plant's i_sc at 1367 W/m² and normal incidence

// The scenario: body rate ω (rad/s, body axes), constant; references fixed in inertial space.
struct Truth {
    Eigen::Vector3d omega{0.02, -0.015, 0.01};
    Eigen::Matrix3d a0 = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    Eigen::Vector3d sun_ref = Eigen::Vector3d(0.2, 0.9, -0.3).normalized();
    Eigen::Vector3d mag_ref{20e-6, -15e-6, 35e-6};
    // exp(−[ω×] t) A0: Eigen's AngleAxis(θ, n) is exp(θ [n×]).
    Eigen::Matrix3d attitude(double t) const {
        const double n = omega.norm();
        return Eigen::AngleAxisd(-n * t, omega / n).toRotationMatrix() * a0;
    }
};

// Cosine-law panels and an ideal magnetometer at the true attitude (the converters are the block's).
void feed(EstimatorData& d, const Truth& truth, double t) {
    const Eigen::Matrix3d a = truth.attitude(t);
    const Eigen::Vector3d s = a * truth.sun_ref, b = a * truth.mag_ref;
    for (int k = 0; k < 6; ++k) d.i_face[k] = kIsc0 * std::max(0.0, (k % 2 == 0 ? 1.0 : -1.0) * s[k / 2]);
    for (int k = 0; k < 3; ++k) {
        d.i_sh[k] = d.i_face[2 * k] - d.i_face[2 * k + 1];
        d.v_mag[k] = 2.5 + d.mag_sensitivity * b[k];
        d.sun_ref[k] = truth.sun_ref[k];
        d.mag_ref[k] = truth.mag_ref[k];
    }
}

// Attitude error (rad) of a scalar-last quaternion against A: our A(q) is Eigen's matrix of (w, x, y, z)
// transposed.
double error_of(const std::array<double, 4>& q, const Eigen::Matrix3d& a) {
    const Eigen::Matrix3d aq = Eigen::Quaterniond(q[3], q[0], q[1], q[2]).normalized().toRotationMatrix().transpose();
    const Eigen::AngleAxisd d(aq * a.transpose());
    return std::abs(d.angle());
}

TEST(EstimatorFmuFilter, DefaultIsNoneAndTheChoiceIsChecked) {
    Simulation sim;
    EXPECT_EQ(sim.data().filter, FilterKind::none);
    EXPECT_THROW(sim.set_choice("filter", "ukf"), fmu::Error);
    sim.set_choice("filter", "mekf");
    sim.data().inertia = {1, 0, 0, 0, 1, 0, 0, 0, -1};  // not positive definite
    EXPECT_THROW(sim.runner.model().validate(), fmu::Error);
    sim.data().inertia = {3.2, 0.05, 0, 0.04, 2.9, 0, 0, 0, 3.6};  // not symmetric
    EXPECT_THROW(sim.runner.model().validate(), fmu::Error);
    sim.data().inertia = {3.2, 0.05, 0, 0.05, 2.9, 0, 0, 0, 3.6};
    EXPECT_NO_THROW(sim.runner.model().validate());
}

TEST(EstimatorFmuFilter, NoneLeavesTheFilterOutputsAtRest) {
    Truth truth;
    Simulation sim;
    auto& d = sim.data();
    feed(d, truth, 0.0);
    sim.start();
    for (int k = 1; k <= 40; ++k) {
        feed(d, truth, k * d.sample_period);
        sim.inputs_changed();
        sim.advance_to(k * d.sample_period);
    }
    EXPECT_TRUE(d.valid);
    EXPECT_FALSE(d.filter_valid);
    EXPECT_EQ(d.q_filt, (std::array<double, 4>{0, 0, 0, 1}));
    EXPECT_EQ(d.onboard.filter.stage, 0);
}

TEST(EstimatorFmuFilter, TracksATumbleBetterThanTheSingleFrameEstimate) {
    Truth truth;
    Simulation sim;
    auto& d = sim.data();
    sim.set_choice("filter", "mekf");
    // 12-bit converters: single-frame errors of a few 0.01 deg (the block test's quantization bound).
    d.filter_sun_sigma = 0.002;
    d.filter_mag_sigma = 0.1e-6;
    feed(d, truth, 0.0);
    sim.start();
    std::vector<double> single, filtered;
    int covered = 0;
    for (int k = 1; k <= 2400; ++k) {  // 120 s
        const double t = k * d.sample_period;
        feed(d, truth, t);
        sim.inputs_changed();
        sim.advance_to(t);
        if (t < 60.0) continue;
        ASSERT_TRUE(d.filter_valid) << t;
        const Eigen::Matrix3d a = truth.attitude(t);
        single.push_back(error_of(d.q_est, a));
        filtered.push_back(error_of(d.q_filt, a));
        covered += filtered.back() <= d.attitude_bound;
        EXPECT_LT((Eigen::Vector3d(d.omega_filt[0], d.omega_filt[1], d.omega_filt[2]) - truth.omega).norm(), 1e-4);
    }
    auto rms = [](const std::vector<double>& v) {
        double s = 0;
        for (double x : v) s += x * x;
        return std::sqrt(s / static_cast<double>(v.size()));
    };
    EXPECT_LT(rms(filtered), 0.5 * rms(single)) << "single " << rms(single) << " filter " << rms(filtered);
    EXPECT_GE(covered, static_cast<int>(0.99 * static_cast<double>(filtered.size())));
    EXPECT_EQ(d.filter_resets, 0);
}

TEST(EstimatorFmuFilter, SavedAndRestoredStateReplaysBitIdentically) {
    // The filter's estimate and covariance are FMU state: a copy of the state bytes taken mid-run and
    // restored into a fresh instance must continue exactly as the original (as fmi2Get/SetFMUstate and
    // serialization do: the block's state is its data struct, copied as bytes).
    Truth truth;
    Simulation a;
    auto& d = a.data();
    a.set_choice("filter", "mekf");
    d.filter_scale = true;
    a.set_choice("sun_method", "inverse_response");
    d.inertia = {3.2, 0.05, -0.02, 0.05, 2.9, 0.03, -0.02, 0.03, 3.6};
    feed(d, truth, 0.0);
    a.start();
    const double t_save = 3.0;
    for (int k = 1; k * d.sample_period <= t_save + 1e-9; ++k) {
        feed(d, truth, k * d.sample_period);
        a.inputs_changed();
        a.advance_to(k * d.sample_period);
    }
    ASSERT_EQ(d.onboard.filter.stage, 2);
    const auto bytes = a.runner.model().bytes();
    const std::vector<std::byte> saved(bytes.begin(), bytes.end());

    Simulation b;
    b.start();
    const auto restored = b.runner.model().clone();  // a fresh instance, then the saved bytes into it
    auto target = restored->bytes();
    ASSERT_EQ(target.size(), saved.size());
    std::memcpy(target.data(), saved.data(), saved.size());
    b.runner.restore(*restored, t_save);
    b.solver = std::make_unique<fmu::CsSolver>(b.runner, 1e-8);

    for (int k = 61; k <= 200; ++k) {
        const double t = k * d.sample_period;
        feed(a.data(), truth, t);
        feed(b.data(), truth, t);
        a.inputs_changed();
        b.inputs_changed();
        a.advance_to(t);
        b.advance_to(t);
    }
    EXPECT_TRUE(a.data().filter_valid);
    // A restored state is checked (fmi2DeSerializeFMUstate): a running filter passes, a broken one not.
    EXPECT_NO_THROW(a.runner.model().check_state());
    {
        const auto broken = a.runner.model().clone();
        auto& bd = static_cast<EstimatorBlock&>(*broken).data();
        bd.onboard.filter.p[5] = std::numeric_limits<double>::quiet_NaN();
        EXPECT_THROW(broken->check_state(), fmu::Error);
        bd.onboard.filter.p[5] = 0.0;
        bd.onboard.filter.stage = 3;
        EXPECT_THROW(broken->check_state(), fmu::Error);
    }
    const auto ea = a.runner.model().bytes();
    const auto eb = b.runner.model().bytes();
    EXPECT_EQ(std::memcmp(ea.data(), eb.data(), ea.size()), 0);
    EXPECT_EQ(a.data().q_filt, b.data().q_filt);
    EXPECT_EQ(a.data().onboard.filter.p, b.data().onboard.filter.p);
}

}  // namespace
}  // namespace attitude_estimator

namespace attitude_estimator {
namespace {

TEST(EstimatorFmuFilter, RateValidFalseWhereTheIntervalAliases) {
    // 2π rad/s turns exactly once per second: every 2 s increment of rate_mean (004 eq. 4) reads a turn of
    // 4π, i.e. none at all. The turn between samples (18 deg) says so, with and without the filter; the
    // filter's rate is the right one.
    for (const char* filter : {"none", "mekf"}) {
        Truth truth;
        truth.omega = 2.0 * std::numbers::pi * Eigen::Vector3d(0.2, -0.3, 0.93).normalized();
        Simulation sim;
        auto& d = sim.data();
        sim.set_choice("filter", filter);
        d.rate_interval = 2.0;
        d.rate_window = 2;
        d.filter_rate_noise = 0.01;
        d.filter_sun_sigma = 0.002;
        d.filter_mag_sigma = 0.1e-6;
        feed(d, truth, 0.0);
        sim.start();
        bool mean_ready = false;
        for (int k = 1; k <= 200; ++k) {  // 10 s
            const double t = k * d.sample_period;
            feed(d, truth, t);
            sim.inputs_changed();
            sim.advance_to(t);
            mean_ready = mean_ready || d.rate_window_time > 0.0;
            EXPECT_FALSE(d.rate_valid) << filter << " t = " << t << " rate_mean " << d.rate_mean;
        }
        EXPECT_TRUE(mean_ready);
        EXPECT_LT(d.rate_mean, 0.1) << "the aliased increments read (almost) no turn";
        if (d.filter == FilterKind::mekf) {
            const Eigen::Vector3d w(d.omega_filt[0], d.omega_filt[1], d.omega_filt[2]);
            EXPECT_LT((w - truth.omega).norm(), 0.01 * truth.omega.norm());
        }
    }
}

}  // namespace
}  // namespace attitude_estimator
