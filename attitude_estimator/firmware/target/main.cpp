// The estimator board: frames in SLIP over UART0, each answered by the board program (EstimatorBoard).
// This is the whole firmware; the bridge's master (cosim, transport "serial") is on the other end.
#include <array>
#include <cstdint>

#include "cmsdk_uart.hpp"
#include "estimator_board.hpp"
#include "protocol/frame_codec.hpp"
#include "protocol/slip_codec.hpp"

namespace {

constexpr std::uintptr_t kUart0 = 0x40004000;
constexpr std::uint32_t kBaudDiv = 217;  // 25 MHz APB / 115200 baud (QEMU ignores the rate)

attitude_estimator::EstimatorBoard board;
std::array<std::uint8_t, bridge::max_frame_size> frame_buffer;
std::array<std::uint8_t, bridge::max_frame_size> reply;
std::array<std::uint8_t, bridge::slip_max_encoded_size(bridge::max_frame_size)> wire;

}  // namespace

int main() {
    firmware::CmsdkUart uart(kUart0, kBaudDiv);
    bridge::SlipReader reader(frame_buffer);
    for (;;) {
        const auto byte = uart.get();
        if (!byte || reader.feed(*byte) != bridge::SlipReader::Event::frame) continue;
        const std::size_t n = board.answer(reader.frame(), reply);
        if (n == 0) continue;  // refused: no answer (the master's timeout and policy decide)
        const std::size_t m = bridge::slip_encode_into(std::span(reply).first(n), wire);
        for (std::size_t i = 0; i < m; ++i) uart.put(wire[i]);
    }
}
