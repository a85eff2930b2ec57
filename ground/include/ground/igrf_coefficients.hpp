#pragma once
// The IGRF-14 main field at 2025.0 and its 2030.0 extrapolation (2025 + 5 yr x predictive SV), generated
// at build time from ground/data/IGRF14.SHC (see ground/data/README.md for the source). The truth
// (environment) and the on-board computer (attitude_estimator/core and its firmware) both read it.
#include <array>
#include <cstddef>

namespace ground {

struct IgrfCoefficient {
    int n;           // degree 1..13
    int m;           // order 0..n
    int is_h;        // 0: g_n^m, 1: h_n^m
    double at_2025;  // nT
    double at_2030;  // nT
};

inline constexpr std::size_t kIgrfCoefficientCount = 195;
inline constexpr int kIgrfMaxDegree = 13;
inline constexpr double kIgrfFirstYear = 2025.0;
inline constexpr double kIgrfLastYear = 2030.0;

extern const std::array<IgrfCoefficient, kIgrfCoefficientCount> kIgrf14Coefficients;

}  // namespace ground
