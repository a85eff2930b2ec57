// One analog-to-digital converter channel of the on-board computer (000 §7, fig. 11: the DSP reads the
// sample/hold currents and the magnetometer voltages through its A/D converter; the TMS320F2808 has 12
// bits). Header-only: it is a handful of operations.
#pragma once

#include <cmath>
#include <cstdint>

namespace attitude_estimator {

// Full-scale range [min, max] in the unit of the converted quantity (volts for the magnetometer, amperes
// for the sun-sensor currents) and resolution in bits.
//  - bits == 0: ideal converter, no quantization; the value is still clipped to [min, max] because the
//    range is the physical input range of the channel.
//  - 1 <= bits <= 24: codes 0 … 2^bits − 1 span [min, max] end to end, so both range ends are exactly
//    representable (the F2808 maps 0 V to code 0 and 3 V to code 4095 the same way). One LSB is
//    (max − min) / (2^bits − 1). Bits above 24 are treated as 24 (float has a 24-bit mantissa).
template <class T>
struct AdcConfig {
    unsigned bits = 12;
    T min = T(0);
    T max = T(5);
};

template <class T>
struct AdcReading {
    std::uint32_t code = 0;  // raw code (0 for an ideal converter)
    T value = T(0);          // the value the code stands for, in the unit of min/max
    bool clipped = false;    // the input was outside [min, max] (or not a number)
};

inline constexpr unsigned kAdcMaxBits = 24;

template <class T>
constexpr bool adc_config_valid(const AdcConfig<T>& adc) noexcept {
    return adc.max > adc.min;  // also false when either end is NaN
}

// One step (LSB) of the converter, (max − min) / (2^bits − 1); 0 for an ideal one (bits == 0).
template <class T>
constexpr T adc_step(const AdcConfig<T>& adc) noexcept {
    if (adc.bits == 0) return T(0);
    const unsigned bits = adc.bits > kAdcMaxBits ? kAdcMaxBits : adc.bits;
    return (adc.max - adc.min) / static_cast<T>((std::uint32_t{1} << bits) - 1u);
}

// Converts x. Rounding: to the nearest code, halves rounded up (code = floor(u + 1/2) with
// u = (x − min)(2^bits − 1)/(max − min)), done explicitly so the result does not depend on the FPU
// rounding mode. Clipping: x <= min gives code 0, x >= max gives the full code, both flagged `clipped`
// when strictly outside. A NaN input or an invalid range (max <= min) gives code 0, value min, clipped.
template <class T>
inline AdcReading<T> convert(const AdcConfig<T>& adc, T x) noexcept {
    AdcReading<T> r;
    if (!adc_config_valid(adc) || std::isnan(x)) {
        r.value = adc.min;
        r.clipped = true;
        return r;
    }
    r.clipped = x < adc.min || x > adc.max;
    if (adc.bits == 0) {
        r.value = x < adc.min ? adc.min : (x > adc.max ? adc.max : x);
        return r;
    }
    const unsigned bits = adc.bits > kAdcMaxBits ? kAdcMaxBits : adc.bits;
    const std::uint32_t full = (std::uint32_t{1} << bits) - 1u;
    const T span = adc.max - adc.min;
    if (x <= adc.min) {
        r.code = 0;
    } else if (x >= adc.max) {
        r.code = full;
    } else {
        const T u = (x - adc.min) / span * static_cast<T>(full);
        const T rounded = std::floor(u + T(0.5));
        r.code = rounded >= static_cast<T>(full) ? full : static_cast<std::uint32_t>(rounded);
    }
    r.value = adc.min + static_cast<T>(r.code) * span / static_cast<T>(full);
    return r;
}

}  // namespace attitude_estimator
