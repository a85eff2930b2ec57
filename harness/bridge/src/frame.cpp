#include "bridge/frame.hpp"

#include <bit>
#include <string>

namespace bridge {

namespace {

// Byte-by-byte little-endian access: the same on any host, and what a DSP's C does with shifts.
void put_u16(std::vector<std::uint8_t>& out, std::size_t at, std::uint16_t x) {
    out[at] = static_cast<std::uint8_t>(x);
    out[at + 1] = static_cast<std::uint8_t>(x >> 8);
}
void put_u32(std::vector<std::uint8_t>& out, std::size_t at, std::uint32_t x) {
    for (int i = 0; i < 4; ++i) out[at + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(x >> (8 * i));
}
void put_f64(std::vector<std::uint8_t>& out, std::size_t at, double x) {
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

std::uint16_t crc16_ccitt(std::span<const std::uint8_t> bytes) {
    std::uint16_t crc = 0xFFFF;
    for (const std::uint8_t b : bytes) {
        crc = static_cast<std::uint16_t>(crc ^ (b << 8));
        for (int i = 0; i < 8; ++i) crc = static_cast<std::uint16_t>((crc & 0x8000) ? (crc << 1) ^ 0x1021 : crc << 1);
    }
    return crc;
}

std::vector<std::uint8_t> encode(const Frame& frame) {
    if (frame.values.size() > max_values)
        throw FrameError("frame of " + std::to_string(frame.values.size()) + " values exceeds the maximum of " +
                         std::to_string(max_values));
    const std::size_t n = frame.values.size();
    std::vector<std::uint8_t> out(header_size + 8 * n + crc_size, 0);
    put_u16(out, 0, frame_magic);
    out[2] = frame_version;
    out[3] = static_cast<std::uint8_t>(frame.type);
    put_u32(out, 4, frame.sequence);
    put_f64(out, 8, frame.time);
    put_u16(out, 16, static_cast<std::uint16_t>(n));
    // bytes 18..23: flags and reserved, zero in versions 1 and 2
    for (std::size_t i = 0; i < n; ++i) put_f64(out, header_size + 8 * i, frame.values[i]);
    const std::size_t body = header_size + 8 * n;
    put_u16(out, body, crc16_ccitt(std::span(out).first(body)));
    return out;
}

Frame decode(std::span<const std::uint8_t> bytes) {
    if (bytes.size() > max_frame_size)
        throw FrameError("frame of " + std::to_string(bytes.size()) + " bytes exceeds the maximum of " +
                         std::to_string(max_frame_size));
    if (bytes.size() < header_size + crc_size)
        throw FrameError("frame of " + std::to_string(bytes.size()) + " bytes is shorter than a header and CRC (" +
                         std::to_string(header_size + crc_size) + ")");
    if (get_u16(bytes, 0) != frame_magic) throw FrameError("bad magic (not a hardware-bridge frame)");
    if (bytes[2] != frame_version)
        throw FrameError("unsupported frame version " + std::to_string(bytes[2]) + " (expected " +
                         std::to_string(frame_version) + ")");
    if (bytes[3] < static_cast<std::uint8_t>(FrameType::request) ||
        bytes[3] > static_cast<std::uint8_t>(FrameType::configured))
        throw FrameError("unknown frame type " + std::to_string(bytes[3]));
    const std::size_t n = get_u16(bytes, 16);
    if (n > max_values)
        throw FrameError("frame announces " + std::to_string(n) + " values, more than the maximum of " +
                         std::to_string(max_values));
    const std::size_t body = header_size + 8 * n;
    if (bytes.size() != body + crc_size)
        throw FrameError("frame length " + std::to_string(bytes.size()) + " does not match its count of " +
                         std::to_string(n) + " values (expected " + std::to_string(body + crc_size) + " bytes)");
    if (get_u16(bytes, body) != crc16_ccitt(bytes.first(body))) throw FrameError("CRC mismatch (frame corrupted)");
    Frame f;
    f.type = static_cast<FrameType>(bytes[3]);
    f.sequence = get_u32(bytes, 4);
    f.time = get_f64(bytes, 8);
    f.values.resize(n);
    for (std::size_t i = 0; i < n; ++i) f.values[i] = get_f64(bytes, header_size + 8 * i);
    return f;
}

}  // namespace bridge
