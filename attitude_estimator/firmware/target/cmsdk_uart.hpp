// UART0 of the MPS2 board, an Arm CMSDK APB UART (as QEMU's mps2-an386 models it; on QEMU's command line
// it is -serial ...). Polled, no interrupts: the firmware does nothing but answer frames.
#pragma once

#include <cstdint>
#include <optional>

namespace firmware {

class CmsdkUart {
public:
    // base: 0x40004000 for UART0; bauddiv: the APB clock over the baud rate (at least 16).
    CmsdkUart(std::uintptr_t base, std::uint32_t bauddiv);
    void put(std::uint8_t byte);
    std::optional<std::uint8_t> get();  // a received byte, or nothing

private:
    volatile std::uint32_t& reg(std::uintptr_t offset) const {
        return *reinterpret_cast<volatile std::uint32_t*>(base_ + offset);
    }
    std::uintptr_t base_;
};

}  // namespace firmware
