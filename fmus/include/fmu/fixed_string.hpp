// A string with a fixed capacity, stored inline, so that a block's data struct stays trivially
// copyable (saving an FMU state is then a byte copy) while still holding String parameters.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>

#include "fmu/errors.hpp"

namespace fmu {

// A text longer than a FixedString holds. Code built without exceptions (the estimator's data and its
// firmware) never assigns text at run time, the FMU's checked setter refusing a long string first: there it
// is a programming error and traps.
[[noreturn]] inline void refuse_long_string(std::size_t capacity) {
#if defined(__cpp_exceptions)
    throw Error("string longer than " + std::to_string(capacity) + " characters");
#else
    (void)capacity;
    __builtin_trap();
#endif
}

template <std::size_t Capacity>
struct FixedString {
    std::array<char, Capacity + 1> chars{};

    constexpr FixedString() = default;
    constexpr FixedString(std::string_view text) { assign(text); }  // NOLINT: implicit on purpose
    template <std::size_t N>
    constexpr FixedString(const char (&text)[N]) {  // NOLINT: lets a default read `label = "ball"`
        assign(std::string_view(text, N - 1));
    }

    constexpr void assign(std::string_view text) {
        if (text.size() > Capacity) refuse_long_string(Capacity);
        std::size_t i = 0;
        for (; i < text.size(); ++i) chars[i] = text[i];
        for (; i <= Capacity; ++i) chars[i] = '\0';
    }
    constexpr std::string_view view() const { return std::string_view(chars.data()); }
    const char* c_str() const { return chars.data(); }
    static constexpr std::size_t capacity() { return Capacity; }
    friend constexpr bool operator==(const FixedString& a, std::string_view b) { return a.view() == b; }
};

}  // namespace fmu
