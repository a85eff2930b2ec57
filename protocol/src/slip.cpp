#include "protocol/slip.hpp"

namespace bridge {

std::vector<std::uint8_t> slip_encode(std::span<const std::uint8_t> frame) {
    std::vector<std::uint8_t> out(slip_max_encoded_size(frame.size()));
    out.resize(slip_encode_into(frame, out));
    return out;
}

std::optional<std::vector<std::uint8_t>> SlipDecoder::feed(std::uint8_t byte) {
    switch (reader_.feed(byte)) {
        case SlipReader::Event::frame: {
            const auto f = reader_.frame();
            return std::vector<std::uint8_t>(f.begin(), f.end());
        }
        case SlipReader::Event::dropped_too_long:
            error_ = "SLIP frame longer than " + std::to_string(buffer_.size()) + " bytes";
            break;
        case SlipReader::Event::dropped_bad_escape:
            error_ = "bad SLIP escape";
            break;
        case SlipReader::Event::none:
            break;
    }
    return std::nullopt;
}

}  // namespace bridge
