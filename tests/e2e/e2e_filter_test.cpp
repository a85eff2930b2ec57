// Issue 16 end to end: the seed spin (paper 000 §4: θ̇ = 6.28 rad/s, φ̇ = 1.26 rad/s, 18 deg of turn per
// 20 Hz sample) with the estimator's recursive filter (est.filter=mekf) beside its single-frame Q-method,
// scored against the environment's true attitude and rate over the first 2 s.
//
// The seed's prescribed spin has a body rate of constant size whose transverse part turns about body z at
// φ̇ = ω_z: exactly the torque-free motion (Euler's equations) of a body with inertia diag(1, 1, ε), ε → 0.
// The filter is given that inertia (ε = 0.001 turns the rate 0.1 % slower than the truth, which the rate
// noise absorbs); docs/filter.md explains the choice and the tuning.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "analysis/angle_error.hpp"
#include "engine/execution.hpp"
#include "engine/system.hpp"
#include "engine/system_description.hpp"
#include "recorder.hpp"

namespace {

double p95_of(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[static_cast<std::size_t>(std::lround(0.95 * static_cast<double>(v.size() - 1)))];
}

}  // namespace

TEST(E2eFilter, SeedSpinFilterNoWorseThanTheQMethod) {
    cosim::SystemOptions options;
    options.fmu_dirs = {PVATT_FMU_DIR};
    options.settings = {"est.filter=mekf",
                        "est.inertia[1]=1",
                        "est.inertia[5]=1",
                        "est.inertia[9]=0.001",
                        "est.filter_rate_noise=0.003",
                        "est.filter_sun_sigma=0.002",
                        "est.filter_mag_sigma=1e-7"};
    cosim::System system(cosim::read_system_description(PVATT_SYSTEMS_DIR "/seed_spin.ssd"), options);
    cosim::ExecutionOptions ex;
    ex.stop_time = 2.0;
    ex.output_interval = 0.05;  // = the estimator's sample period: rows fall on sample instants
    ex.relative_tolerance = 1e-6;
    auto cols = e2e::vec("env.q_true", 4);
    for (const auto& prefix : {"est.q_est", "est.q_filt"})
        for (const auto& c : e2e::vec(prefix, 4)) cols.push_back(c);
    for (const auto& prefix : {"est.omega_filt", "env.omega_body"})
        for (const auto& c : e2e::vec(prefix, 3)) cols.push_back(c);
    for (const char* c : {"est.valid", "est.filter_valid", "est.attitude_bound", "est.filter_resets"})
        cols.push_back(c);
    e2e::Recorder rec(system, cols);
    cosim::Execution(system, ex).run({&rec});

    std::vector<double> single, filtered, rate;
    int covered = 0;
    for (std::size_t k = 0; k < rec.time.size(); ++k) {
        // The filter starts at the second sample (the rate from two attitudes); judged from 0.5 s on.
        if (rec.time[k] < 0.5 - 1e-9) continue;
        double qt[4], qe[4], qf[4];
        for (int i = 0; i < 4; ++i) {
            const std::string n = "[" + std::to_string(i + 1) + "]";
            qt[i] = rec["env.q_true" + n][k];
            qe[i] = rec["est.q_est" + n][k];
            qf[i] = rec["est.q_filt" + n][k];
        }
        ASSERT_GT(rec["est.valid"][k], 0.5) << rec.time[k];
        ASSERT_GT(rec["est.filter_valid"][k], 0.5) << rec.time[k];
        single.push_back(analysis::attitude_error_degrees(qt, qe));
        filtered.push_back(analysis::attitude_error_degrees(qt, qf));
        covered += filtered.back() <= rec["est.attitude_bound"][k] * 180.0 / M_PI;
        double w2 = 0;
        for (int i = 0; i < 3; ++i) {
            const std::string n = "[" + std::to_string(i + 1) + "]";
            const double d = rec["est.omega_filt" + n][k] - rec["env.omega_body" + n][k];
            w2 += d * d;
        }
        rate.push_back(std::sqrt(w2));
    }
    ASSERT_GE(filtered.size(), 30u);
    const double single_p95 = p95_of(single), filter_p95 = p95_of(filtered);
    std::printf("seed spin 0.5-2 s: single-frame p95 %.3f deg, filter p95 %.3f deg, rate error p95 %.4f rad/s\n",
                single_p95, filter_p95, p95_of(rate));
    // Issue 16: no worse than the Q-method (the issue quotes its p95 as 0.23 deg for this scenario).
    EXPECT_LE(filter_p95, single_p95);
    EXPECT_LT(filter_p95, 0.23);
    // The filter's 3-sigma bound holds (a filter that is right and says so).
    EXPECT_GE(covered, static_cast<int>(filtered.size()) - 1);
    // Rate: 6.4 rad/s known to better than 1 % (the eq. 4 mean rate aliases here; docs/rates.md).
    EXPECT_LT(p95_of(rate), 0.064);
    EXPECT_EQ(rec["est.filter_resets"].back(), 0.0);
}
