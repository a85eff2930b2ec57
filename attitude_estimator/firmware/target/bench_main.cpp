// The firmware's figures, run under QEMU with -icount (scripts/pil.sh --bench): instructions per 20 Hz
// sample for each sun method, solver and the filter, and the deepest stack. A sample is the board's whole
// answer to a request frame (decode, the computer in float, encode), as main.cpp runs it, on a spinning,
// lit scene. Counted with SysTick, which QEMU clocks from its virtual time: with -icount shift=0 every
// instruction is 1 ns, so ticks convert to instructions (calibrated below on a loop of known length).
// QEMU counts instructions, not cycles: the Cortex-M4F takes 1 cycle for most, 2 for loads, 14 for a
// division or square root in the FPU, so cycles are somewhat more than the instructions printed.
#include <array>
#include <cmath>
#include <cstdint>

#include "attitude_estimator/onboard_references.hpp"
#include "cmsdk_uart.hpp"
#include "estimator_board.hpp"
#include "leo_orbit_as_bundled.hpp"
#include "orbit/tle.hpp"
#include "protocol/frame_codec.hpp"
#include "stack_paint.hpp"

namespace {

using attitude_estimator::EstimatorData;

volatile std::uint32_t& reg(std::uintptr_t address) {
    return *reinterpret_cast<volatile std::uint32_t*>(address);
}
constexpr std::uintptr_t kSystCsr = 0xE000E010, kSystRvr = 0xE000E014, kSystCvr = 0xE000E018;

firmware::CmsdkUart* uart = nullptr;

void print(const char* s) {
    while (*s) uart->put(static_cast<std::uint8_t>(*s++));
}
void print(std::uint64_t x) {
    char buf[24];
    int n = 0;
    do {
        buf[n++] = static_cast<char>('0' + x % 10);
        x /= 10;
    } while (x);
    while (n) uart->put(static_cast<std::uint8_t>(buf[--n]));
}

void systick_start() {
    reg(kSystRvr) = 0xFFFFFF;
    reg(kSystCvr) = 0;
    reg(kSystCsr) = 0x5;  // enabled, processor clock, no interrupt
}
std::uint32_t systick() {
    return reg(kSystCvr);
}
std::uint32_t ticks_between(std::uint32_t start, std::uint32_t end) {
    return (start - end) & 0xFFFFFF;
}

// Ticks per million instructions, from a loop of two instructions per turn.
std::uint32_t calibrate() {
    std::uint32_t n = 500000;
    const std::uint32_t start = systick();
    asm volatile("1: subs %0, %0, #1\n bne 1b" : "+r"(n));
    return ticks_between(start, systick());  // for 1,000,000 instructions
}

// Inputs of sample k: a body spinning about a tilted axis, sun and field fixed in inertial axes, face
// currents by the cosine law with a little albedo on one face, the HMC2003's voltages in the set/reset
// polarity the computer last commanded (+1 set, as at power-up; without the pulses it stays set).
void scene(EstimatorData& d, int k, double polarity) {
    const double t = 0.05 * k;
    const double a = 1.26 * t, b = 0.4 + 0.3 * std::sin(0.7 * t);
    auto to_body = [&](const std::array<double, 3>& v) {
        const double x1 = std::cos(a) * v[0] + std::sin(a) * v[1], y1 = -std::sin(a) * v[0] + std::cos(a) * v[1];
        return std::array<double, 3>{x1, std::cos(b) * y1 + std::sin(b) * v[2], -std::sin(b) * y1 + std::cos(b) * v[2]};
    };
    d.sun_ref = {0.6, 0.64, 0.48};
    d.mag_ref = {18e-6, -9e-6, 24e-6};
    const auto s = to_body(d.sun_ref), m = to_body(d.mag_ref);
    const double i0 = attitude_estimator::kPanelCurrentAt1Au<double>;
    for (std::size_t i = 0; i < 3; ++i) {
        d.i_sh[i] = i0 * s[i];
        d.i_face[2 * i] = i0 * std::max(0.0, s[i]) + (i == 1 ? 0.02 : 0.0);
        d.i_face[2 * i + 1] = i0 * std::max(0.0, -s[i]);
        d.v_mag[i] = 2.5 + polarity * 1e4 * m[i] + 0.003;
    }
    d.v_mag_ref = 2.5;
    d.sun_distance = 1.495978707e11;
}

// The board's request frame for sample k (inputs in wire order).
std::size_t request(int k, double polarity, std::span<std::uint8_t> out) {
    static EstimatorData d;
    scene(d, k, polarity);
    std::array<double, attitude_estimator::wire::kInputCount> in{};
    // wire::set_input's inverse: inputs by reading them back from a data struct through the outputs is not
    // possible, so the order is rebuilt here from the same scene as the table's (i_sh, i_face, v_mag,
    // v_mag_ref, sun_ref, mag_ref, sun_distance: value-reference order, checked by the host test).
    std::size_t n = 0;
    for (double x : d.i_sh) in[n++] = x;
    for (double x : d.i_face) in[n++] = x;
    for (double x : d.v_mag) in[n++] = x;
    in[n++] = d.v_mag_ref;
    for (double x : d.sun_ref) in[n++] = x;
    for (double x : d.mag_ref) in[n++] = x;
    in[n++] = d.sun_distance;
    const bridge::FrameHeader h{.type = bridge::FrameType::request,
                                .sequence = static_cast<std::uint32_t>(k + 1),
                                .time = 0.05 * k,
                                .count = attitude_estimator::wire::kInputCount};
    return bridge::encode_frame(h, in, out);
}

attitude_estimator::EstimatorBoard board;
std::array<std::uint8_t, bridge::max_frame_size> frame, reply;

struct Case {
    const char* name;
    void (*edit)(EstimatorData&);
};

void run(const Case& c, std::uint32_t ticks_per_million) {
    using namespace attitude_estimator;
    static EstimatorData d;
    firmware::bench_case_start(d);
    c.edit(d);
    for (std::size_t first = 0; first < wire::kParameterCount; first += bridge::max_values) {
        std::array<double, bridge::max_values> values{};
        std::size_t n = 0;
        for (std::size_t p = first; p < wire::kParameterCount && n < values.size(); ++p)
            values[n++] = wire::parameter(d, p);
        const bridge::FrameHeader h{.type = bridge::FrameType::configure,
                                    .sequence = static_cast<std::uint32_t>(first),
                                    .time = static_cast<double>(wire::kParameterCount),
                                    .count = n};
        const std::size_t size = bridge::encode_frame(h, std::span(values).first(n), frame);
        board.answer(std::span(frame).first(size), reply);
    }
    constexpr int kSamples = 200;
    std::uint64_t first = 0, total = 0, worst = 0, computer_first = 0, computer_total = 0, computer_worst = 0;
    std::uint64_t last_rate_mrad = 0;
    double polarity = 1.0;  // the sensor's: set at power-up, then as the computer commands (out.mag_set_reset)
    int answered = 0, mismatches = 0;
    // The computer alone (onboard_sample), beside the board's whole answer: the rest is the frame codec
    // (22 inputs and 57 outputs as f64, soft-float on this FPU, and a bitwise CRC) and the conversions.
    const OnboardSettings<float> settings = onboard_settings_from<float>(d);
    static OnboardState<float> state;
    onboard_start(state, settings);
    for (int k = 0; k < kSamples; ++k) {
        const std::size_t size = request(k, polarity, frame);
        const std::uint32_t start = systick();
        const std::size_t n = board.answer(std::span(frame).first(size), reply);
        const std::uint64_t ticks = ticks_between(start, systick());  // 64 bits: times 10^6 below
        answered += n > 0;
        const std::uint64_t instructions = ticks * 1000000u / ticks_per_million;
        // The first sample also starts the run (the cones' tables, the filter's initialisation): counted
        // apart, so that the mean and the worst are over the same 199 steady samples.
        if (k == 0) {
            first = instructions;
        } else {
            total += instructions;
            if (instructions > worst) worst = instructions;
        }
        scene(d, k, polarity);
        const OnboardInputs<float> in = onboard_inputs_from<float>(d);
        const std::uint32_t c0 = systick();
        const OnboardOutputs<float> out = onboard_sample(state, in, settings, static_cast<float>(0.05 * k));
        const std::uint64_t computer =
            static_cast<std::uint64_t>(ticks_between(c0, systick())) * 1000000u / ticks_per_million;
        asm volatile("" : : "r"(&out) : "memory");  // the result is used
        polarity = out.mag_set_reset ? 1.0 : -1.0;
        // The filter's rate at the last sample, mrad/s: its propagation takes a substep per 0.05 rad of turn
        // (mekf.cpp), so what a sample costs depends on the rate the filter believes.
        last_rate_mrad = static_cast<std::uint64_t>(1e3f * std::sqrt(out.omega_filt[0] * out.omega_filt[0] +
                                                                     out.omega_filt[1] * out.omega_filt[1] +
                                                                     out.omega_filt[2] * out.omega_filt[2]));
        bridge::FrameHeader rh;
        if (bridge::decode_frame(std::span(reply).first(n), rh) == bridge::DecodeStatus::ok &&
            static_cast<float>(bridge::frame_value(reply, 3)) != out.sample.q.w)
            ++mismatches;
        if (k == 0) {
            computer_first = computer;
        } else {
            computer_total += computer;
            if (computer > computer_worst) computer_worst = computer;
        }
    }
    print(c.name);
    print(" samples=");
    print(static_cast<std::uint64_t>(answered));
    print(" first_instructions=");
    print(first);
    print(" mean_instructions=");
    print(total / (kSamples - 1));
    print(" max_instructions=");
    print(worst);
    print(" differing=");  // samples where the board's q_est differs from the computer's (expected 0)
    print(static_cast<std::uint64_t>(mismatches));
    print(" computer_first=");
    print(computer_first);
    print(" computer_mean=");
    print(computer_total / (kSamples - 1));
    print(" computer_max=");
    print(computer_worst);
    print(" filter_rate_mrad_s=");
    print(last_rate_mrad);
    print("\n");
}

// The on-board references (onboard_references.hpp) in float: one evaluation of each model and of all three
// (what a sample that passes a knot of the reference grid adds, twice at the first sample), and the
// per-sample interpolation between knots. The element set is leo_orbit's kind (570 km, 64.9°), given as
// the numbers of its two lines (the board parses no text).
template <class F>
std::uint64_t instructions_of(F&& f, std::uint32_t ticks_per_million, int repeat) {
    std::uint64_t worst = 0;
    for (int k = 0; k < repeat; ++k) {
        const std::uint32_t start = systick();
        f(k);
        const std::uint64_t n =
            static_cast<std::uint64_t>(ticks_between(start, systick())) * 1000000u / ticks_per_million;
        if (n > worst) worst = n;
    }
    return worst;
}

void bench_references(std::uint32_t ticks_per_million) {
    using namespace attitude_estimator;
    orbit::Tle tle;
    tle.epoch_jd_utc = 2461119.5;  // 2026-03-20 00:00 UTC
    tle.mean_motion_rev_per_day = 14.98996383;
    tle.eccentricity = 0.001;
    tle.inclination_deg = 64.9;
    tle.raan_deg = 120.0;
    tle.arg_perigee_deg = 90.0;
    tle.mean_anomaly_deg = 270.0;
    tle.bstar_per_earth_radius = 3.0e-5;
    const CalendarInstant epoch{.year = 2026, .month = 3, .day = 21, .hour = 0, .minute = 0, .second = 0.0};
    for (const std::int32_t degree : {1, 8, 13}) {
        static OnboardReferenceConfig<float> config;
        make_reference_config(config, epoch, tle.mean_elements<double>(), tle.epoch_jd_utc, degree, 10.0);
        volatile float sink = 0.0f;
        const std::uint64_t all =
            instructions_of([&](int k) { sink = evaluate_references(config, 10.0f * static_cast<float>(k)).field[0]; },
                            ticks_per_million, 20);
        const std::uint64_t field = instructions_of(
            [&](int k) {
                const Vec3<float> r{6948e3f * std::cos(0.3f * k), 0.0f, 6948e3f * std::sin(0.3f * k)};
                sink = field_ecef(config.field, r, 2026.2f)[0];
            },
            ticks_per_million, 20);
        print("references_degree_");
        print(static_cast<std::uint64_t>(degree));
        print(" evaluation_max_instructions=");
        print(all);
        print(" field_max_instructions=");
        print(field);
        if (degree == 8) {
            orbit::OrbitState<float> state;
            const std::uint64_t sgp4 = instructions_of(
                [&](int k) {
                    config.orbit.propagate(1440.0f + 0.5f * static_cast<float>(k), state);
                    sink = state.position_km[0];
                },
                ticks_per_million, 20);
            const std::uint64_t sun = instructions_of(
                [&](int k) { sink = onboard_sun(config.clock, 10.0f * static_cast<float>(k)).direction[0]; },
                ticks_per_million, 20);
            static ReferenceState<float> state_between;
            onboard_references(state_between, config, 0.0f);
            const std::uint64_t between = instructions_of(
                [&](int k) {
                    sink = onboard_references(state_between, config, 0.05f * static_cast<float>(k + 1)).sun[0];
                },
                ticks_per_million, 150);
            print(" sgp4_max_instructions=");
            print(sgp4);
            print(" sun_max_instructions=");
            print(sun);
            print(" interpolation_max_instructions=");
            print(between);
        }
        print("\n");
    }
}

[[noreturn]] void semihosting_exit() {
    // SYS_EXIT with ADP_Stopped_ApplicationExit: QEMU (-semihosting-config enable=on) ends.
    register std::uint32_t r0 asm("r0") = 0x18;
    register std::uint32_t r1 asm("r1") = 0x20026;
    asm volatile("bkpt 0xAB" : : "r"(r0), "r"(r1) : "memory");
    for (;;) {}
}

}  // namespace

int main() {
    using namespace attitude_estimator;
    firmware::CmsdkUart u(0x40004000, 217);
    uart = &u;
    systick_start();
    const std::uint32_t ticks_per_million = calibrate();
    print("calibration ticks_per_million_instructions=");
    print(ticks_per_million);
    print("\n");
    const Case cases[] = {
        {"difference_qmethod", [](EstimatorData&) {}},
        {"difference_fast", [](EstimatorData& d) { d.solver = SolverKind::fast; }},
        {"inverse_response_qmethod", [](EstimatorData& d) { d.sun_method = SunMethod::inverse_response; }},
        {"cones_qmethod", [](EstimatorData& d) { d.sun_method = SunMethod::cones; }},
        {"cones_fast",
         [](EstimatorData& d) {
             d.sun_method = SunMethod::cones;
             d.solver = SolverKind::fast;
         }},
        {"three_faces_qmethod", [](EstimatorData& d) { d.sun_method = SunMethod::three_faces; }},
        {"difference_qmethod_mekf", [](EstimatorData& d) { d.filter = FilterKind::mekf; }},
        {"difference_qmethod_mekf_onboard_references",
         [](EstimatorData& d) {
             d.filter = FilterKind::mekf;
             d.reference_source = ReferenceSource::onboard;  // degree 8, a knot every 10 s (200 samples)
             d.tle_elements = {2461118.5, 14.98524078, 0.0012, 64.9, 3.1277, 90.376, 275.3137, 1.5e-4};
         }},
        // Issue 28: the orbit's computer with set/reset pulses, without and with the fault detection.
        {"difference_qmethod_mekf_onboard_references_setreset",
         [](EstimatorData& d) {
             d.filter = FilterKind::mekf;
             d.reference_source = ReferenceSource::onboard;
             d.tle_elements = {2461118.5, 14.98524078, 0.0012, 64.9, 3.1277, 90.376, 275.3137, 1.5e-4};
             d.mag_set_reset_samples = 1;
         }},
        {"difference_qmethod_mekf_onboard_references_setreset_detect",
         [](EstimatorData& d) {
             d.filter = FilterKind::mekf;
             d.reference_source = ReferenceSource::onboard;
             d.tle_elements = {2461118.5, 14.98524078, 0.0012, 64.9, 3.1277, 90.376, 275.3137, 1.5e-4};
             d.mag_set_reset_samples = 1;
             d.detect_faults = true;
         }},
        // Issue 39: the filter with the 3U's torques (dipole and gravity gradient) as first bundled, without and
        // with the fault detection, then leo_orbit as bundled now (the drag on board, the tuned noise, the
        // ground calibration), without and with the detection (on as bundled).
        {"difference_qmethod_mekf_onboard_references_setreset_torques",
         [](EstimatorData& d) { firmware::leo_orbit_3u(d, false, true); }},
        {"difference_qmethod_mekf_onboard_references_setreset_torques_detect",
         [](EstimatorData& d) { firmware::leo_orbit_3u(d, true, true); }},
        {"leo_orbit_detect_off", [](EstimatorData& d) { firmware::leo_orbit_3u(d, false, false); }},
        {"leo_orbit_as_bundled", [](EstimatorData& d) { firmware::leo_orbit_3u(d, true, false); }},
        {"cones_qmethod_mekf_scale_setreset",
         [](EstimatorData& d) {
             d.sun_method = SunMethod::cones;
             d.filter = FilterKind::mekf;
             d.filter_scale = true;
             d.mag_set_reset_samples = 1;
         }},
    };
    for (const Case& c : cases) run(c, ticks_per_million);
    bench_references(ticks_per_million);
    print("stack_bytes=");
    print(static_cast<std::uint64_t>(firmware::stack_used()));
    print("\n");
    semihosting_exit();
}
