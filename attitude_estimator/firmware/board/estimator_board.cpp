#include "estimator_board.hpp"

#include <memory>

namespace attitude_estimator {

std::size_t EstimatorBoard::refuse(Refusal why) noexcept {
    refusal_ = why;
    ++refused_;
    return 0;
}

std::size_t EstimatorBoard::answer(std::span<const std::uint8_t> frame, std::span<std::uint8_t> reply) noexcept {
    refusal_ = Refusal::none;
    bridge::FrameHeader h;
    if (bridge::decode_frame(frame, h) != bridge::DecodeStatus::ok) return refuse(Refusal::undecodable);
    if (h.type == bridge::FrameType::configure) return configure(frame, h, reply);
    if (h.type == bridge::FrameType::request) return sample(frame, h, reply);
    return refuse(Refusal::not_for_a_board);
}

std::size_t EstimatorBoard::configure(std::span<const std::uint8_t> frame, const bridge::FrameHeader& h,
                                      std::span<std::uint8_t> reply) noexcept {
    if (h.time != static_cast<double>(wire::kParameterCount) || h.sequence > wire::kParameterCount ||
        h.count > wire::kParameterCount - h.sequence)
        return refuse(Refusal::wrong_parameter_count);
    // Checked before any is kept: a frame with one value out of range is refused whole.
    for (std::size_t i = 0; i < h.count; ++i) {
        const std::size_t p = h.sequence + i;
        const double x = bridge::frame_value(frame, i);
        if (!wire::parameter_accepts(p, x)) return refuse(Refusal::parameter_out_of_range);
        const bool single = x == static_cast<double>(Precision::single_precision);
        if ((p == wire::kParameter_precision && !single) || (p == wire::kParameter_spin_window && x != 0.0))
            return refuse(Refusal::not_on_this_board);
    }
    for (std::size_t i = 0; i < h.count; ++i) {
        configuration_[h.sequence + i] = bridge::frame_value(frame, i);
        configured_[h.sequence + i] = true;
    }
    const bridge::FrameHeader ack{.type = bridge::FrameType::configured,
                                  .sequence = h.sequence,
                                  .time = static_cast<double>(wire::kParameterCount),
                                  .count = 0};
    const std::size_t n = bridge::encode_frame(ack, {}, reply);
    return n ? n : refuse(Refusal::reply_too_long);
}

bool EstimatorBoard::open_run() noexcept {
    // From the block's defaults, then the master's configuration; the precision and the spin window
    // are this firmware's whatever the master left at their defaults.
    std::destroy_at(&data_);
    std::construct_at(&data_);
    for (std::size_t p = 0; p < wire::kParameterCount; ++p)
        if (configured_[p]) wire::set_parameter(data_, p, configuration_[p]);
    data_.precision = Precision::single_precision;
    data_.spin_window = 0;
    // On-board references need the element set, which reaches the board as numbers (tle_elements: the
    // text lines are not on the wire); without it there is no orbit to run.
    if (data_.reference_source == ReferenceSource::onboard && !(data_.tle_elements[0] > 0.0)) return false;
    settings_ = onboard_settings_from<float>(data_);
    onboard_start(data_.onboard_float, settings_);
    return true;
}

std::size_t EstimatorBoard::sample(std::span<const std::uint8_t> frame, const bridge::FrameHeader& h,
                                   std::span<std::uint8_t> reply) noexcept {
    if (h.count != wire::kInputCount) return refuse(Refusal::wrong_input_count);
    if (h.sequence == 1) running_ = false;  // sequence 1 opens a run
    if (!running_ && !open_run()) return refuse(Refusal::not_on_this_board);
    for (std::size_t i = 0; i < wire::kInputCount; ++i) wire::set_input(data_, i, bridge::frame_value(frame, i));
    store_outputs(data_, onboard_sample(data_.onboard_float, onboard_inputs_from<float>(data_), settings_,
                                        static_cast<float>(h.time)));
    running_ = true;
    for (std::size_t i = 0; i < wire::kOutputCount; ++i) outputs_[i] = wire::output(data_, i);
    const bridge::FrameHeader r{
        .type = bridge::FrameType::reply, .sequence = h.sequence, .time = h.time, .count = wire::kOutputCount};
    const std::size_t n = bridge::encode_frame(r, outputs_, reply);
    return n ? n : refuse(Refusal::reply_too_long);
}

}  // namespace attitude_estimator
