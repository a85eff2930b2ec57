// The hardware-bridge wire format for the host (README.md beside this folder is the firmware author's
// copy): one little-endian binary frame per exchange, over the freestanding codec (frame_codec.hpp) that
// the firmware uses too, with vectors and exceptions that say what was wrong. No FMI, no sockets.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

#include "protocol/frame_codec.hpp"

namespace bridge {

// A frame the codec refuses (bad magic, version, type, length, count or CRC); what() says which.
class FrameError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A frame with its values (FrameHeader's fields mean the same here).
struct Frame {
    FrameType type = FrameType::request;
    std::uint32_t sequence = 0;
    double time = 0.0;
    // request: inputs; reply: outputs; configure: parameter values — each in value-reference order, the
    // parameters being the block's non-String ones (an Integer, Boolean or Enumeration as its number).
    std::vector<double> values;
};

// Throws FrameError when the frame holds more than max_values values.
std::vector<std::uint8_t> encode(const Frame& frame);
// Throws FrameError for anything but one whole, valid frame.
Frame decode(std::span<const std::uint8_t> bytes);

}  // namespace bridge
