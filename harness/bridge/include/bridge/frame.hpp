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
// Version 2 added the configuration frames; a version-1 peer is refused by name.
inline constexpr std::uint8_t frame_version = 2;
inline constexpr std::size_t header_size = 24;  // values start 8-byte aligned
inline constexpr std::size_t crc_size = 2;
inline constexpr std::size_t max_values = 64;
inline constexpr std::size_t max_frame_size = header_size + 8 * max_values + crc_size;  // 538 bytes

// request/reply: one sample. configure (master -> board, before the first request of a run): the bridged
// block's parameter values, as many frames as they need; configured (board -> master): the board took one.
enum class FrameType : std::uint8_t { request = 1, reply = 2, configure = 3, configured = 4 };

struct Frame {
    FrameType type = FrameType::request;
    // request/reply: the exchange's number (1 opens a run). configure/configured: the index of the first
    // parameter value the frame carries.
    std::uint32_t sequence = 0;
    // request/reply: simulation time of the sample instant, s. configure: the number of parameters the
    // master sends in all; configured: the number the board has (the two must agree).
    double time = 0.0;
    // request: inputs; reply: outputs; configure: parameter values — each in value-reference order, the
    // parameters being the block's non-String ones (an Integer, Boolean or Enumeration as its number).
    std::vector<double> values;
};

// CRC-16/CCITT-FALSE: polynomial 0x1021, initial value 0xFFFF, no reflection, no final xor.
std::uint16_t crc16_ccitt(std::span<const std::uint8_t> bytes);

// Throws FrameError when the frame holds more than max_values values.
std::vector<std::uint8_t> encode(const Frame& frame);
// Throws FrameError for anything but one whole, valid frame.
Frame decode(std::span<const std::uint8_t> bytes);

}  // namespace bridge
