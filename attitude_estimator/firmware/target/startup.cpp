// Reset for the Cortex-M4F: the vector table, then copy .data, clear .bss, paint the stack (the bench
// measures how much of it a sample uses), turn the FPU on, run the static constructors, call main.
#include <cstddef>
#include <cstdint>

#include "stack_paint.hpp"

extern "C" {
extern std::uint32_t __data_load, __data_start, __data_end, __bss_start, __bss_end, __stack_bottom, __stack_top;
extern void (*__preinit_array_start[])();
extern void (*__preinit_array_end[])();
extern void (*__init_array_start[])();
extern void (*__init_array_end[])();
int main();
[[noreturn]] void reset_handler();
[[noreturn]] void fault_handler();
}

namespace {

volatile std::uint32_t& reg(std::uintptr_t address) {
    return *reinterpret_cast<volatile std::uint32_t*>(address);
}
constexpr std::uintptr_t kCpacr = 0xE000ED88;  // Coprocessor Access Control: CP10 and CP11 = the FPU

}  // namespace

extern "C" [[noreturn]] void fault_handler() {
    for (;;) {}
}

extern "C" [[noreturn]] void reset_handler() {
    for (std::uint32_t *src = &__data_load, *dst = &__data_start; dst < &__data_end;) *dst++ = *src++;
    for (std::uint32_t* p = &__bss_start; p < &__bss_end; ++p) *p = 0;
    // Paint all of the stack below the current frame (the reset handler's own few words stay).
    std::uint32_t here = 0;
    for (std::uint32_t* p = &__stack_bottom; p + 16 < &here; ++p) *p = firmware::kStackPaint;
    reg(kCpacr) |= (0xFu << 20);  // full access to CP10 and CP11
    asm volatile("dsb\n isb" ::: "memory");
    for (auto* f = __preinit_array_start; f < __preinit_array_end; ++f) (*f)();
    for (auto* f = __init_array_start; f < __init_array_end; ++f) (*f)();
    main();
    fault_handler();
}

// The vector table: initial stack pointer, reset, and every fault to one handler that stops.
using Vector = void (*)();
extern "C" __attribute__((section(".vectors"), used)) const Vector vector_table[16] = {
    reinterpret_cast<Vector>(&__stack_top),
    reset_handler,
    fault_handler,  // NMI
    fault_handler,  // HardFault
    fault_handler,  // MemManage
    fault_handler,  // BusFault
    fault_handler,  // UsageFault
    nullptr,
    nullptr,
    nullptr,
    nullptr,
    fault_handler,  // SVCall
    fault_handler,  // DebugMonitor
    nullptr,
    fault_handler,  // PendSV
    fault_handler,  // SysTick (never enabled as an interrupt)
};
