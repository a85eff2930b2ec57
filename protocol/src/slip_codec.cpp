#include "protocol/slip_codec.hpp"

namespace bridge {

std::size_t slip_encode_into(std::span<const std::uint8_t> frame, std::span<std::uint8_t> out) noexcept {
    std::size_t n = 0;
    auto put = [&](std::uint8_t b) {
        if (n < out.size()) out[n] = b;
        ++n;
    };
    put(slip_end);  // a leading END flushes line noise at the receiver
    for (const std::uint8_t b : frame) {
        if (b == slip_end) {
            put(slip_esc);
            put(slip_esc_end);
        } else if (b == slip_esc) {
            put(slip_esc);
            put(slip_esc_esc);
        } else {
            put(b);
        }
    }
    put(slip_end);
    return n <= out.size() ? n : 0;
}

SlipReader::Event SlipReader::feed(std::uint8_t byte) noexcept {
    frame_size_ = 0;
    if (byte == slip_end) {
        const bool had = size_ > 0 && !discarding_;
        frame_size_ = had ? size_ : 0;
        size_ = 0;
        discarding_ = escaped_ = false;
        return had ? Event::frame : Event::none;
    }
    if (discarding_) return Event::none;
    if (escaped_) {
        escaped_ = false;
        if (byte == slip_esc_end) {
            byte = slip_end;
        } else if (byte == slip_esc_esc) {
            byte = slip_esc;
        } else {
            ++dropped_;
            discarding_ = true;
            size_ = 0;
            return Event::dropped_bad_escape;
        }
    } else if (byte == slip_esc) {
        escaped_ = true;
        return Event::none;
    }
    if (size_ >= buffer_.size()) {
        ++dropped_;
        discarding_ = true;
        size_ = 0;
        return Event::dropped_too_long;
    }
    buffer_[size_++] = byte;
    return Event::none;
}

}  // namespace bridge
