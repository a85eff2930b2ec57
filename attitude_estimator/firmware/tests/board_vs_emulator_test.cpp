// The firmware's board program (board/estimator_board.cpp) on the host against the board emulator running
// attitude_estimator.fmu's block with precision = float: the same frames in, the same reply bytes out.
// The two share the core and the parameter conversions but not the code around them (the emulator drives
// the FMU block through the runtime; the board reads the generated wire table), so this checks the
// firmware's sequencing, parameter order and output order against the block's own.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <ostream>
#include <vector>

#include "attitude_estimator/estimator_block.hpp"
#include "emulator/board_emulator.hpp"
#include "estimator_board.hpp"
#include "fmu/value_access.hpp"
#include "protocol/frame.hpp"

namespace attitude_estimator {
namespace {

// The FMU's parameter values, as the master sends them in configure frames (value-reference order).
std::vector<double> parameter_values(const fmu::TableBase& table, const EstimatorData& d) {
    std::vector<const fmu::Variable*> params;
    for (const auto& v : table.variables())
        if (v.causality == fmu::Causality::parameter && v.type != fmu::ValueType::String) params.push_back(&v);
    std::sort(params.begin(), params.end(), [](auto* a, auto* b) { return a->value_reference < b->value_reference; });
    std::vector<double> out;
    const auto bytes = std::as_bytes(std::span(&d, 1));
    for (const auto* v : params) out.push_back(fmu::read_number(bytes, *v));
    return out;
}

// Inputs of sample k of a scene: a body spinning about a tilted axis, the sun and a field in inertial axes,
// face currents by the cosine law plus a little albedo on one face, the HMC2003's voltages.
std::vector<double> scene_inputs(int k) {
    const double t = 0.05 * k;
    const double a = 1.26 * t, b = 0.4 + 0.3 * std::sin(0.7 * t);
    // Body axes: a rotation by a about z, then by b about x (inertial -> body).
    auto to_body = [&](const std::array<double, 3>& v) {
        const double x1 = std::cos(a) * v[0] + std::sin(a) * v[1], y1 = -std::sin(a) * v[0] + std::cos(a) * v[1];
        const double z1 = v[2];
        return std::array<double, 3>{x1, std::cos(b) * y1 + std::sin(b) * z1, -std::sin(b) * y1 + std::cos(b) * z1};
    };
    const std::array<double, 3> sun_ref{0.6, 0.64, 0.48}, mag_ref{18e-6, -9e-6, 24e-6};
    const auto s = to_body(sun_ref), m = to_body(mag_ref);
    const double i0 = kPanelCurrentAt1Au<double>;
    std::vector<double> in;
    for (int i = 0; i < 3; ++i) in.push_back(i0 * s[static_cast<std::size_t>(i)]);  // i_sh
    for (int i = 0; i < 3; ++i) {                                                   // i_face +x, -x, ...
        in.push_back(i0 * std::max(0.0, s[static_cast<std::size_t>(i)]) + (i == 2 ? 0.02 : 0.0));
        in.push_back(i0 * std::max(0.0, -s[static_cast<std::size_t>(i)]));
    }
    for (int i = 0; i < 3; ++i) in.push_back(2.5 + 1e4 * m[static_cast<std::size_t>(i)] + 0.003);  // v_mag
    in.push_back(2.5);                                                                             // v_mag_ref
    for (double x : sun_ref) in.push_back(x);
    for (double x : mag_ref) in.push_back(x);
    in.push_back(1.495978707e11 * 0.99);  // sun_distance
    return in;
}

// Index of output `name` in a reply (value-reference order).
std::size_t output_index(const fmu::TableBase& table, const std::string& name) {
    std::vector<const fmu::Variable*> outs;
    for (const auto& v : table.variables())
        if (v.causality == fmu::Causality::output) outs.push_back(&v);
    std::sort(outs.begin(), outs.end(), [](auto* a, auto* b) { return a->value_reference < b->value_reference; });
    for (std::size_t i = 0; i < outs.size(); ++i)
        if (outs[i]->name == name) return i;
    throw std::runtime_error("no output " + name);
}

struct Case {
    const char* name;
    void (*edit)(EstimatorData&);
};

// The case's name in test listings (gtest would print the struct's bytes, pointers included).
void PrintTo(const Case& c, std::ostream* out) {
    *out << c.name;
}

class BoardVsEmulator : public ::testing::TestWithParam<Case> {};

TEST_P(BoardVsEmulator, RepliesAreByteIdentical) {
    auto block = std::make_unique<EstimatorBlock>();
    const auto& table = block->table();
    EstimatorData d;
    d.precision = Precision::single_precision;
    d.spin_window = 0;
    GetParam().edit(d);
    const std::vector<double> params = parameter_values(table, d);
    const std::size_t valid = output_index(table, "valid"), filter_valid = output_index(table, "filter_valid");
    int valid_replies = 0, filter_valid_replies = 0;

    bridge::BoardEmulator emulator(std::move(block));
    ASSERT_EQ(emulator.input_count(), wire::kInputCount);
    ASSERT_EQ(emulator.output_count(), wire::kOutputCount);
    ASSERT_EQ(emulator.parameter_count(), wire::kParameterCount);
    static EstimatorBoard board;  // 60 kB: not on the stack
    board = EstimatorBoard{};
    std::vector<std::uint8_t> reply(bridge::max_frame_size);

    // The configuration in two frames, as the master splits a long one.
    for (std::size_t first = 0; first < params.size(); first += 40) {
        bridge::Frame c;
        c.type = bridge::FrameType::configure;
        c.sequence = static_cast<std::uint32_t>(first);
        c.time = static_cast<double>(params.size());
        c.values.assign(params.begin() + static_cast<long>(first),
                        params.begin() + static_cast<long>(std::min(params.size(), first + 40)));
        const auto bytes = bridge::encode(c);
        const auto expected = bridge::encode(emulator.answer(bridge::decode(bytes)));
        const std::size_t n = board.answer(bytes, reply);
        ASSERT_EQ(std::vector<std::uint8_t>(reply.begin(), reply.begin() + static_cast<long>(n)), expected)
            << "configure frame at " << first;
    }
    // Two runs: the second (sequence 1 again) must start over exactly as the first.
    for (int run = 0; run < 2; ++run)
        for (int k = 0; k < 120; ++k) {
            bridge::Frame r;
            r.sequence = static_cast<std::uint32_t>(k + 1);
            r.time = 0.05 * k;
            r.values = scene_inputs(k + 7 * run);
            const auto bytes = bridge::encode(r);
            const auto expected = bridge::encode(emulator.answer(bridge::decode(bytes)));
            const std::size_t n = board.answer(bytes, reply);
            ASSERT_EQ(std::vector<std::uint8_t>(reply.begin(), reply.begin() + static_cast<long>(n)), expected)
                << GetParam().name << ": run " << run << ", sample " << k;
            const bridge::Frame answer = bridge::decode(expected);
            valid_replies += answer.values[valid] != 0.0;
            filter_valid_replies += answer.values[filter_valid] != 0.0;
        }
    // The scene is lit and well conditioned: the estimates are valid, and the filter runs where chosen.
    EXPECT_GT(valid_replies, 100) << GetParam().name;  // of 240 (three_faces needs three lit faces)
    // The filter's start covariance carries the field offset's error in the single-frame attitude (docs/filter.md,
    // "The start"): with the on-board references' hard-iron prior its 3σ bound falls below 10° about 3 s into
    // each 6 s run, so about half the replies are filter-valid.
    if (d.filter == FilterKind::mekf) {
        EXPECT_GT(filter_valid_replies, 100) << GetParam().name;
    }
    EXPECT_EQ(board.refused(), 0);
    EXPECT_EQ(board.samples(), 120);
}

INSTANTIATE_TEST_SUITE_P(Configurations, BoardVsEmulator,
                         ::testing::Values(Case{"seed", [](EstimatorData&) {}},
                                           Case{"fast_cones_mekf",
                                                [](EstimatorData& d) {
                                                    d.solver = SolverKind::fast;
                                                    d.sun_method = SunMethod::cones;
                                                    d.filter = FilterKind::mekf;
                                                    d.filter_scale = true;
                                                    d.mag_set_reset_samples = 1;
                                                }},
                                           Case{"three_faces_kelly",
                                                [](EstimatorData& d) {
                                                    d.sun_method = SunMethod::three_faces;
                                                    d.angular_response = AngularResponse::kelly;
                                                    d.adc_bits = 10;
                                                }},
                                           // The on-board references from the element set as numbers (the
                                           // text lines do not cross the wire), a knot every second.
                                           Case{"onboard_references",
                                                [](EstimatorData& d) {
                                                    d.reference_source = ReferenceSource::onboard;
                                                    d.tle_elements = {2461118.5, 14.98524078, 0.0012,   64.9,
                                                                      3.1277,    90.376,      275.3137, 1.5e-4};
                                                    d.reference_period = 1.0;
                                                    d.filter = FilterKind::mekf;
                                                }}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(FirmwareBoard, RefusesWhatItDoesNotCompute) {
    static EstimatorBoard board;
    std::vector<std::uint8_t> reply(bridge::max_frame_size);
    bridge::Frame c;
    c.type = bridge::FrameType::configure;
    c.time = static_cast<double>(wire::kParameterCount);
    c.sequence = static_cast<std::uint32_t>(wire::kParameter_spin_window);
    c.values = {512.0};  // the FFT is not on board
    EXPECT_EQ(board.answer(bridge::encode(c), reply), 0u);
    EXPECT_EQ(board.refusal(), EstimatorBoard::Refusal::not_on_this_board);
    c.sequence = static_cast<std::uint32_t>(wire::kParameter_precision);
    c.values = {0.0};  // double
    EXPECT_EQ(board.answer(bridge::encode(c), reply), 0u);
    EXPECT_EQ(board.refusal(), EstimatorBoard::Refusal::not_on_this_board);
    c.values = {1.0};  // float
    EXPECT_GT(board.answer(bridge::encode(c), reply), 0u);
    c.time = 3.0;  // another block's parameter count
    EXPECT_EQ(board.answer(bridge::encode(c), reply), 0u);
    EXPECT_EQ(board.refusal(), EstimatorBoard::Refusal::wrong_parameter_count);
    bridge::Frame r;
    r.sequence = 1;
    r.values.assign(wire::kInputCount - 1, 0.0);
    EXPECT_EQ(board.answer(bridge::encode(r), reply), 0u);
    EXPECT_EQ(board.refusal(), EstimatorBoard::Refusal::wrong_input_count);
    const std::vector<std::uint8_t> noise{1, 2, 3};
    EXPECT_EQ(board.answer(noise, reply), 0u);
    EXPECT_EQ(board.refusal(), EstimatorBoard::Refusal::undecodable);
}

}  // namespace
}  // namespace attitude_estimator
