// A string with a fixed capacity, stored inline, so that a block's data struct stays trivially
// copyable (saving an FMU state is then a byte copy) while still holding String parameters.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>

#include "fmu/errors.hpp"

namespace fmu {

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
        if (text.size() > Capacity) throw Error("string longer than " + std::to_string(Capacity) + " characters");
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
