// SLIP framing (RFC 1055) for byte streams such as a serial line: each frame is sent as
// END, the frame with END and ESC bytes escaped, END. The decoder resynchronizes at the next END
// after noise or an oversized frame, so one corrupted frame never costs more than itself.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace bridge {

inline constexpr std::uint8_t slip_end = 0xC0, slip_esc = 0xDB, slip_esc_end = 0xDC, slip_esc_esc = 0xDD;

std::vector<std::uint8_t> slip_encode(std::span<const std::uint8_t> frame);

class SlipDecoder {
public:
    explicit SlipDecoder(std::size_t max_size) : max_size_(max_size) {}
    // Feeds one byte; returns a whole frame when an END closes a non-empty one. A frame longer than
    // max_size, or with a bad escape, is dropped and counted; error() says why.
    std::optional<std::vector<std::uint8_t>> feed(std::uint8_t byte);
    long dropped() const { return dropped_; }
    const std::string& error() const { return error_; }

private:
    std::size_t max_size_;
    std::vector<std::uint8_t> buffer_;
    bool escaped_ = false, discarding_ = false;
    long dropped_ = 0;
    std::string error_;
};

}  // namespace bridge
