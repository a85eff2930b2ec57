// SLIP framing (RFC 1055), freestanding: no heap, no exceptions — the same file in the host's links and
// in the Cortex-M firmware. Each frame is sent as END, the frame with END and ESC bytes escaped, END. The
// reader resynchronizes at the next END after noise or an oversized frame, so one corrupted frame never
// costs more than itself. slip.hpp wraps it for the host.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

namespace bridge {

inline constexpr std::uint8_t slip_end = 0xC0, slip_esc = 0xDB, slip_esc_end = 0xDC, slip_esc_esc = 0xDD;

// The longest encoding of a frame of n bytes: every byte escaped, and the two ENDs.
inline constexpr std::size_t slip_max_encoded_size(std::size_t n) {
    return 2 * n + 2;
}

// Writes the encoding of `frame` into `out`; returns its size, or 0 when `out` is too small.
std::size_t slip_encode_into(std::span<const std::uint8_t> frame, std::span<std::uint8_t> out) noexcept;

// Reassembles frames from a byte stream into a caller's buffer (its size is the longest frame taken).
class SlipReader {
public:
    enum class Event : std::uint8_t { none, frame, dropped_too_long, dropped_bad_escape };
    explicit SlipReader(std::span<std::uint8_t> buffer) noexcept : buffer_(buffer) {}
    // Feeds one byte. `frame`: an END closed a non-empty frame, now in frame() until the next feed.
    // `dropped_*`: the frame being read was thrown away (counted in dropped()).
    Event feed(std::uint8_t byte) noexcept;
    std::span<const std::uint8_t> frame() const noexcept { return buffer_.first(frame_size_); }
    long dropped() const noexcept { return dropped_; }

private:
    std::span<std::uint8_t> buffer_;
    std::size_t size_ = 0, frame_size_ = 0;
    bool escaped_ = false, discarding_ = false;
    long dropped_ = 0;
};

}  // namespace bridge
