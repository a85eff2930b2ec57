#include "magnetometer/hmc2003.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace magnetometer {

Mat3 sensor_matrix(double cross_axis, const Vec3& misalignment) {
    const double c = cross_axis;
    const Mat3 coupling = {1, c, c, c, 1, c, c, c, 1};
    const auto [ax, ay, az] = misalignment;
    // I − [θ×]: the rotation of the sensor frame by small angles, to first order.
    const Mat3 rotation = {1, az, -ay, -az, 1, ax, ay, -ax, 1};
    Mat3 m{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) m[3 * i + j] += coupling[3 * i + k] * rotation[3 * k + j];
    return m;
}

Vec3 multiply(const Mat3& m, const Vec3& v) {
    return {m[0] * v[0] + m[1] * v[1] + m[2] * v[2], m[3] * v[0] + m[4] * v[1] + m[5] * v[2],
            m[6] * v[0] + m[7] * v[1] + m[8] * v[2]};
}

Vec3 filter_derivative(const Vec3& b_sensed, const Vec3& b_filt, double bandwidth_hz) {
    const double rate = 2.0 * std::numbers::pi * bandwidth_hz;  // 1/τ of a first-order low-pass
    return {rate * (b_sensed[0] - b_filt[0]), rate * (b_sensed[1] - b_filt[1]), rate * (b_sensed[2] - b_filt[2])};
}

double sensitivity_at(double sensitivity, double tempco_per_kelvin, double t_celsius) {
    return sensitivity * (1.0 + tempco_per_kelvin * (t_celsius - reference_temperature));
}

double output_voltage(const OutputStage& stage, double b_filt, double noise, double set_polarity) {
    const double v = stage.v_null + set_polarity * stage.sensitivity * (b_filt + noise) + stage.offset;
    return std::clamp(v, stage.v_low, stage.v_high);
}

}  // namespace magnetometer
