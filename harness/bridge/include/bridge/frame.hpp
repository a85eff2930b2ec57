// The hardware-bridge wire format (README.md beside this folder is the firmware author's copy):
// one little-endian binary frame per exchange, written and read here once for both ends of the link
// (the cosim master and the board emulator). Plain C++: no FMI, no sockets.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

namespace bridge {

// A frame the codec refuses (bad magic, version, type, length, count or CRC); what() says which.
class FrameError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

inline constexpr std::uint16_t frame_magic = 0x5650;  // bytes 'P' 'V' on the wire
inline constexpr std::uint8_t frame_version = 1;
inline constexpr std::size_t header_size = 24;  // values start 8-byte aligned
inline constexpr std::size_t crc_size = 2;
inline constexpr std::size_t max_values = 64;
inline constexpr std::size_t max_frame_size = header_size + 8 * max_values + crc_size;  // 538 bytes

enum class FrameType : std::uint8_t { request = 1, reply = 2 };

struct Frame {
    FrameType type = FrameType::request;
    std::uint32_t sequence = 0;
    double time = 0.0;           // simulation time of the sample instant, s
    std::vector<double> values;  // inputs (request) or outputs (reply) in value-reference order
};

// CRC-16/CCITT-FALSE: polynomial 0x1021, initial value 0xFFFF, no reflection, no final xor.
std::uint16_t crc16_ccitt(std::span<const std::uint8_t> bytes);

// Throws FrameError when the frame holds more than max_values values.
std::vector<std::uint8_t> encode(const Frame& frame);
// Throws FrameError for anything but one whole, valid frame.
Frame decode(std::span<const std::uint8_t> bytes);

}  // namespace bridge
