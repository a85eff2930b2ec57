// The hardware-bridge wire format's codec, freestanding: no heap, no exceptions, no operating system —
// the same file compiles into the cosim master, the board emulator and the Cortex-M firmware
// (attitude_estimator/firmware). frame.hpp wraps it for the host with vectors and exceptions.
// README.md beside this folder is the firmware author's copy of the format.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

namespace bridge {

inline constexpr std::uint16_t frame_magic = 0x5650;  // bytes 'P' 'V' on the wire
// Version 2 added the configuration frames; a version-1 peer is refused by name.
inline constexpr std::uint8_t frame_version = 2;
inline constexpr std::size_t header_size = 24;  // values start 8-byte aligned
inline constexpr std::size_t crc_size = 2;
inline constexpr std::size_t max_values = 128;
inline constexpr std::size_t max_frame_size = header_size + 8 * max_values + crc_size;  // 1050 bytes

// request/reply: one sample. configure (master -> board, before the first request of a run): the bridged
// block's parameter values, as many frames as they need; configured (board -> master): the board took one.
enum class FrameType : std::uint8_t { request = 1, reply = 2, configure = 3, configured = 4 };

struct FrameHeader {
    FrameType type = FrameType::request;
    // request/reply: the exchange's number (1 opens a run). configure/configured: the index of the first
    // parameter value the frame carries.
    std::uint32_t sequence = 0;
    // request/reply: simulation time of the sample instant, s. configure: the number of parameters the
    // master sends in all; configured: the number the board has (the two must agree).
    double time = 0.0;
    std::size_t count = 0;  // values in the frame
};

// Why decode_frame refused a frame.
enum class DecodeStatus : std::uint8_t {
    ok,
    too_long,         // more than max_frame_size bytes
    too_short,        // less than a header and a CRC
    bad_magic,        // not a hardware-bridge frame
    bad_version,      // another version of the format
    bad_type,         // a type this version does not have
    too_many_values,  // a count above max_values
    bad_length,       // the length does not match the count
    bad_crc,          // corrupted
};
const char* describe(DecodeStatus status) noexcept;

// CRC-16/CCITT-FALSE: polynomial 0x1021, initial value 0xFFFF, no reflection, no final xor.
std::uint16_t crc16_ccitt(std::span<const std::uint8_t> bytes) noexcept;

inline constexpr std::size_t frame_size(std::size_t count) {
    return header_size + 8 * count + crc_size;
}

// Writes the frame into `out`; returns its size, or 0 when values.size() > max_values or `out` is too small.
std::size_t encode_frame(const FrameHeader& header, std::span<const double> values,
                         std::span<std::uint8_t> out) noexcept;
// Checks one whole frame; on ok fills `header` (its values are read with frame_value).
DecodeStatus decode_frame(std::span<const std::uint8_t> bytes, FrameHeader& header) noexcept;
// Value i of a frame decode_frame accepted.
double frame_value(std::span<const std::uint8_t> bytes, std::size_t i) noexcept;

}  // namespace bridge
