#include "magnetometer/held_noise.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "fmu/description.hpp"
#include "fmu/errors.hpp"
#include "fmu/model.hpp"

namespace magnetometer {

namespace {

constexpr std::uint64_t golden_gamma = 0x9E3779B97F4A7C15ull;

std::uint64_t mix64(std::uint64_t z) {  // the splitmix64 finaliser: a bijection with full avalanche
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

// Uniform in (0, 1): the top 53 bits, centred in their cell so that 0 is never returned (log(0)).
double unit_open(std::uint64_t bits) {
    return (static_cast<double>(bits >> 11) + 0.5) * 0x1.0p-53;
}

}  // namespace

std::int64_t noise_index(double t, double t0, double period, const char* t0_name, const char* period_name) {
    const double x = (t - t0) / period;
    if (!std::isfinite(x) || std::fabs(x) > max_noise_index)
        throw fmu::Error(std::string("magnetometer: (t - ") + t0_name + ")/" + period_name + " = (" +
                         fmu::format_real(t) + " - " + fmu::format_real(t0) + ")/" + fmu::format_real(period) + " = " +
                         fmu::format_real(x) +
                         " is not finite or exceeds the hold-interval limit max_noise_index = 2^53");
    auto k = static_cast<std::int64_t>(std::floor(x));
    if (fmu::reached(t, t0 + static_cast<double>(k + 1) * period)) ++k;  // t is k+1's start, rounded below it
    return k;
}

namespace {
// The two uniforms of (key, index, axis).
std::array<double, 2> uniform_pair(std::uint64_t key, std::int64_t index, int axis) {
    // Unsigned wrap-around keeps negative indices distinct from positive ones for |k| ≤ 2^53.
    const std::uint64_t counter = 2 * (3 * static_cast<std::uint64_t>(index) + static_cast<std::uint64_t>(axis));
    return {unit_open(mix64(key ^ mix64(counter))), unit_open(mix64(key ^ mix64(counter + 1)))};
}
}  // namespace

double held_normal(std::uint64_t seed, std::int64_t index, int axis) {
    const auto [u1, u2] = uniform_pair(mix64(seed + golden_gamma), index, axis);
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

double held_uniform(std::uint64_t seed, std::int64_t index, int stream) {
    // A key of its own: the uniforms of a seed are independent of the normals of the same seed.
    return uniform_pair(mix64(seed + 2 * golden_gamma), index, stream)[0];
}

}  // namespace magnetometer
