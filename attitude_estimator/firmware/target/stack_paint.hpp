// The stack is painted with this word at reset; the deepest word no longer holding it is the deepest the
// stack has reached.
#pragma once

#include <cstddef>
#include <cstdint>

extern "C" std::uint32_t __stack_bottom, __stack_top;

namespace firmware {

inline constexpr std::uint32_t kStackPaint = 0xA5C3A5C3u;

// Bytes of stack used so far (the deepest point since reset).
inline std::size_t stack_used() {
    const std::uint32_t* p = &__stack_bottom;
    while (p < &__stack_top && *p == kStackPaint) ++p;
    return static_cast<std::size_t>(reinterpret_cast<const char*>(&__stack_top) - reinterpret_cast<const char*>(p));
}

}  // namespace firmware
