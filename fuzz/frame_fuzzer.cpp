// The bridge frame decoder: any bytes are a Frame or a FrameError; a decoded frame encodes back to
// the same bytes but for the reserved ones, which receivers ignore.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

#include "protocol/frame.hpp"

namespace {

void decode_and_check(std::span<const std::uint8_t> bytes) {
    try {
        const bridge::Frame frame = bridge::decode(bytes);
        // Bytes 18..23 are reserved: "zero in version 1; receivers ignore" (README beside the codec), so
        // the re-encoding equals the input with them zeroed (and the CRC of that).
        std::vector<std::uint8_t> expected(bytes.begin(), bytes.end());
        std::fill(expected.begin() + 18, expected.begin() + bridge::header_size, std::uint8_t{0});
        const std::size_t body = expected.size() - bridge::crc_size;
        const std::uint16_t crc = bridge::crc16_ccitt(std::span<const std::uint8_t>(expected).first(body));
        expected[body] = static_cast<std::uint8_t>(crc);
        expected[body + 1] = static_cast<std::uint8_t>(crc >> 8);
        if (bridge::encode(frame) != expected) std::abort();
    } catch (const bridge::FrameError&) {}
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    decode_and_check(std::span<const std::uint8_t>(data, size));
    // The same bytes with a valid CRC, as a sender with a bug (not line noise) would make them: the
    // checks after the CRC are reached too.
    if (size < bridge::crc_size) return 0;
    std::vector<std::uint8_t> sealed(data, data + size);
    const std::size_t body = size - bridge::crc_size;
    const std::uint16_t crc = bridge::crc16_ccitt(std::span<const std::uint8_t>(sealed).first(body));
    sealed[body] = static_cast<std::uint8_t>(crc);
    sealed[body + 1] = static_cast<std::uint8_t>(crc >> 8);
    decode_and_check(sealed);
    return 0;
}
