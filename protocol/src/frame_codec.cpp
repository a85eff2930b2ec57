#include "protocol/frame_codec.hpp"

#include <bit>

namespace bridge {

namespace {

// Byte-by-byte little-endian access: the same on any host, and what a DSP's C does with shifts.
void put_u16(std::span<std::uint8_t> out, std::size_t at, std::uint16_t x) {
    out[at] = static_cast<std::uint8_t>(x);
    out[at + 1] = static_cast<std::uint8_t>(x >> 8);
}
void put_u32(std::span<std::uint8_t> out, std::size_t at, std::uint32_t x) {
    for (int i = 0; i < 4; ++i) out[at + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(x >> (8 * i));
}
void put_f64(std::span<std::uint8_t> out, std::size_t at, double x) {
    const auto bits = std::bit_cast<std::uint64_t>(x);
    for (int i = 0; i < 8; ++i) out[at + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(bits >> (8 * i));
}
std::uint16_t get_u16(std::span<const std::uint8_t> in, std::size_t at) {
    return static_cast<std::uint16_t>(in[at] | (in[at + 1] << 8));
}
std::uint32_t get_u32(std::span<const std::uint8_t> in, std::size_t at) {
    std::uint32_t x = 0;
    for (int i = 3; i >= 0; --i) x = (x << 8) | in[at + static_cast<std::size_t>(i)];
    return x;
}
double get_f64(std::span<const std::uint8_t> in, std::size_t at) {
    std::uint64_t bits = 0;
    for (int i = 7; i >= 0; --i) bits = (bits << 8) | in[at + static_cast<std::size_t>(i)];
    return std::bit_cast<double>(bits);
}

}  // namespace

const char* describe(DecodeStatus status) noexcept {
    switch (status) {
        case DecodeStatus::ok:
            return "ok";
        case DecodeStatus::too_long:
            return "frame longer than the maximum";
        case DecodeStatus::too_short:
            return "frame shorter than a header and CRC";
        case DecodeStatus::bad_magic:
            return "bad magic (not a hardware-bridge frame)";
        case DecodeStatus::bad_version:
            return "unsupported frame version";
        case DecodeStatus::bad_type:
            return "unknown frame type";
        case DecodeStatus::too_many_values:
            return "frame announces more values than the maximum";
        case DecodeStatus::bad_length:
            return "frame length does not match its count of values";
        case DecodeStatus::bad_crc:
            return "CRC mismatch (frame corrupted)";
    }
    return "unknown decode status";
}

std::uint16_t crc16_ccitt(std::span<const std::uint8_t> bytes) noexcept {
    std::uint16_t crc = 0xFFFF;
    for (const std::uint8_t b : bytes) {
        crc = static_cast<std::uint16_t>(crc ^ (b << 8));
        for (int i = 0; i < 8; ++i) crc = static_cast<std::uint16_t>((crc & 0x8000) ? (crc << 1) ^ 0x1021 : crc << 1);
    }
    return crc;
}

std::size_t encode_frame(const FrameHeader& header, std::span<const double> values,
                         std::span<std::uint8_t> out) noexcept {
    const std::size_t n = values.size();
    if (n > max_values || out.size() < frame_size(n)) return 0;
    for (std::size_t i = 0; i < header_size; ++i) out[i] = 0;  // bytes 18..23: flags and reserved, zero
    put_u16(out, 0, frame_magic);
    out[2] = frame_version;
    out[3] = static_cast<std::uint8_t>(header.type);
    put_u32(out, 4, header.sequence);
    put_f64(out, 8, header.time);
    put_u16(out, 16, static_cast<std::uint16_t>(n));
    for (std::size_t i = 0; i < n; ++i) put_f64(out, header_size + 8 * i, values[i]);
    const std::size_t body = header_size + 8 * n;
    put_u16(out, body, crc16_ccitt(out.first(body)));
    return body + crc_size;
}

DecodeStatus decode_frame(std::span<const std::uint8_t> bytes, FrameHeader& header) noexcept {
    if (bytes.size() > max_frame_size) return DecodeStatus::too_long;
    if (bytes.size() < header_size + crc_size) return DecodeStatus::too_short;
    if (get_u16(bytes, 0) != frame_magic) return DecodeStatus::bad_magic;
    if (bytes[2] != frame_version) return DecodeStatus::bad_version;
    if (bytes[3] < static_cast<std::uint8_t>(FrameType::request) ||
        bytes[3] > static_cast<std::uint8_t>(FrameType::configured))
        return DecodeStatus::bad_type;
    const std::size_t n = get_u16(bytes, 16);
    if (n > max_values) return DecodeStatus::too_many_values;
    const std::size_t body = header_size + 8 * n;
    if (bytes.size() != body + crc_size) return DecodeStatus::bad_length;
    if (get_u16(bytes, body) != crc16_ccitt(bytes.first(body))) return DecodeStatus::bad_crc;
    header.type = static_cast<FrameType>(bytes[3]);
    header.sequence = get_u32(bytes, 4);
    header.time = get_f64(bytes, 8);
    header.count = n;
    return DecodeStatus::ok;
}

double frame_value(std::span<const std::uint8_t> bytes, std::size_t i) noexcept {
    return get_f64(bytes, header_size + 8 * i);
}

}  // namespace bridge
