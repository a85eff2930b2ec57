// The wire codec: round trips, the published CRC check value, and every kind of bad frame refused
// with a message (never a crash or an out-of-bounds read: the sanitizer build runs these too).
#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <string>

#include "protocol/frame.hpp"
#include "protocol/slip.hpp"

namespace bridge {
namespace {

std::span<const std::uint8_t> bytes_of(const char* text) {
    return {reinterpret_cast<const std::uint8_t*>(text), std::strlen(text)};
}

Frame sample_frame() {
    Frame f;
    f.type = FrameType::reply;
    f.sequence = 0xA1B2C3D4u;
    f.time = 0.05;
    f.values = {1.0, -2.5, std::numeric_limits<double>::denorm_min(), 1e300, -0.0};
    return f;
}

std::string rejection(std::span<const std::uint8_t> bytes) {
    try {
        decode(bytes);
    } catch (const FrameError& e) {
        return e.what();
    }
    return "accepted";
}

// The catalogue check value of CRC-16/CCITT-FALSE over the ASCII digits "123456789" is 0x29B1
// (Greg Cook's CRC catalogue, "CRC-16/IBM-3740", formerly CCITT-FALSE).
TEST(Codec, CrcCheckValue) {
    EXPECT_EQ(crc16_ccitt(bytes_of("123456789")), 0x29B1);
}

TEST(Codec, RoundTripKeepsEveryBit) {
    const Frame f = sample_frame();
    const auto bytes = encode(f);
    EXPECT_EQ(bytes.size(), header_size + 8 * f.values.size() + crc_size);
    const Frame g = decode(bytes);
    EXPECT_EQ(g.type, f.type);
    EXPECT_EQ(g.sequence, f.sequence);
    EXPECT_EQ(g.time, f.time);
    ASSERT_EQ(g.values.size(), f.values.size());
    for (std::size_t i = 0; i < f.values.size(); ++i)
        EXPECT_EQ(std::memcmp(&g.values[i], &f.values[i], sizeof(double)), 0) << i;
}

// The layout a firmware author reads in the README, byte by byte: 'P' 'V', version 1, type,
// little-endian sequence, f64 time 1.0 = 0x3FF0000000000000, count.
TEST(Codec, LayoutIsLittleEndianAsDocumented) {
    Frame f;
    f.type = FrameType::request;
    f.sequence = 0x01020304u;
    f.time = 1.0;
    f.values = {2.0};
    const auto b = encode(f);
    EXPECT_EQ(b[0], 'P');
    EXPECT_EQ(b[1], 'V');
    EXPECT_EQ(b[2], 2);  // version 2
    EXPECT_EQ(b[3], 1);  // request
    EXPECT_EQ(b[4], 0x04);
    EXPECT_EQ(b[7], 0x01);
    EXPECT_EQ(b[15], 0x3F);
    EXPECT_EQ(b[14], 0xF0);
    EXPECT_EQ(b[16], 1);
    EXPECT_EQ(b[17], 0);
    EXPECT_EQ(b[31], 0x40);  // 2.0 = 0x4000000000000000, its top byte last
    const std::uint16_t crc = crc16_ccitt(std::span(b).first(32));
    EXPECT_EQ(b[32], crc & 0xFF);
    EXPECT_EQ(b[33], crc >> 8);
}

TEST(Codec, EmptyFrameRoundTrips) {
    Frame f;
    EXPECT_EQ(decode(encode(f)).values.size(), 0u);
}

TEST(Codec, BadMagicRejected) {
    auto b = encode(sample_frame());
    b[0] = 'X';
    EXPECT_NE(rejection(b).find("magic"), std::string::npos);
}

TEST(Codec, BadVersionRejected) {
    auto b = encode(sample_frame());
    b[2] = 1;  // a peer of before the configuration frames
    EXPECT_NE(rejection(b).find("version 1"), std::string::npos);
}

TEST(Codec, UnknownTypeRejected) {
    auto b = encode(sample_frame());
    b[3] = 9;
    EXPECT_NE(rejection(b).find("type 9"), std::string::npos);
}

// From the frame fuzzer (fuzz/frame_fuzzer.cpp, its first run): bytes 18..23 set and a valid CRC. The
// format says receivers ignore them, so the frame decodes to the same values and re-encodes with zeros.
TEST(Codec, ReservedBytesAreIgnored) {
    const Frame f = sample_frame();
    auto b = encode(f);
    for (std::size_t i = 18; i < header_size; ++i) b[i] = static_cast<std::uint8_t>(0xC8 + i);
    const std::size_t body = b.size() - crc_size;
    const std::uint16_t crc = crc16_ccitt(std::span<const std::uint8_t>(b).first(body));
    b[body] = static_cast<std::uint8_t>(crc);
    b[body + 1] = static_cast<std::uint8_t>(crc >> 8);
    const Frame d = decode(b);
    EXPECT_EQ(d.sequence, f.sequence);
    EXPECT_EQ(d.values, f.values);
    EXPECT_EQ(encode(d), encode(f));
}

TEST(Codec, EveryFlippedBitFailsTheCrc) {
    const auto good = encode(sample_frame());
    for (std::size_t i = 18; i < good.size(); ++i)  // past magic, version, type and count
        for (int bit = 0; bit < 8; ++bit) {
            auto b = good;
            b[i] ^= static_cast<std::uint8_t>(1u << bit);
            EXPECT_NE(rejection(b), "accepted") << "byte " << i << " bit " << bit;
        }
    auto b = good;
    b[30] ^= 0x10;
    EXPECT_NE(rejection(b).find("CRC"), std::string::npos);
}

TEST(Codec, WrongLengthRejected) {
    auto b = encode(sample_frame());
    b.pop_back();
    EXPECT_NE(rejection(b).find("length"), std::string::npos);
    b.push_back(0);
    b.push_back(0);
    EXPECT_NE(rejection(b).find("length"), std::string::npos);
    EXPECT_NE(rejection(std::span(b).first(10)).find("shorter"), std::string::npos);
    EXPECT_NE(rejection({}).find("shorter"), std::string::npos);
}

TEST(Codec, OversizedRejected) {
    Frame f;
    f.values.assign(max_values + 1, 1.0);
    EXPECT_THROW(encode(f), FrameError);
    std::vector<std::uint8_t> big(max_frame_size + 1, 0);
    EXPECT_NE(rejection(big).find("exceeds"), std::string::npos);
    // A header announcing more values than allowed, with a frame too short to hold them.
    auto b = encode(sample_frame());
    b[16] = 0xFF;
    b[17] = 0xFF;
    EXPECT_NE(rejection(b).find("more than the maximum"), std::string::npos);
}

TEST(Codec, MaximumFrameRoundTrips) {
    Frame f;
    for (std::size_t i = 0; i < max_values; ++i) f.values.push_back(static_cast<double>(i));
    const auto b = encode(f);
    EXPECT_EQ(b.size(), max_frame_size);
    EXPECT_EQ(decode(b).values.back(), static_cast<double>(max_values - 1));
}

std::vector<std::vector<std::uint8_t>> feed_all(SlipDecoder& d, const std::vector<std::uint8_t>& stream) {
    std::vector<std::vector<std::uint8_t>> frames;
    for (auto b : stream)
        if (auto f = d.feed(b)) frames.push_back(*f);
    return frames;
}

TEST(Slip, EscapesEndAndEscBytes) {
    const std::vector<std::uint8_t> raw = {1, slip_end, 2, slip_esc, 3};
    const auto enc = slip_encode(raw);
    // RFC 1055: END -> ESC ESC_END, ESC -> ESC ESC_ESC, framed by END on both sides.
    const std::vector<std::uint8_t> expected = {slip_end,     1, slip_esc, slip_esc_end, 2, slip_esc,
                                                slip_esc_esc, 3, slip_end};
    EXPECT_EQ(enc, expected);
    SlipDecoder d(max_frame_size);
    const auto frames = feed_all(d, enc);
    ASSERT_EQ(frames.size(), 1u);
    EXPECT_EQ(frames[0], raw);
}

TEST(Slip, ResynchronizesAfterNoiseAndOversizedFrames) {
    const auto frame = encode(sample_frame());
    std::vector<std::uint8_t> stream = {0x11, 0x22, slip_esc, 0x00};  // noise with a bad escape
    auto good = slip_encode(frame);
    stream.insert(stream.end(), good.begin(), good.end());
    std::vector<std::uint8_t> huge(max_frame_size + 10, 0x55);
    auto bad = slip_encode(huge);
    stream.insert(stream.end(), bad.begin(), bad.end());
    stream.insert(stream.end(), good.begin(), good.end());
    SlipDecoder d(max_frame_size);
    const auto frames = feed_all(d, stream);
    EXPECT_EQ(d.dropped(), 2);
    EXPECT_NE(d.error().find("longer"), std::string::npos);
    ASSERT_EQ(frames.size(), 2u);
    EXPECT_EQ(decode(frames[0]).sequence, sample_frame().sequence);
    EXPECT_EQ(frames[1], frame);
}

}  // namespace
}  // namespace bridge
