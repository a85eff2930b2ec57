// The Honeywell HMC2003 three-axis magnetoresistive sensor hybrid and its output circuit (seed 000 §5,
// fig. 10): what a user of the real part sees on its X, Y, Z and +2.5 V reference pins. Plain C++.
//
// Signal chain per axis i (fields in tesla, 1 gauss = 1e-4 T):
//   b_sensed = M · b_body                 cross-axis sensitivity and misalignment (matrix M)
//   d b_filt / dt = 2π f_c (b_sensed − b_filt)   the sensor's bandwidth as a first-order low-pass
//   S(T) = S0 (1 + k_T (T − 25 °C))      sensitivity with its temperature coefficient
//   v_out = clamp(v_null + σ S(T) (b_filt + n) + v_off, v_low, v_high)
// where n is the bridge's noise (field-equivalent, held between noise samples), σ = +1 after a set
// pulse and −1 after a reset pulse, and the clamp is the saturation at the supply rails. A set or reset
// pulse re-magnetises the permalloy film and so reverses the sign of the bridge's response to the
// field; the bridge and amplifier offset v_off does not change. Half the difference of a set and a reset
// reading is S·B without the offset, half their sum is v_null + v_off (Honeywell application note AN-213,
// "Set/Reset Function for Magnetic Sensors").
#pragma once

#include <array>

namespace magnetometer {

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<double, 9>;  // row-major

inline constexpr double tesla_per_gauss = 1e-4;
inline constexpr double reference_temperature = 25.0;  // °C, where the datasheet gives S0

// M = C · R: C has 1 on the diagonal and `cross_axis` off it (each axis picks up that fraction of
// the two fields across it); R is the small-angle rotation I − [θ×] of the sensor axes by the
// misalignment angles θ (rad) about body x, y, z.
Mat3 sensor_matrix(double cross_axis, const Vec3& misalignment);

Vec3 multiply(const Mat3& m, const Vec3& v);

// Right-hand side of the first-order bandwidth filter, per axis.
Vec3 filter_derivative(const Vec3& b_sensed, const Vec3& b_filt, double bandwidth_hz);

// Sensitivity (V/T) at temperature t_celsius.
double sensitivity_at(double sensitivity, double tempco_per_kelvin, double t_celsius);

struct OutputStage {
    double sensitivity;  // V/T at the current temperature
    double v_null;       // V, zero-field output (= the reference pin)
    double offset;       // V, bridge offset referred to the output
    double v_low;        // V, lower rail
    double v_high;       // V, upper rail
};

// Output voltage of one axis. `set_polarity` is +1 after a set pulse, −1 after a reset pulse: it
// multiplies the field term (and the bridge noise), not the offset.
double output_voltage(const OutputStage& stage, double b_filt, double noise, double set_polarity);

}  // namespace magnetometer
