// SLIP (RFC 1055): the decoder takes any byte stream without growing past its bound, and a frame
// encoded by slip_encode comes back unchanged from the decoder.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

#include "protocol/slip.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    constexpr std::size_t max_size = 600;
    bridge::SlipDecoder noise(max_size);
    for (std::size_t i = 0; i < size; ++i)
        if (const auto frame = noise.feed(data[i]); frame && (frame->empty() || frame->size() > max_size)) std::abort();

    if (size == 0 || size > max_size) return 0;
    const auto wire = bridge::slip_encode(std::span<const std::uint8_t>(data, size));
    bridge::SlipDecoder decoder(max_size);
    std::vector<std::vector<std::uint8_t>> frames;
    for (const auto byte : wire)
        if (auto frame = decoder.feed(byte)) frames.push_back(std::move(*frame));
    if (frames.size() != 1 || frames[0] != std::vector<std::uint8_t>(data, data + size)) std::abort();
    return 0;
}
