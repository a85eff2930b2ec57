#include "bridge/slip.hpp"

namespace bridge {

std::vector<std::uint8_t> slip_encode(std::span<const std::uint8_t> frame) {
    std::vector<std::uint8_t> out;
    out.reserve(frame.size() + 8);
    out.push_back(slip_end);  // a leading END flushes line noise at the receiver
    for (const std::uint8_t b : frame) {
        if (b == slip_end) {
            out.push_back(slip_esc);
            out.push_back(slip_esc_end);
        } else if (b == slip_esc) {
            out.push_back(slip_esc);
            out.push_back(slip_esc_esc);
        } else {
            out.push_back(b);
        }
    }
    out.push_back(slip_end);
    return out;
}

std::optional<std::vector<std::uint8_t>> SlipDecoder::feed(std::uint8_t byte) {
    if (byte == slip_end) {
        const bool had = !buffer_.empty() && !discarding_;
        std::vector<std::uint8_t> frame;
        frame.swap(buffer_);
        discarding_ = escaped_ = false;
        if (had) return frame;
        return std::nullopt;
    }
    if (discarding_) return std::nullopt;
    if (escaped_) {
        escaped_ = false;
        if (byte == slip_esc_end)
            byte = slip_end;
        else if (byte == slip_esc_esc)
            byte = slip_esc;
        else {
            error_ = "bad SLIP escape";
            ++dropped_;
            discarding_ = true;
            buffer_.clear();
            return std::nullopt;
        }
    } else if (byte == slip_esc) {
        escaped_ = true;
        return std::nullopt;
    }
    if (buffer_.size() >= max_size_) {
        error_ = "SLIP frame longer than " + std::to_string(max_size_) + " bytes";
        ++dropped_;
        discarding_ = true;
        buffer_.clear();
        return std::nullopt;
    }
    buffer_.push_back(byte);
    return std::nullopt;
}

}  // namespace bridge
