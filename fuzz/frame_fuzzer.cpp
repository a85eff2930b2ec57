// The bridge frame decoder: any bytes are a Frame or a FrameError; a decoded frame encodes back to
// the same bytes (the format has one encoding per frame).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>

#include "bridge/frame.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::span<const std::uint8_t> bytes(data, size);
    try {
        const bridge::Frame frame = bridge::decode(bytes);
        const auto again = bridge::encode(frame);
        if (again.size() != size || !std::equal(again.begin(), again.end(), data)) std::abort();
    } catch (const bridge::FrameError&) {
    }
    return 0;
}
