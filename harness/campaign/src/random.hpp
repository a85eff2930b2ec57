// A seeded pseudo-random generator whose whole state is four words: a campaign's draw for (seed, run,
// name) is reproducible anywhere, in any order, on any MPI rank.
// xoshiro256** (Blackman & Vigna, 2018) seeded through splitmix64; normal deviates by the polar
// Box–Muller method without a cached second value, so the state is just the four words.
#pragma once

#include <cmath>
#include <cstdint>

namespace campaign {

struct Random {
    std::uint64_t s[4] = {0x9E3779B97F4A7C15ull, 0xBF58476D1CE4E5B9ull, 0x94D049BB133111EBull, 1};

    void seed(std::uint64_t value) {
        for (auto& word : s) {  // splitmix64: spreads any seed, including 0, over the whole state
            value += 0x9E3779B97F4A7C15ull;
            std::uint64_t z = value;
            z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
            z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
            word = z ^ (z >> 31);
        }
    }

    std::uint64_t next() {
        const std::uint64_t result = rotl(s[1] * 5, 7) * 9;
        const std::uint64_t t = s[1] << 17;
        s[2] ^= s[0];
        s[3] ^= s[1];
        s[1] ^= s[2];
        s[0] ^= s[3];
        s[2] ^= t;
        s[3] = rotl(s[3], 45);
        return result;
    }

    // Uniform in (-1, 1), from the top 53 bits.
    double uniform_signed() { return (static_cast<double>(next() >> 11) + 0.5) * 0x1.0p-52 - 1.0; }

    // Standard normal deviate.
    double normal() {
        for (;;) {
            const double u = uniform_signed();
            const double v = uniform_signed();
            const double r2 = u * u + v * v;
            if (r2 > 0.0 && r2 < 1.0) return u * std::sqrt(-2.0 * std::log(r2) / r2);
        }
    }

private:
    static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
};

}  // namespace campaign
