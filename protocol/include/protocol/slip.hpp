// SLIP framing (RFC 1055) for byte streams such as a serial line, for the host: vectors over the
// freestanding codec (slip_codec.hpp) that the firmware uses too.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "protocol/slip_codec.hpp"

namespace bridge {

std::vector<std::uint8_t> slip_encode(std::span<const std::uint8_t> frame);

class SlipDecoder {
public:
    explicit SlipDecoder(std::size_t max_size) : buffer_(max_size), reader_(buffer_) {}
    SlipDecoder(const SlipDecoder&) = delete;
    SlipDecoder& operator=(const SlipDecoder&) = delete;
    // Feeds one byte; returns a whole frame when an END closes a non-empty one. A frame longer than
    // max_size, or with a bad escape, is dropped and counted; error() says why.
    std::optional<std::vector<std::uint8_t>> feed(std::uint8_t byte);
    long dropped() const { return reader_.dropped(); }
    const std::string& error() const { return error_; }

private:
    std::vector<std::uint8_t> buffer_;  // before reader_: it reads into this
    SlipReader reader_;
    std::string error_;
};

}  // namespace bridge
