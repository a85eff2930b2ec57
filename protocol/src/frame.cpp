#include "protocol/frame.hpp"

#include <string>

namespace bridge {

std::vector<std::uint8_t> encode(const Frame& frame) {
    if (frame.values.size() > max_values)
        throw FrameError("frame of " + std::to_string(frame.values.size()) + " values exceeds the maximum of " +
                         std::to_string(max_values));
    std::vector<std::uint8_t> out(frame_size(frame.values.size()));
    const FrameHeader header{
        .type = frame.type, .sequence = frame.sequence, .time = frame.time, .count = frame.values.size()};
    if (encode_frame(header, frame.values, out) != out.size()) throw FrameError("frame encoding failed");
    return out;
}

Frame decode(std::span<const std::uint8_t> bytes) {
    FrameHeader header;
    const DecodeStatus status = decode_frame(bytes, header);
    // The codec says what; the message adds the numbers.
    switch (status) {
        case DecodeStatus::ok:
            break;
        case DecodeStatus::too_long:
            throw FrameError("frame of " + std::to_string(bytes.size()) + " bytes exceeds the maximum of " +
                             std::to_string(max_frame_size));
        case DecodeStatus::too_short:
            throw FrameError("frame of " + std::to_string(bytes.size()) + " bytes is shorter than a header and CRC (" +
                             std::to_string(header_size + crc_size) + ")");
        case DecodeStatus::bad_version:
            throw FrameError("unsupported frame version " + std::to_string(bytes[2]) + " (expected " +
                             std::to_string(frame_version) + ")");
        case DecodeStatus::bad_type:
            throw FrameError("unknown frame type " + std::to_string(bytes[3]));
        case DecodeStatus::too_many_values:
            throw FrameError("frame announces " + std::to_string(bytes[16] | (bytes[17] << 8)) +
                             " values, more than the maximum of " + std::to_string(max_values));
        case DecodeStatus::bad_length: {
            const std::size_t n = bytes[16] | (bytes[17] << 8);
            throw FrameError("frame length " + std::to_string(bytes.size()) + " does not match its count of " +
                             std::to_string(n) + " values (expected " + std::to_string(frame_size(n)) + " bytes)");
        }
        default:
            throw FrameError(describe(status));
    }
    Frame f;
    f.type = header.type;
    f.sequence = header.sequence;
    f.time = header.time;
    f.values.resize(header.count);
    for (std::size_t i = 0; i < header.count; ++i) f.values[i] = frame_value(bytes, i);
    return f;
}

}  // namespace bridge
