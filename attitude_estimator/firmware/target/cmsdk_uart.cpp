#include "cmsdk_uart.hpp"

namespace firmware {

namespace {
// Register offsets and bits (Arm CoreLink SDK, APB UART).
constexpr std::uintptr_t kData = 0x00, kState = 0x04, kCtrl = 0x08, kBaudDiv = 0x10;
constexpr std::uint32_t kTxFull = 1u << 0, kRxFull = 1u << 1;
constexpr std::uint32_t kTxEnable = 1u << 0, kRxEnable = 1u << 1;
}  // namespace

CmsdkUart::CmsdkUart(std::uintptr_t base, std::uint32_t bauddiv) : base_(base) {
    reg(kBaudDiv) = bauddiv;
    reg(kCtrl) = kTxEnable | kRxEnable;
}

void CmsdkUart::put(std::uint8_t byte) {
    while (reg(kState) & kTxFull) {}
    reg(kData) = byte;
}

std::optional<std::uint8_t> CmsdkUart::get() {
    if (!(reg(kState) & kRxFull)) return std::nullopt;
    return static_cast<std::uint8_t>(reg(kData) & 0xFF);
}

}  // namespace firmware
