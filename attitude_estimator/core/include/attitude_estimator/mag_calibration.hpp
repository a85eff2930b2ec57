// Attitude-independent magnetometer calibration in flight: scale, non-orthogonality (a symmetric 3 × 3
// correction) and offset, from the measured field against the reference field's magnitude only — no
// attitude needed, so it runs before, and independently of, the attitude it improves.
//
// Model (Alonso and Shuster 2002, docs/references.md): the reading H relates to the true field B (body
// axes, up to a rotation the magnitude cannot see) by B = (I + D) H − b, D symmetric. With E = 2D + D²
// and c = (I + D) b, every sample gives one equation linear in (c, E, μ):
//   z = |H|² − |B_ref|² = 2 Hᵀ c − Hᵀ E H − μ,   μ = |b|² (taken as a free constant: the linear, "centered"
// first step of TWOSTEP; the constraint μ = |b|² is not imposed, its effect is second order in b).
// The normal equations are accumulated in a fixed 10 × 10 array (information form, weights 1/(4 σ² |H|²),
// the variance of z from a field noise σ per axis) and solved by LDLᵀ; I + D = √(I + E) (the symmetric
// square root), b = (I + D)⁻¹ c. H is the reading with the set/reset offset estimate taken out, so b is
// what stays fixed in body axes in it: the spacecraft's own field at the sensor (its residual dipole, the
// hard iron), which the set/reset pulses flip together with the earth's field and so cannot remove. What
// is left of the sensor's own offset changes sign with the polarity; it is not modelled here (with the
// equations taken at one polarity it would join b and come back doubled at the other) but left to the
// filter's offset state, whose sign follows the polarity. The corrected field is (I + D) H − b.
// Fixed sizes, no heap, no exceptions, float and double; the block runs it in its sample
// (docs/filter.md, "Magnetometer calibration").
#pragma once

#include <array>
#include <cstdint>

#include "attitude_estimator/types.hpp"

namespace attitude_estimator {

inline constexpr int kMagCalUnknowns = 10;  // c (3), E (6: xx, yy, zz, xy, xz, yz), μ
inline constexpr int kMagCalPacked = kMagCalUnknowns * (kMagCalUnknowns + 1) / 2;

template <class T>
struct MagCalibrationConfig {
    T sigma = T(0.05e-6);              // T: 1σ per axis of the field (noise, quantization, reference model)
    std::int32_t every = 20;           // samples between equations (20: 1 Hz at 20 Hz; neighbours add little)
    std::int32_t min_equations = 600;  // equations before a solution is applied (10 min at 1 Hz)
    std::int32_t solve_every = 60;     // equations between solves
    T max_distortion = T(0.05);        // largest |D_ij| accepted (larger: not enough rotation seen, or bad data)
    // T: largest |b| accepted, half the HMC2003's ±200 µT range (beyond it too little range is left for a
    // 60 µT earth field). 20 µT before issue 28's round 5: the spacecraft's own 7.3 µT plus a bias jump of
    // more than about 13 µT (a magnetised part, docs/faults.md) then had no solution accepted, and the
    // offset was never re-learnt (faults.toml's run 302, 23.3 µT: sunlit p95 1.10° → 0.32° with 60 µT).
    // Wrong solutions are refused by their 1σ (below) and the distortion bound, not by this.
    T max_offset = T(100e-6);
    // A solution is applied only once the equations pin it down: the 1σ of every element of E = 2D + D²
    // (from the inverse of the normal matrix, with `sigma` the readings' noise) below twice this, and of
    // every offset component below max_offset_sigma. Early on (a few hundred equations over a fraction of
    // an orbit) the field's magnitude varies too little to separate scale, offset and μ.
    T max_gain_sigma = T(1e-4);
    T max_offset_sigma = T(10e-9);  // T
    // The ground calibration uplinked before flight (docs/filter.md, "The ground calibration"): the
    // spacecraft's own field at the sensor as measured on the ground (T, body axes) and its 1σ per axis
    // (T; 0: no ground calibration). mag_calibration_start applies it from the first sample and enters it
    // into the equations as a prior on c, so that the in-flight solution refines it rather than replacing it.
    Vec3<T> prior_offset{};
    T prior_offset_sigma = T(0);
    // The field's 1σ in the filter while the ground calibration applies (T, white-equivalent; 0: the filter's
    // mag_sigma_calibrated): the offset is the ground's, but the sensor's scale, cross-axis coupling and
    // misalignment are not yet calibrated (an orbit without enough change of the field's size never is).
    T prior_field_sigma = T(0);
    // Meanwhile, instead (above 0): the field's error as it turns through the uncalibrated sensor, 1σ per axis
    // correlated over one radian of the tumble, at most prior_field_correlation (s): MekfConfig::mag_turn_*.
    T prior_field_fluctuation = T(0);
    T prior_field_correlation = T(0);
};

template <class T>
struct MagCalibrationState {
    std::array<T, kMagCalPacked> info{};   // upper triangle of Σ w L Lᵀ, row by row (fields in units of 10 µT)
    std::array<T, kMagCalUnknowns> rhs{};  // Σ w L z
    std::int32_t equations = 0;
    std::int32_t countdown = 0;                          // samples until the next equation
    bool valid = false;                                  // a solution is applied
    Matrix3RowMajor<T> gain{1, 0, 0, 0, 1, 0, 0, 0, 1};  // I + D
    Vec3<T> offset{};                                    // b, T
};

// Starts the calibration (all equations dropped) from the ground calibration of config, if any: its offset
// applied from the first sample (valid stays false: no in-flight solution yet) and its information
// 1/prior_offset_sigma² on c in the normal equations.
template <class T>
void mag_calibration_start(MagCalibrationState<T>& s, const MagCalibrationConfig<T>& config) noexcept;

// Whether the ground calibration applies (given, and no in-flight solution yet).
template <class T>
bool mag_calibration_prior_applies(const MagCalibrationState<T>& s, const MagCalibrationConfig<T>& config) noexcept {
    return !s.valid && config.prior_offset_sigma > T(0);
}

// The spacecraft's residual dipole m (A m², body axes) at dipole_position seen at sensor_position (m): the
// point dipole's field μ0/4π (3 r̂ (m·r̂) − m)/|r|³, r from the dipole to the sensor (T). How the computer
// derives its ground calibration's hard iron from the spacecraft's magnetic budget (estimator_data.cpp);
// zero when the two positions coincide.
template <class T>
Vec3<T> dipole_field_at_sensor(const Vec3<T>& moment, const Vec3<T>& dipole_position,
                               const Vec3<T>& sensor_position) noexcept;

// Offers one reading: H (T, body axes, the set/reset offset estimate taken out) and the reference field's magnitude
// (T). Takes an equation every config.every offers, solves every config.solve_every equations once
// config.min_equations are in, and applies the solution when it is within the config's bounds.
template <class T>
void mag_calibration_offer(MagCalibrationState<T>& s, const Vec3<T>& field, T ref_magnitude,
                           const MagCalibrationConfig<T>& config) noexcept;

// Solves the accumulated equations into (I + D, b); false (state unchanged) when singular or out of bounds.
template <class T>
bool mag_calibration_solve(MagCalibrationState<T>& s, const MagCalibrationConfig<T>& config) noexcept;

// The corrected field (I + D) H − b (before a solution: H less the ground calibration's offset, if any).
template <class T>
Vec3<T> mag_calibration_apply(const MagCalibrationState<T>& s, const Vec3<T>& field) noexcept;

// A new field at the sensor (a bias jump, fault_detection.hpp): the applied offset b moves by `shift` (T,
// the jump as the filter saw it, corrected by I + D) and the equations' information on the offset (c and μ)
// is dropped, that on the scale and non-orthogonality E kept: the next solution the new equations pin
// down replaces b.
template <class T>
void mag_calibration_reopen_offset(MagCalibrationState<T>& s, const Vec3<T>& shift) noexcept;

#define ATTITUDE_ESTIMATOR_MAG_CAL_EXTERN(T)                                                                      \
    extern template void mag_calibration_start(MagCalibrationState<T>&, const MagCalibrationConfig<T>&) noexcept; \
    extern template Vec3<T> dipole_field_at_sensor(const Vec3<T>&, const Vec3<T>&, const Vec3<T>&) noexcept;      \
    extern template void mag_calibration_offer(MagCalibrationState<T>&, const Vec3<T>&, T,                        \
                                               const MagCalibrationConfig<T>&) noexcept;                          \
    extern template bool mag_calibration_solve(MagCalibrationState<T>&, const MagCalibrationConfig<T>&) noexcept; \
    extern template Vec3<T> mag_calibration_apply(const MagCalibrationState<T>&, const Vec3<T>&) noexcept;        \
    extern template void mag_calibration_reopen_offset(MagCalibrationState<T>&, const Vec3<T>&) noexcept;
ATTITUDE_ESTIMATOR_MAG_CAL_EXTERN(float)
ATTITUDE_ESTIMATOR_MAG_CAL_EXTERN(double)
#undef ATTITUDE_ESTIMATOR_MAG_CAL_EXTERN

}  // namespace attitude_estimator
