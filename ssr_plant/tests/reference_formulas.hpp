// Independent reference formulas for the tests (not used by the library).
#pragma once

#include <cmath>

namespace ssr_plant_test {

// Principal branch of Lambert W for z = exp(log_z) ≥ 0, given ln z so that huge arguments do not
// overflow. Newton on w + ln w = ln z for large z, Halley on w e^w = z otherwise.
inline double lambert_w_of_exp(double log_z) {
    if (log_z > 1.0) {
        double w = log_z - std::log(log_z);
        for (int i = 0; i < 100; ++i) {
            const double f = w + std::log(w) - log_z;
            const double step = f / (1.0 + 1.0 / w);
            w -= step;
            if (std::abs(step) < 1e-15 * w) break;
        }
        return w;
    }
    const double z = std::exp(log_z);
    double w = std::log1p(z);
    for (int i = 0; i < 100; ++i) {
        const double ew = std::exp(w);
        const double f = w * ew - z;
        const double step = f / (ew * (w + 1.0) - (w + 2.0) * f / (2.0 * w + 2.0));
        w -= step;
        if (std::abs(step) < 1e-16 * (1.0 + std::abs(w))) break;
    }
    return w;
}

// Explicit solution of the single-diode equation (eq. 2 with R_s, R_sh) by Lambert W
// (Jain & Kapoor, Solar Energy Materials & Solar Cells 81 (2004) 269):
//   I = (R_sh (I_ph + I_0) − V) / (R_s + R_sh) − (a / R_s) W(θ),
//   θ = R_s R_sh I_0 / (a (R_s + R_sh)) · exp(R_sh (R_s I_ph + R_s I_0 + V) / (a (R_s + R_sh))).
inline double lambert_panel_current(double iph, double i0, double a, double rs, double rsh, double v) {
    const double log_theta =
        std::log(rs * rsh * i0 / (a * (rs + rsh))) + rsh * (rs * iph + rs * i0 + v) / (a * (rs + rsh));
    return (rsh * (iph + i0) - v) / (rs + rsh) - a / rs * lambert_w_of_exp(log_theta);
}

}  // namespace ssr_plant_test
