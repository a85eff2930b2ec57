// The FMI words of a model description (causality, variability, initial, the variable types), spelled
// once for FMI 2.0 and 3.0 and shared by the runtime's description writers and the loader's reader.
// Each user's enums list their values in the standard's order; `spelling` and `parse` index them by
// position, and a user pins that order with a static_assert on the last value.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

namespace fmi_vocabulary {

// FMI 2.0 section 2.2.7, FMI 3.0 section 2.4.7.4: the same words in both versions.
inline constexpr std::array<std::string_view, 6> causalities = {"parameter", "calculatedParameter", "input", "output",
                                                                "local",     "independent"};
inline constexpr std::array<std::string_view, 5> variabilities = {"constant", "fixed", "tunable", "discrete",
                                                                  "continuous"};
// "none": the attribute is absent (inputs, the independent variable); it is never written.
inline constexpr std::array<std::string_view, 4> initials = {"none", "exact", "approx", "calculated"};

// The element name of a variable type: FMI 2.0 <ScalarVariable><Real/> ..., FMI 3.0 <Float64> ...
// (3.0 reads and writes an Enumeration through fmi3GetInt64, an Integer through fmi3GetInt32).
inline constexpr std::array<std::string_view, 5> types_fmi2 = {"Real", "Integer", "Boolean", "String", "Enumeration"};
inline constexpr std::array<std::string_view, 5> types_fmi3 = {"Float64", "Int32", "Boolean", "String", "Enumeration"};

template <class E, std::size_t N>
constexpr std::string_view spelling(const std::array<std::string_view, N>& words, E value) {
    const auto i = static_cast<std::size_t>(value);
    return i < N ? words[i] : std::string_view("?");
}

template <class E, std::size_t N>
constexpr std::optional<E> parse(const std::array<std::string_view, N>& words, std::string_view text) {
    for (std::size_t i = 0; i < N; ++i)
        if (words[i] == text) return static_cast<E>(i);
    return std::nullopt;
}

}  // namespace fmi_vocabulary
