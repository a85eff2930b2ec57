// The ssr_plant block through the runtime's C++ layer (ModelRunner + CsSolver, as inside the FMU in
// Co-Simulation): the verification (10 s seed spin with an eclipse at 5 s, both fidelities), the
// ripple and the S/H error, eclipse currents, the charge switch, the model cache, errors. Expected values
// are derived by hand in the comments, never taken from a run.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string_view>

#include "fmu/cs_solver.hpp"
#include "fmu/errors.hpp"
#include "fmu/model_runner.hpp"
#include "fmu/testing/block_driver.hpp"
#include "ssr_plant/angular_response.hpp"
#include "ssr_plant/ssr_plant_block.hpp"

namespace ssr_plant {
namespace {

struct PlantRun : fmu::testing::BlockDriver<SsrPlantBlock> {
    // The hand bounds of the tests in this file are derived for the regular modulator at 3 per volt (the
    // model's earlier reading of the seed's "300" as 300 %/V) and the battery controlled on its state of
    // charge; the seed's 300 per volt with the latched_natural modulator is tested below (SsrFmuModulation),
    // the voltage-controlled charge in the core tests.
    explicit PlantRun(bool earlier_reading = true) : BlockDriver(1e-6) {
        if (!earlier_reading) return;
        data().controller_gain = 3.0;
        set_choice("modulation", "regular");
        set_choice("charge_control", "state_of_charge");  // and the earlier battery (see earlier_reading.hpp)
    }
    void step_to(double t) { advance_to(t); }
};

// Seed 000 §4: s = (sin φ sin θ, cos φ sin θ, cos θ), φ̇ = 1.26 rad/s, θ̇ = 6.28 rad/s.
std::array<double, 3> seed_sun(double t) {
    const double phi = 1.26 * t, theta = 6.28 * t;
    return {std::sin(phi) * std::sin(theta), std::cos(phi) * std::sin(theta), std::cos(theta)};
}

// Short-circuit current of a panel facing the sun, measured through the block itself: the
// calibration a satellite would do on the ground (eq. 5 divides by it).
double normal_incidence_isc() {
    PlantRun run;
    run.set_choice("angular_response", "cosine");
    run.data().sun_body = {1.0, 0.0, 0.0};
    run.start();
    return run.data().i_sc[0];
}

// The verification run: the seed spin for 10 s, inputs set every h = 0.5 ms (the value at the
// step's start held over the step, as a co-simulation master does), eclipse (irradiance 0) from 5 s on.
constexpr double seed_duration = 10.0;
constexpr double eclipse_start = 5.0;
constexpr double input_step = 0.5e-3;
constexpr double settle_time = 0.05;  // the controller's start-up from 15 V and duty 0 (a few ms)

struct SeedResult {
    double isc0 = 0.0;
    // sunlit window [settle_time, eclipse_start)
    double v_min = 1e9, v_max = -1e9, v_mean = 0.0;
    std::array<double, 3> err_rms{}, err_max{};  // i_sh / isc0 − true sun s(t)
    double held_input_err_max = 0.0;             // i_sh / isc0 − the sun input actually applied
    double soc_at_eclipse = 0.0;
    // eclipse
    double soc_a = 0.0, soc_b = 0.0, t_a = 0.0, t_b = 0.0;  // soc at the window's ends
    double i_load_a = 0.0, i_load_b = 0.0;
    double v_bus_end = 0.0;
    std::array<double, 3> i_sh_max_eclipse{};
    double face_identity_err_max = 0.0;  // |i_sh[k] − (i_face_sh[2k−1] − i_face_sh[2k])| over every sample
    SsrPlantData final{};
};

SeedResult run_seed(const char* fidelity) {
    SeedResult r;
    r.isc0 = normal_incidence_isc();
    PlantRun run;
    run.set_choice("fidelity", fidelity);
    run.set_choice("angular_response", "cosine");  // eq. 5 assumes the cosine law
    run.data().sun_body = seed_sun(0.0);
    run.start();
    const double soc_start = run.data().soc;
    int sunlit = 0;
    const int steps = static_cast<int>(std::lround(seed_duration / input_step));
    for (int k = 1; k <= steps; ++k) {
        const double t0 = (k - 1) * input_step, t1 = k * input_step;
        const auto applied = seed_sun(t0);
        run.data().sun_body = applied;
        run.data().irradiance = t0 < eclipse_start - 1e-12 ? 1367.0 : 0.0;
        run.step_to(t1);
        const auto& d = run.data();
        for (int i = 0; i < 3; ++i)
            r.face_identity_err_max =
                std::max(r.face_identity_err_max, std::abs(d.i_sh[i] - (d.i_face_sh[2 * i] - d.i_face_sh[2 * i + 1])));
        if (t1 <= eclipse_start + 1e-12) {
            if (std::abs(t1 - eclipse_start) < 1e-12) r.soc_at_eclipse = d.soc - soc_start;
            if (t1 < settle_time) continue;
            ++sunlit;
            r.v_min = std::min(r.v_min, d.v_bus);
            r.v_max = std::max(r.v_max, d.v_bus);
            r.v_mean += d.v_bus;
            const auto s = seed_sun(t1);
            for (int i = 0; i < 3; ++i) {
                const double e = d.i_sh[i] / r.isc0 - s[i];
                r.err_rms[i] += e * e;
                r.err_max[i] = std::max(r.err_max[i], std::abs(e));
                r.held_input_err_max = std::max(r.held_input_err_max, std::abs(d.i_sh[i] / r.isc0 - applied[i]));
            }
        } else {
            for (int i = 0; i < 3; ++i) r.i_sh_max_eclipse[i] = std::max(r.i_sh_max_eclipse[i], std::abs(d.i_sh[i]));
            if (std::abs(t1 - (eclipse_start + 0.5)) < 1e-9) {
                r.t_a = t1;
                r.soc_a = d.soc;
                r.i_load_a = d.i_load;
            }
        }
    }
    r.t_b = run.runner.time();
    r.soc_b = run.data().soc;
    r.i_load_b = run.data().i_load;
    r.v_bus_end = run.data().v_bus;
    r.final = run.data();
    r.v_mean /= sunlit;
    for (auto& e : r.err_rms) e = std::sqrt(e / sunlit);
    std::printf(
        "%s seed 10 s: v_bus mean %.4f min %.4f max %.4f V (samples every 0.5 ms); i_sh/i_sc0 - s: "
        "rms (%.3e %.3e %.3e) max (%.3e %.3e %.3e), vs applied input max %.2e; eclipse soc slope %.5e /s, "
        "i_load %.5f A, v_bus at 10 s %.4f V\n",
        fidelity, r.v_mean, r.v_min, r.v_max, r.err_rms[0], r.err_rms[1], r.err_rms[2], r.err_max[0], r.err_max[1],
        r.err_max[2], r.held_input_err_max, (r.soc_b - r.soc_a) / (r.t_b - r.t_a), r.i_load_a, r.v_bus_end);
    return r;
}

// Bus band, by hand. The P controller settles where the duty balances the load (eq. 4):
// (1 − D) ΣI = V/R_L, with ΣI = I1 Σ|s_i| over the lit faces, I1 ≈ 0.82–0.85 A (one panel at normal
// incidence and 1367 W/m², Isc 0.62 A × 1.367 less its diode and shunt losses at the bus + 0.6 V), and
// 1 ≤ Σ|s_i| ≤ √3; V/R_L = 15.28/90 = 0.170 A. So D ∈ [1 − 0.170/0.82, 1 − 0.170/(√3 0.85)] = [0.793, 0.885]
// and the sampled bus V = v_ref + 100 D / K = 15 + D/3 ∈ [15.264, 15.295] V. Switching adds the ripple:
// during the on-time the load alone drains the capacitor, ΔV = 0.170 A × 0.885 × 200 µs / 1500 µF = 0.020 V
// below the sampled value. 5 mV margin for the loop's response to the input steps.
void expect_bus_band(const SeedResult& r, double ripple, const char* what) {
    EXPECT_GT(r.v_min, 15.0 + 0.793 / 3.0 - ripple - 0.005) << what;
    EXPECT_LT(r.v_max, 15.0 + 0.885 / 3.0 + 0.005) << what;
}

// The sun error, by hand. Inputs are held over each 0.5 ms step and the S/H (switching) holds at most
// (1 − D) T = 41 µs, always inside the same step, so i_sh / i_sc0 at t_k is the sun of t_k − h up to the
// panel's nonlinearity (the Hall current flows through R_DS(on) = 0.05 Ω more than the true Isc:
// relative 0.05 / R_sh = 2.5e-5; diode current at ~1.2 V: 2e-8 A): below 1e-4 of the applied input.
// Against the true sun the error is then s(t_k) − s(t_k − h) ≈ h ds/dt:
//   max: |ds_x/dt|, |ds_y/dt| ≤ sqrt(φ̇² + θ̇²) = 6.405 /s, |ds_z/dt| ≤ θ̇ = 6.28 /s → 3.20e-3, 3.14e-3 (+1e-4);
//   RMS: <(ds_x/dt)²> = <(ds_y/dt)²> = (φ̇² + θ̇²)/4, <(ds_z/dt)²> = θ̇²/2 over whole turns (the 5 s sunlit
//   window holds 1.0 turn of φ and 5.0 of θ) → h × (3.203, 3.203, 4.441) = (1.601, 1.601, 2.220)e-3, ±10 %.
void expect_sun_error(const SeedResult& r, const char* what) {
    const double h = input_step;
    const double max_rate[3] = {std::hypot(1.26, 6.28), std::hypot(1.26, 6.28), 6.28};
    const double rms_rate[3] = {std::hypot(1.26, 6.28) / 2.0, std::hypot(1.26, 6.28) / 2.0, 6.28 / std::sqrt(2.0)};
    EXPECT_LT(r.held_input_err_max, 1e-4) << what;
    for (int i = 0; i < 3; ++i) {
        EXPECT_LT(r.err_max[i], max_rate[i] * h + 1e-4) << what << " axis " << i;
        EXPECT_NEAR(r.err_rms[i], rms_rate[i] * h, 0.1 * rms_rate[i] * h) << what << " axis " << i;
    }
}

double eclipse_load_current(const SsrPlantData& d, double soc, bool connected);

// Bus 15.28 V against battery 12.62 V − 0.6 V diode: the diode blocks and the charge switch is open
// (soc 0.9 > soc_connect 0.8), so not one coulomb moves before the eclipse. From 5.5 s (the bus fell to
// the battery's level within RC ln(15.28/12.0) = 33 ms) the battery alone feeds the load: the hand KCL
// current, and soc' = −i_load / capacity.
void expect_battery(const SeedResult& r, const char* what) {
    EXPECT_EQ(r.soc_at_eclipse, 0.0) << what;
    const double i_hand = eclipse_load_current(r.final, r.soc_a, false);
    EXPECT_NEAR(r.i_load_a, i_hand, 1e-4 * i_hand) << what;
    const double slope = (r.soc_b - r.soc_a) / (r.t_b - r.t_a);
    const double predicted = -0.5 * (r.i_load_a + r.i_load_b) / r.final.battery_capacity;
    // The current is constant to 1e-6 (OCV slope 1.2 V × Δsoc 8e-5 over 90 Ω), which BDF integrates
    // exactly; what remains is the integrator's absolute tolerance on soc (1e-6) against the 8.3e-5
    // change: 1.2 %, bounded by 2 %.
    EXPECT_NEAR(slope, predicted, 0.02 * std::abs(predicted)) << what;
    EXPECT_NEAR(slope, -i_hand / r.final.battery_capacity, 0.02 * std::abs(predicted)) << what;
    for (double i : r.i_sh_max_eclipse) EXPECT_EQ(i, 0.0) << what;  // dark panels: no Hall current
    EXPECT_LT(r.v_bus_end, 12.1) << what;                           // battery 12.62 V less its diode (0.6 V) and drops
}

// The verification, averaged fidelity: 10 s of seed spin, eclipse at 5 s.
TEST(SsrFmu, SeedScenarioAveraged) {
    const SeedResult r = run_seed("averaged");
    expect_bus_band(r, 0.0, "averaged");  // no ripple in the average
    expect_sun_error(r, "averaged");
    expect_battery(r, "averaged");
    EXPECT_EQ(r.face_identity_err_max, 0.0);  // the per-axis S/H is the difference of the per-face ones
}

// The same in switching fidelity (every PWM edge a time event), and its agreement with the average.
TEST(SsrFmu, SeedScenarioSwitchingAgreesWithAveraged) {
    const SeedResult sw = run_seed("switching");
    expect_bus_band(sw, 0.020, "switching");
    expect_sun_error(sw, "switching");
    expect_battery(sw, "switching");
    EXPECT_EQ(sw.face_identity_err_max, 0.0);  // one hold instant for the axis and its two faces
    const SeedResult avg = run_seed("averaged");
    // The switched bus sampled every 0.5 ms (2.5 PWM periods: alternately at the period start, on the
    // sampled value, and mid on-time, ~10 mV lower) against the average: within the 20 mV ripple.
    EXPECT_NEAR(sw.v_mean, avg.v_mean, 0.020);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(sw.err_rms[i], avg.err_rms[i], 1e-4) << "axis " << i;
    const double sw_slope = (sw.soc_b - sw.soc_a) / (sw.t_b - sw.t_a);
    const double avg_slope = (avg.soc_b - avg.soc_a) / (avg.t_b - avg.t_a);
    EXPECT_NEAR(sw_slope, avg_slope, 0.01 * std::abs(avg_slope));
}

// The sampling itself (seed 001 §3, fig. 8 of seed 000): with inputs refreshed every 10 µs, far inside a
// 200 µs PWM period, the input hold no longer hides the S/H. While the gate is off the S/H holds the sun of
// the last trailing edge, up to (1 − D) T ≤ (1 − 0.793) 200 µs = 41 µs old; the averaged plant has no
// S/H. By hand, max error against the true sun: averaged ≤ |ds/dt|max h = 6.405 /s × 10 µs = 6.4e-5,
// switching ≤ 6.405 /s × (10 + 41) µs = 3.3e-4, each + 3e-5 of panel nonlinearity (see above).
struct FineResult {
    std::array<double, 3> err_rms{}, err_max{};
};

FineResult fine_sun_error(const char* fidelity, double duration) {
    const double isc0 = normal_incidence_isc();
    PlantRun run;
    run.set_choice("fidelity", fidelity);
    run.set_choice("angular_response", "cosine");
    run.data().sun_body = seed_sun(0.0);
    run.start();
    const double h = 10e-6;
    FineResult r;
    int n = 0;
    const int steps = static_cast<int>(std::lround(duration / h));
    for (int k = 1; k <= steps; ++k) {
        run.data().sun_body = seed_sun((k - 1) * h);
        run.step_to(k * h);
        if (k * h < settle_time) continue;
        ++n;
        const auto s = seed_sun(k * h);
        for (int i = 0; i < 3; ++i) {
            const double e = run.data().i_sh[i] / isc0 - s[i];
            r.err_rms[i] += e * e;
            r.err_max[i] = std::max(r.err_max[i], std::abs(e));
        }
    }
    for (auto& e : r.err_rms) e = std::sqrt(e / n);
    std::printf("%s, inputs every 10 us, %.2f s: i_sh/i_sc0 - s rms (%.2e %.2e %.2e) max (%.2e %.2e %.2e)\n", fidelity,
                duration, r.err_rms[0], r.err_rms[1], r.err_rms[2], r.err_max[0], r.err_max[1], r.err_max[2]);
    return r;
}

TEST(SsrFmu, SampleHoldErrorIsBoundedByTheOffTime) {
    const double rate = std::hypot(1.26, 6.28);
    const auto avg = fine_sun_error("averaged", 0.3);
    const auto sw = fine_sun_error("switching", 0.3);
    double avg_max = 0.0, sw_max = 0.0;
    for (int i = 0; i < 3; ++i) {
        EXPECT_LT(avg.err_max[i], rate * 10e-6 + 3e-5) << "axis " << i;
        EXPECT_LT(sw.err_max[i], rate * 51e-6 + 3e-5) << "axis " << i;
        avg_max = std::max(avg_max, avg.err_max[i]);
        sw_max = std::max(sw_max, sw.err_max[i]);
    }
    // The S/H shows: within 0.3 s θ sweeps 1.9 rad, so |ds_z/dt| passes 6 /s while the gate is off.
    EXPECT_GT(sw_max, 2.0 * avg_max);
}

// Issue 8: each face's own Hall channel (i_face_sh), for an estimator that uses the panels one by one.
// A face's channel carries its panel's current short-circuited through the shunt switch: the diode sits at
// V = I (R_s + R_DS(on)), a few tens of mV, where it passes ~1e-9 of the current, and R_sh takes the fixed
// fraction (R_s + R_DS(on)) / R_sh; so the current is c · g, linear in the face's effective irradiance
// g = irradiance · f(β) + albedo (photocurrent linear in g), with one c for all faces. c is calibrated on
// a face at normal incidence; every face must then follow its own g, whatever the others see.
std::array<double, 6> face_currents(const char* fidelity, const char* law, std::array<double, 3> sun, double irr,
                                    std::array<double, 6> albedo) {
    PlantRun run;
    run.set_choice("fidelity", fidelity);
    run.set_choice("angular_response", law);
    run.data().sun_body = sun;
    run.data().irradiance = irr;
    run.data().albedo_face = albedo;
    run.start();
    run.step_to(0.02);  // constant inputs: the switching S/H holds the same value it tracked
    return run.data().i_face_sh;
}

TEST(SsrFmu, EachFaceChannelFollowsItsOwnIllumination) {
    const std::array<double, 3> s = {0.6, -0.48, 0.64};  // unit vector: cos β of ±x, ±y, ±z faces = ±s_i
    const std::array<double, 6> albedo = {50.0, 0.0, 120.0, 30.0, 0.0, 200.0};
    for (const char* fidelity : {"averaged", "switching"}) {
        for (const char* law : {"cosine", "kelly"}) {
            const double c = face_currents(fidelity, law, {1.0, 0.0, 0.0}, 1367.0, {})[0] / 1367.0;
            EXPECT_NEAR(c, 0.62 / 1000.0, 0.01 * 0.62 / 1000.0) << fidelity << " " << law;  // Isc at 1000 W/m²
            const auto i = face_currents(fidelity, law, s, 1367.0, albedo);
            const AngularResponse f =
                std::string_view(law) == "kelly" ? AngularResponse::kelly : AngularResponse::cosine;
            for (int k = 0; k < 6; ++k) {
                const double cos_beta = (k % 2 == 0 ? 1.0 : -1.0) * s[k / 2];
                const double g = 1367.0 * angular_response(f, cos_beta) + albedo[k];
                EXPECT_NEAR(i[k], c * g, 1e-6 * c * 1367.0 + 1e-12) << fidelity << " " << law << " face " << k;
            }
            EXPECT_NEAR(i[1], 0.0, 1e-12);  // −x: sun behind it, no albedo: dark
        }
    }
}

// The per-face S/H tracks while the gate is on and holds while it is off, as the per-axis one does (seed
// 001 §3). Sun on +z alone: D = 1 − i_load / ΣI ≈ 1 − 0.170 / 0.82 = 0.79, so the gate is off from 0.79 T
// to T. At 0.9 T the sun jumps to +x: the channels keep the +z values until the next period's pulse,
// then follow +x, and hold the +x values over the next off-time. Averaged fidelity has no hold.
TEST(SsrFmu, FaceSampleHoldTracksWhileTheGateIsOnAndHoldsWhileItIsOff) {
    for (const char* fidelity : {"switching", "averaged"}) {
        const bool switching = std::string_view(fidelity) == "switching";
        PlantRun run;
        auto& d = run.data();
        run.set_choice("fidelity", fidelity);
        run.set_choice("angular_response", "cosine");
        d.sun_body = {0.0, 0.0, 1.0};
        run.start();
        const double t0 = 0.1, T = 1.0 / d.pwm_frequency;
        run.step_to(t0 + 0.9 * T);  // t0 is a period start (500 periods)
        if (switching) {
            ASSERT_FALSE(d.gate);
        }
        const auto before = d.i_face_sh;
        EXPECT_GT(before[4], 0.8);
        d.sun_body = {1.0, 0.0, 0.0};
        run.step_to(t0 + 0.95 * T);
        if (switching) {
            EXPECT_FALSE(d.gate);
            EXPECT_EQ(d.i_face_sh, before) << "held while the gate is off";
            EXPECT_GT(d.i_sc[0], 0.8);  // the panel itself already sees the new sun
        } else {
            EXPECT_NEAR(d.i_face_sh[0], d.i_sc[0], 1e-4 * d.i_sc[0]) << "averaged: live";
            EXPECT_NEAR(d.i_face_sh[4], 0.0, 1e-12);
        }
        run.step_to(t0 + 1.05 * T);
        if (switching) {
            EXPECT_TRUE(d.gate);
        }
        EXPECT_NEAR(d.i_face_sh[0], d.i_sc[0], 1e-4 * d.i_sc[0]) << fidelity << ": tracking";
        EXPECT_NEAR(d.i_face_sh[4], 0.0, 1e-12) << fidelity;
        const auto tracked = d.i_face_sh;
        run.step_to(t0 + 1.9 * T);
        if (switching) {
            EXPECT_FALSE(d.gate);
        }
        EXPECT_EQ(d.i_face_sh, tracked) << fidelity << ": held (switching) / constant inputs (averaged)";
        for (int k = 0; k < 3; ++k) EXPECT_EQ(d.i_sh[k], d.i_face_sh[2 * k] - d.i_face_sh[2 * k + 1]);
    }
}

// The currents a sensor slower than the PWM sees (the magnetometer's field of the currents): period
// averages that do not jump at the PWM edges. Switching: D times the shorted panel's current for the shunt
// switch, the shorted current for the cells, on both sides of an edge; averaged: the duty's share of the
// shorted current, and the cells carry what goes to the bus plus what the shunt takes.
TEST(SsrFmu, ShuntAndStringCurrentsArePwmPeriodAverages) {
    const double T = 1.0 / 5000.0, t0 = 0.1;
    const auto start_in_sun_on_z = [](PlantRun& run, const char* fidelity) {
        run.set_choice("fidelity", fidelity);
        run.set_choice("angular_response", "cosine");
        run.data().sun_body = {0.0, 0.0, 1.0};
        run.start();
    };
    {
        PlantRun run;
        auto& d = run.data();
        start_in_sun_on_z(run, "switching");
        run.step_to(t0 + 0.5 * T);  // D ≈ 0.79: gate on, the S/H tracks the shorted currents
        ASSERT_TRUE(d.gate);
        const auto on_shunt = d.i_shunt;
        const auto shorted = d.i_face_sh;
        EXPECT_GT(shorted[4], 0.8);
        for (int k = 0; k < 6; ++k) {
            EXPECT_DOUBLE_EQ(d.i_shunt[k], d.duty * shorted[k]) << "face " << k;
            EXPECT_EQ(d.i_string[k], shorted[k]) << "face " << k;
        }
        run.step_to(t0 + 0.9 * T);  // gate off: the same averages
        ASSERT_FALSE(d.gate);
        EXPECT_EQ(d.i_shunt, on_shunt);
        EXPECT_EQ(d.i_string, shorted);
    }
    {
        PlantRun run;
        auto& d = run.data();
        start_in_sun_on_z(run, "averaged");
        run.step_to(t0);
        ASSERT_GT(d.duty, 0.5);
        for (int k = 0; k < 6; ++k) {
            EXPECT_DOUBLE_EQ(d.i_shunt[k], d.duty * d.i_face_sh[k]) << "face " << k;
            EXPECT_DOUBLE_EQ(d.i_string[k], d.i_panel[k] + d.i_shunt[k]) << "face " << k;
        }
        // A panel at the bus voltage gives less than shorted.
        EXPECT_GT(d.i_panel[4], 0.0);
        EXPECT_LT(d.i_string[4], d.i_face_sh[4]);
    }
}

// Ripple, by hand: over the on-time D T the load alone drains the 1500 µF capacitor, over the off-time the
// panels refill it by as much: peak-to-peak i_load D T / C. Measured on one fixed sun direction, sampled
// every 2 µs over 5 periods after the loop has settled.
TEST(SsrFmu, SwitchingRippleIsTheLoadChargeOfOneOnTime) {
    PlantRun run;
    run.set_choice("angular_response", "cosine");
    run.data().sun_body = seed_sun(0.3);
    run.start();
    run.step_to(0.1);
    double v_min = 1e9, v_max = -1e9;
    for (int k = 1; k <= 500; ++k) {
        run.step_to(0.1 + k * 2e-6);
        v_min = std::min(v_min, run.data().v_bus);
        v_max = std::max(v_max, run.data().v_bus);
    }
    const auto& d = run.data();
    const double expected = d.i_load * d.duty / d.pwm_frequency / d.bus_capacitance;
    std::printf("switching ripple %.5f V peak-to-peak (hand %.5f V, duty %.4f)\n", v_max - v_min, expected, d.duty);
    EXPECT_NEAR(v_max - v_min, expected, 0.03 * expected);  // i_load varies by 0.13 % over the swing
}

// The ripple of one period exactly: while the gate is on the panels are shorted and the battery is behind its
// blocking diode, so the bus is the RC discharge v(t) = v(t_k) e^{−(t − t_k)/(R_L C)} (closed form written
// here), and the peak-to-peak of the period is v(t_k) (1 − e^{−D T/(R_L C)}). The step between PWM edges takes
// this exactly (to 1e-9 V; CVODE at rtol 1e-6 was within ~1e-6 V). Its figure must match the hand ripple
// i_load D T / C above (its linearization: they differ by D T / (2 R_L C) = 0.06 %) to 0.1 %.
TEST(SsrFmu, OnTimeDropIsTheExactRcDischarge) {
    PlantRun run;
    run.set_choice("angular_response", "cosine");
    run.data().sun_body = seed_sun(0.3);
    run.start();
    const auto& d = run.data();
    for (int k = 500; k < 503; ++k) {  // period starts at k T (0.1 s on)
        const double t_k = k / d.pwm_frequency;
        run.step_to(t_k);
        ASSERT_TRUE(d.gate);
        ASSERT_EQ(d.i_batt, 0.0);  // the battery diode blocks: the bus sees the load alone
        const double v_k = d.v_bus, duty = d.duty;
        const double on_time = duty / d.pwm_frequency;
        run.step_to(t_k + 0.5 * on_time);
        EXPECT_NEAR(d.v_bus, v_k * std::exp(-0.5 * on_time / (d.load_resistance * d.bus_capacitance)), 1e-9);
        run.step_to(t_k + on_time);
        const double drop = v_k - d.v_bus;
        const double exact = v_k * -std::expm1(-on_time / (d.load_resistance * d.bus_capacitance));
        EXPECT_NEAR(drop, exact, 1e-9);
        const double hand = v_k / d.load_resistance * on_time / d.bus_capacitance;
        std::printf("period %d: on-time drop %.6f mV (closed form %.6f mV, hand i_load D T / C %.4f mV)\n", k,
                    1e3 * drop, 1e3 * exact, 1e3 * hand);
        EXPECT_NEAR(drop, hand, 1e-3 * hand);
    }
}

// Eclipse load current from the circuit laws alone (KCL at the battery terminal and at the bus, written
// here independently of the core): EMF e behind R_int; from terminal to bus the charge path R_sw (only
// when the charge switch is closed) in parallel with the series diode (V_f, R_d); bus load R_L; the panels
// are dark, so the regulator idles and the battery feeds the load:
//   i (R_L + R_int + 1/(g_sw + g_d)) = e − V_f g_d / (g_sw + g_d),   g = 1/R.
// e is the linear interpolation at soc of Trojan Battery Company's published rested voltages of a 12 V
// lead-acid battery (10 … 100 % in steps of 10 %, typed here from the source; 0 %: 11.30 V) and R_int the
// lead-acid battery's 0.05 Ω (the default chemistry).
double eclipse_load_current(const SsrPlantData& d, double soc, bool connected) {  // declared above
    constexpr std::array<double, 11> trojan = {11.30, 11.51, 11.66, 11.81, 11.96, 12.10,
                                               12.24, 12.37, 12.50, 12.62, 12.73};
    constexpr double r_int = 0.05;
    const double x = soc * 10.0;
    const auto k = static_cast<std::size_t>(x);
    const double e = trojan[k] + (x - static_cast<double>(k)) * (trojan[k + 1] - trojan[k]);
    const double g_sw = connected ? 1.0 / d.charge_path_resistance : 0.0;
    const double g_d = 1.0 / d.battery_diode_resistance;
    return (e - d.battery_diode_forward_voltage * g_d / (g_sw + g_d)) /
           (d.load_resistance + r_int + 1.0 / (g_sw + g_d));
}

void expect_eclipse_rate(double soc_start, bool connected) {
    PlantRun run;
    run.data().irradiance = 0.0;
    run.data().soc_state = soc_start;  // below soc_connect (0.8): switch closed; above: open
    run.start();
    // The 1500 uF bus falls from its 15 V start to the battery's level through the 90 Ohm load in
    // RC ln(15/11.8) = 0.135 s x 0.24 = 33 ms; then the bus follows the battery with C (R_int + R_path)
    // = 0.15 ms. From 0.1 s on the battery alone carries the load.
    run.step_to(0.1);
    const double soc0 = run.data().soc;
    const double i_load = run.data().i_load;
    const double i_expected = eclipse_load_current(run.data(), soc0, connected);
    // The OCV moves by 1.3 V x 2e-5 over the run: the load current stays within 1e-5 relative.
    EXPECT_NEAR(i_load, i_expected, 1e-4 * i_expected);
    EXPECT_NEAR(run.data().i_batt, -i_load, 1e-6);  // bus capacitor current has died out
    run.step_to(1.0);
    const double slope = (run.data().soc - soc0) / 0.9;
    // soc' = i_batt / capacity = −i_load / capacity (seed: coulomb counting). The slope is constant to 1e-5,
    // which BDF integrates exactly; what remains is the integrator's error on a ~1.6e-5 change with
    // absolute tolerance 1e-6 (rtol x nominal 1) — bounded loosely by 2 %.
    const double predicted = -i_expected / run.data().battery_capacity;
    EXPECT_NEAR(slope, predicted, 0.02 * std::abs(predicted));
    std::printf("eclipse soc %.2f (%s): i_load %.6f A (hand %.6f), soc slope %.6e /s (predicted %.6e)\n", soc_start,
                connected ? "switch closed" : "switch open", i_load, i_expected, slope, predicted);
}

TEST(SsrFmu, EclipseBatteryConnectedCarriesTheLoadAtThePredictedRate) {
    expect_eclipse_rate(0.75, true);
}

TEST(SsrFmu, EclipseBatteryThroughItsDiodeCarriesTheLoadAtThePredictedRate) {
    expect_eclipse_rate(0.85, false);
}

// The hysteresis charge switch through the FMU: a lithium-ion battery (no charge polarization) of 7.2 C
// (2 mAh, so that it fills in seconds) starting at soc 0.79 (below soc_connect 0.8: switch closed) charges
// from the 15.28 V bus through its 5 Ω path, ~(15.28 − 11.8) / (5 + 0.22) = 0.67 A, i.e. soc' ≈ 0.09 /s
// (charge efficiency 0.99): at soc_disconnect 0.95 (below the 12.3 V charger limit's taper) after ~2 s. Then
// exactly one state event opens the switch, the diode blocks (bus above battery) and soc stays there.
void expect_charge_cycle(const char* fidelity) {
    PlantRun run;
    auto& d = run.data();
    run.set_choice("fidelity", fidelity);
    run.set_choice("battery_chemistry", "lithium_ion");
    d.sun_body = {0.0, 0.0, 1.0};
    d.battery_capacity = 7.2;
    d.soc_disconnect = 0.95;
    d.soc_state = 0.79;
    run.start();
    run.step_to(0.5);
    EXPECT_GT(d.i_batt, 0.4) << fidelity;  // charging at about C/3 of the real battery
    EXPECT_EQ(run.solver->statistics().state_events, 0) << fidelity;
    run.step_to(5.0);
    EXPECT_EQ(run.solver->statistics().state_events, 1) << fidelity;
    EXPECT_NEAR(d.soc, 0.95, 1e-6) << fidelity;  // stopped at the threshold, located by CVODE's root finding
    EXPECT_EQ(d.i_batt, 0.0) << fidelity;
    const double soc_full = d.soc;
    run.step_to(6.0);
    EXPECT_EQ(d.soc, soc_full) << fidelity;
    EXPECT_EQ(run.solver->statistics().state_events, 1) << fidelity;  // no chattering at the threshold
}

TEST(SsrFmu, ChargeSwitchOpensOnceAtFullCharge) {
    expect_charge_cycle("averaged");
    expect_charge_cycle("switching");
}

// Every parameter's default is the core's (written once, in parameters.hpp), but for angular_response,
// which the FMU sets to the measured Kelly response on purpose.
TEST(SsrFmu, ParameterDefaultsAreTheCores) {
    const SsrPlantData d{};
    const Parameters core{};
    EXPECT_EQ(d.fidelity, core.fidelity);
    EXPECT_EQ(d.modulation, core.modulation);
    EXPECT_EQ(d.angular_response, AngularResponse::kelly);
    EXPECT_EQ(d.panel_isc, core.panel.short_circuit_current);
    EXPECT_EQ(d.panel_voc, core.panel.open_circuit_voltage);
    EXPECT_EQ(d.cell_temperature, core.panel.cell_temperature);
    EXPECT_EQ(d.controller_gain, core.controller_gain);
    EXPECT_EQ(d.pwm_frequency, core.pwm_frequency);
    EXPECT_EQ(d.battery_chemistry, core.battery.chemistry);
    EXPECT_EQ(d.battery_capacity, core.battery.capacity);
    EXPECT_EQ(d.charge_control, core.battery.charge_control);
    EXPECT_EQ(core.faults, FaultParameters{});  // no fault by default
    EXPECT_EQ(d.fault_string_open_face, no_fault_face);
    EXPECT_EQ(d.fault_cell_short_face, no_fault_face);
    EXPECT_EQ(d.fault_degradation_face, no_fault_face);
    EXPECT_EQ(d.fault_shadow_face, no_fault_face);
    EXPECT_EQ(d.fault_switch_face, no_fault_face);
    EXPECT_EQ(d.fault_hall_face, no_fault_face);
    EXPECT_EQ(d.fault_appendage_face, no_fault_face);
    EXPECT_EQ(d.fault_appendage_box, core.faults.appendage_box);
    EXPECT_EQ(d.fault_cell_short_cells, core.faults.shorted_cells);
    // The block's parameters() hands every field to the core unchanged: a default-constructed block
    // describes the core's default plant but for the angular response.
    EXPECT_EQ(Inputs{}.irradiance, d.irradiance);
}

// A load step mid-run (load_resistance is tunable): the cached model must follow. Averaged fidelity, the
// sun on +z: in steady state the panels' current into the bus equals the new load's V / R (KCL at the bus,
// battery idle) and the duty is the P law 3 (V − 15).
TEST(SsrFmu, LoadStepRefitsTheCachedModel) {
    PlantRun run;
    run.set_choice("fidelity", "averaged");
    run.data().sun_body = {0.0, 0.0, 1.0};
    run.start();
    run.step_to(0.2);
    const double v90 = run.data().v_bus;
    EXPECT_NEAR(run.data().i_load, v90 / 90.0, 1e-12);
    run.data().load_resistance = 45.0;
    run.parameters_changed();  // what fmi2SetReal of a tunable parameter does
    run.step_to(0.4);
    const auto& d = run.data();
    EXPECT_NEAR(d.i_load, d.v_bus / 45.0, 1e-12);
    double into_bus = 0.0;
    for (double i : d.i_panel) into_bus += i;
    EXPECT_NEAR(into_bus, d.v_bus / 45.0, 1e-6);
    EXPECT_NEAR(d.duty, 3.0 * (d.v_bus - 15.0), 1e-9);
    EXPECT_LT(d.v_bus, v90);  // twice the load: less to shunt, lower duty, lower bus
}

// An FMU-state restore across a parameter change: the restored bytes bring back their parameters, and
// the block is configured for them again. The run after the restore equals, bit for bit,
// a run continued from a copy of the saved block.
TEST(SsrFmu, RestoreAcrossAParameterChangeUsesTheRestoredParameters) {
    PlantRun run;
    run.data().sun_body = seed_sun(0.7);
    run.start();
    run.step_to(0.01);
    const auto saved = run.runner.model().clone();
    const double t_saved = run.runner.time();
    run.data().bus_voltage_reference = 14.0;  // as if set between save and restore (a reset, another run)
    run.parameters_changed();
    run.step_to(0.02);
    EXPECT_LT(run.data().v_bus, 14.5);  // the change took effect: regulated near 14 + D/3
    run.runner.restore(*saved, t_saved);
    run.step_to(0.03);

    PlantRun copy;
    copy.runner.restore(*saved, t_saved);
    copy.solver = std::make_unique<fmu::CsSolver>(copy.runner, 1e-6);
    copy.step_to(0.03);
    EXPECT_EQ(run.data().bus_voltage_reference, 15.0);
    EXPECT_EQ(run.data().v_bus, copy.data().v_bus);
    EXPECT_EQ(run.data().duty, copy.data().duty);
    EXPECT_GT(run.data().v_bus, 15.0);  // regulated to the restored 15 V reference, not 14 V
}

TEST(SsrFmu, InputsAreCheckedAndParametersValidated) {
    PlantRun run;
    run.data().irradiance = -1.0;
    EXPECT_THROW(run.start(), fmu::Error);
    PlantRun bad;
    bad.data().soc_connect = 0.95;
    bad.data().soc_disconnect = 0.9;
    EXPECT_THROW(bad.start(), fmu::Error);
    PlantRun inconsistent;
    inconsistent.data().panel_imp = 0.7;             // above the short-circuit current: no single-diode fit
    EXPECT_THROW(inconsistent.start(), fmu::Error);  // configure() at exit of initialization
}

// The seed's 300 per volt (000 §4) with the default latched_natural modulator and in averaged fidelity:
// 0.5 s of the seed spin (cosine panels), bus sampled every 0.1 ms over 0.1–0.5 s.
struct BusFigures {
    double mean = 0.0, min = 1e9, max = -1e9;
};
BusFigures seed_bus_at_300_per_volt(const char* fidelity) {
    PlantRun run(false);  // the block's defaults: 300 per volt, latched_natural
    run.set_choice("fidelity", fidelity);
    run.set_choice("angular_response", "cosine");
    run.data().sun_body = seed_sun(0.0);
    run.start();
    BusFigures b;
    int n = 0;
    for (int k = 1; k <= 5000; ++k) {
        const double t0 = (k - 1) * 1e-4;
        run.data().sun_body = seed_sun(t0);
        run.step_to(k * 1e-4);
        if (k * 1e-4 < 0.1) continue;
        const double v = run.data().v_bus;
        b.mean += v;
        b.min = std::min(b.min, v);
        b.max = std::max(b.max, v);
        ++n;
    }
    b.mean /= n;
    std::printf("seed spin at 300 /V, %s: v_bus mean %.4f V, min %.4f, max %.4f (peak to peak %.1f mV)\n", fidelity,
                b.mean, b.min, b.max, 1e3 * (b.max - b.min));
    return b;
}

// A string opening mid-step through the runtime (the parameters a .ssd or --set gives): the onset is a
// time event, so the solver stops there and the bus sees the loss from that instant on. Averaged fidelity,
// the sun on +x; the string closes again at its end.
TEST(SsrFmuFaults, StringOpensAndClosesAtItsTimeEvents) {
    PlantRun run(false);
    run.set_choice("fidelity", "averaged");
    run.data().sun_body = {1.0, 0.0, 0.0};
    run.data().fault_string_open_face = 1;
    run.data().fault_string_open_onset = 0.0123;
    run.data().fault_string_open_end = 0.0456;
    run.parameters_changed();
    run.start();
    EXPECT_EQ(run.block().next_time_event(), 0.0123);
    run.step_to(0.0122);
    EXPECT_GT(run.data().i_sc[0], 0.6);
    run.step_to(0.02);  // across the onset: one communication step holding the time event
    EXPECT_EQ(run.data().i_sc[0], 0.0);
    EXPECT_EQ(run.data().i_face_sh[0], 0.0);
    EXPECT_EQ(run.data().i_panel[0], 0.0);
    EXPECT_EQ(run.block().next_time_event(), 0.0456);
    run.step_to(0.05);
    EXPECT_GT(run.data().i_sc[0], 0.6);
    EXPECT_EQ(run.block().next_time_event(), fmu::no_time_event);
}

// A bad fault parameter is refused with the parameter's name.
TEST(SsrFmuFaults, RefusesAnEndBeforeTheOnset) {
    PlantRun run;
    run.data().fault_shadow_face = 2;
    run.data().fault_shadow_onset = 10.0;
    run.data().fault_shadow_end = 5.0;
    run.parameters_changed();
    try {
        run.start();
        FAIL() << "accepted an end before the onset";
    } catch (const fmu::Error& e) {
        EXPECT_NE(std::string_view(e.what()).find("fault_shadow_end"), std::string_view::npos) << e.what();
    }
}

TEST(SsrFmuModulation, AveragedBusSitsAtTheReferencePlusDOverK) {
    // By hand (the bus band above with K = 300 /V): D ∈ [0.793, 0.885] → v = 15 + D/300 ∈ [15.00264,
    // 15.00295] V; the averaged plant has no ripple.
    const BusFigures b = seed_bus_at_300_per_volt("averaged");
    EXPECT_GT(b.min, 15.00264 - 2e-5);
    EXPECT_LT(b.max, 15.00295 + 2e-5);
}

TEST(SsrFmuModulation, LatchedNaturalModulatorHoldsTheSeedsFifteenVolts) {
    // Reference outside this code (issue 19's independent re-computation of the seed's circuit with a
    // latched trailing-edge modulator at 300 /V): bus 15.04 V with a period-doubling sub-harmonic of
    // 145 mV peak to peak. Bounds: ±0.02 V on the mean, ±25 mV on the swing; and the swing stays above the
    // reference (the comparator only turns the shunt on above it) and far below the regular modulator's
    // 0/1 limit cycle at this gain.
    const BusFigures b = seed_bus_at_300_per_volt("switching");
    EXPECT_NEAR(b.mean, 15.04, 0.02);
    EXPECT_NEAR(b.max - b.min, 0.145, 0.025);
    EXPECT_GT(b.min, 14.99);
}

}  // namespace
}  // namespace ssr_plant
