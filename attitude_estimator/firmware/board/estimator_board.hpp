// The on-board computer behind the hardware bridge's wire protocol (protocol/README.md), as the
// firmware runs it: configure frames set the parameters (kept, and applied at the start of each run),
// request frames are samples, each answered with the block's outputs. Freestanding — no heap, no
// exceptions, no operating system — so the same file runs on the Cortex-M (main.cpp beside this folder)
// and on the host, where a test holds it against the board emulator running attitude_estimator.fmu in
// float. The computer runs in float (onboard_sample<float>); the spin-rate FFT is not on board.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "attitude_estimator/estimator_data.hpp"
#include "estimator_wire_table.hpp"
#include "protocol/frame_codec.hpp"

namespace attitude_estimator {

class EstimatorBoard {
public:
    // Why a frame got no answer (counted; the master's timeout and policy take it from there).
    enum class Refusal : std::uint8_t {
        none,
        undecodable,             // the codec refused it (bridge::DecodeStatus)
        not_for_a_board,         // a reply or configured frame
        wrong_input_count,       // a request whose count is not the block's inputs
        wrong_parameter_count,   // a configuration of another number of parameters
        parameter_out_of_range,  // a value a parameter does not take
        not_on_this_board,       // precision = double or spin_window > 0: not what this firmware computes
        reply_too_long,          // the reply does not fit the caller's buffer
    };

    // Answers one frame: writes the reply into `reply` and returns its size, or 0 for no reply (refusal()
    // says why). A run starts at request sequence 1 (or the first request after power-up) from the
    // block's defaults with the configuration received so far.
    std::size_t answer(std::span<const std::uint8_t> frame, std::span<std::uint8_t> reply) noexcept;

    Refusal refusal() const noexcept { return refusal_; }
    long refused() const noexcept { return refused_; }
    std::int32_t samples() const noexcept { return data_.samples; }

private:
    std::size_t configure(std::span<const std::uint8_t> frame, const bridge::FrameHeader& h,
                          std::span<std::uint8_t> reply) noexcept;
    std::size_t sample(std::span<const std::uint8_t> frame, const bridge::FrameHeader& h,
                       std::span<std::uint8_t> reply) noexcept;
    std::size_t refuse(Refusal why) noexcept;
    // Opens a run: the block's defaults, the master's configuration, the on-board settings. Its own
    // function, kept out of line, so that the settings it builds (4.5 kB on the target) are on the stack
    // only while a run opens, not under every sample's computation.
    [[gnu::noinline]] bool open_run() noexcept;

    EstimatorData data_{};
    OnboardSettings<float> settings_{};
    std::array<double, wire::kParameterCount> configuration_{};
    std::array<bool, wire::kParameterCount> configured_{};
    std::array<double, wire::kOutputCount> outputs_{};
    bool running_ = false;
    Refusal refusal_ = Refusal::none;
    long refused_ = 0;
};

}  // namespace attitude_estimator
