#include "ssr_plant/pv_panel.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

namespace ssr_plant {
namespace {

constexpr double boltzmann = 1.380649e-23;             // J/K (SI, exact)
constexpr double elementary_charge = 1.602176634e-19;  // C (SI, exact)

// For a trial (a, R_s), I_ph and I_D follow linearly from the short-circuit and open-circuit points
// (eq. 2 at (0, Isc) and (Voc, 0)). Written with exponentials of non-positive arguments so that
// small trial values of a cannot overflow. Returns I_D·(exp(v/a) − 1) as a function.
struct Trial {
    double a;
    double rs;
    double rsh;
    double isc;
    double voc;
    double scale;  // I_D · exp(Voc / a)

    Trial(const PanelDatasheet& s, double a_, double rs_) : a(a_), rs(rs_), rsh(s.shunt_resistance) {
        isc = s.short_circuit_current;
        voc = s.open_circuit_voltage;
        const double num = isc * (1.0 + rs / rsh) - voc / rsh;  // I_D (e2 − e1), eq. 2 subtracted
        scale = num / (1.0 - std::exp((isc * rs - voc) / a));
    }
    double saturation_current() const { return scale * std::exp(-voc / a); }
    double diode(double v) const { return scale * (std::exp((v - voc) / a) - std::exp(-voc / a)); }
    double diode_slope(double v) const { return scale * std::exp((v - voc) / a) / a; }
    double photocurrent() const { return voc / rsh + diode(voc); }
    // eq. 2 at the maximum-power point, as a residual.
    double mpp_residual(double vmp, double imp) const {
        const double vd = vmp + imp * rs;
        return photocurrent() - diode(vd) - vd / rsh - imp;
    }
    // dP/dV = 0 at the MPP ⇔ −dI/dV = Imp/Vmp, with dI/dV = −g / (1 + R_s g) from eq. 2.
    double slope_residual(double vmp, double imp) const {
        const double g = diode_slope(vmp + imp * rs) + 1.0 / rsh;
        return g / (1.0 + rs * g) - imp / vmp;
    }
};

template <class F>
double bisect(F f, double lo, double hi, double flo) {
    for (int i = 0; i < 200 && hi - lo > 1e-15 * std::max(1.0, std::abs(hi)); ++i) {
        const double mid = 0.5 * (lo + hi);
        const double fm = f(mid);
        if ((fm > 0) == (flo > 0)) {
            lo = mid;
            flo = fm;
        } else {
            hi = mid;
        }
    }
    return 0.5 * (lo + hi);
}

}  // namespace

DiodeModel fit_diode_model(const PanelDatasheet& s) {
    const bool finite = std::isfinite(s.rated_irradiance) && std::isfinite(s.short_circuit_current) &&
                        std::isfinite(s.open_circuit_voltage) && std::isfinite(s.max_power_current) &&
                        std::isfinite(s.max_power_voltage) && std::isfinite(s.shunt_resistance) &&
                        std::isfinite(s.cell_temperature);
    if (!finite || s.rated_irradiance <= 0 || s.cells_in_series < 1 || s.cell_temperature <= 0 ||
        s.shunt_resistance <= 0)
        throw ParameterError(
            "panel datasheet: values must be finite, irradiance, cell count, temperature and "
            "shunt resistance positive");
    if (!(0 < s.max_power_current && s.max_power_current < s.short_circuit_current && 0 < s.max_power_voltage &&
          s.max_power_voltage < s.open_circuit_voltage))
        throw ParameterError("panel datasheet: need 0 < Imp < Isc and 0 < Vmp < Voc");
    if (s.open_circuit_voltage / s.shunt_resistance >= s.short_circuit_current)
        throw ParameterError("panel datasheet: shunt resistance too small for Isc and Voc (Voc/Rsh >= Isc)");

    const double vt = boltzmann * s.cell_temperature / elementary_charge;
    const double ns_vt = s.cells_in_series * vt;
    const double vmp = s.max_power_voltage;
    const double imp = s.max_power_current;
    const double a_lo = 0.3 * ns_vt;  // ideality 0.3…10 spans every physical cell and more
    const double a_hi = 10.0 * ns_vt;

    // Inner problem: for a given R_s, the a that puts the curve through the MPP (r3 decreases with a:
    // a softer knee gives less current at Vmp).
    auto fit_a = [&](double rs) -> std::optional<double> {
        auto r3 = [&](double a) { return Trial(s, a, rs).mpp_residual(vmp, imp); };
        const double f_lo = r3(a_lo);
        const double f_hi = r3(a_hi);
        if (!(f_lo > 0 && f_hi < 0)) return std::nullopt;
        return bisect(r3, a_lo, a_hi, f_lo);
    };
    // Outer problem: the R_s whose fit has dP/dV = 0 at the MPP. Scan for a sign change, then bisect.
    const double rs_max = (s.open_circuit_voltage - vmp) / imp;
    auto r4 = [&](double rs) -> std::optional<double> {
        const auto a = fit_a(rs);
        if (!a) return std::nullopt;
        return Trial(s, *a, rs).slope_residual(vmp, imp);
    };
    constexpr int scan = 400;
    std::optional<double> prev_rs, prev_r;
    double rs_root = -1.0;
    for (int i = 0; i < scan && rs_root < 0; ++i) {
        const double rs = rs_max * i / scan;
        const auto r = r4(rs);
        if (r && prev_r && ((*r > 0) != (*prev_r > 0))) {
            double lo = *prev_rs, hi = rs, flo = *prev_r;
            for (int k = 0; k < 200 && hi - lo > 1e-15 * std::max(1.0, hi); ++k) {
                const double mid = 0.5 * (lo + hi);
                const auto fm = r4(mid);
                if (!fm) break;
                if ((*fm > 0) == (flo > 0)) {
                    lo = mid;
                    flo = *fm;
                } else {
                    hi = mid;
                }
            }
            rs_root = 0.5 * (lo + hi);
        }
        if (r) {
            prev_rs = rs;
            prev_r = r;
        }
    }
    if (rs_root < 0)
        throw ParameterError(
            "panel datasheet: no single-diode fit (R_s >= 0, ideality 0.3..10) passes through "
            "Isc, Voc and the maximum-power point with the given shunt resistance");
    const double a = *fit_a(rs_root);
    const Trial t(s, a, rs_root);
    DiodeModel m;
    m.photocurrent_rated = t.photocurrent();
    m.saturation_current = t.saturation_current();
    m.ideality_voltage = a;
    m.ideality = a / ns_vt;
    m.series_resistance = rs_root;
    m.shunt_resistance = s.shunt_resistance;
    m.rated_irradiance = s.rated_irradiance;
    return m;
}

double photocurrent(const DiodeModel& m, double effective_irradiance) {
    return m.photocurrent_rated * std::max(0.0, effective_irradiance) / m.rated_irradiance;
}

double panel_current(const DiodeModel& m, double iph, double v, double extra_series_resistance) {
    const double a = m.ideality_voltage;
    const double i0 = m.saturation_current;
    const double rsh = m.shunt_resistance;
    const double rs = m.series_resistance + extra_series_resistance;
    iph = std::max(0.0, iph);
    if (rs <= 0.0) return iph - i0 * std::expm1(v / a) - v / rsh;  // eq. 2 explicit when R_s = 0

    // Unknown: the diode voltage x = V + I R_s. g(x) = I_ph − I_D (e^{x/a} − 1) − x/R_sh − (x − V)/R_s
    // is strictly decreasing, so its root is unique. Bracket: g > 0 at x = min(0, V) − 1 (every term
    // is ≥ 0 and the last > 0); g < 0 beyond (I_ph + I_D + V/R_s) / (1/R_s + 1/R_sh) because
    // −I_D (e^{x/a} − 1) ≤ I_D.
    // Conductances and 1/a once: the loop below then divides only for its step.
    const double inv_a = 1.0 / a, g_s = 1.0 / rs, g_sh = 1.0 / rsh;
    double lo = std::min(0.0, v) - 1.0;
    double hi = (iph + i0 + v * g_s) / (g_s + g_sh);
    hi += 1e-9 * (1.0 + std::abs(hi));
    // Start where the panel is near short circuit (the usual operating region on the bus).
    double x = std::clamp(v + rs * iph, lo, hi);
    double em1 = std::expm1(x * inv_a);  // kept equal to expm1(x / a): one exponential serves g, g' and g''
    for (int it = 0; it < 200; ++it) {
        const double gx = iph - i0 * em1 - x * g_sh - (x - v) * g_s;
        if (gx == 0.0) break;
        const double g_diode = i0 * (em1 + 1.0) * inv_a;  // the diode's conductance I_D e^{x/a} / a
        const double dgx = -g_diode - g_sh - g_s;         // g' < 0; g'' = −g_diode / a; g''' = g'' / a
        if (gx > 0)
            lo = x;
        else
            hi = x;
        const double tol = 1e-14 * std::max(1.0, std::abs(x));
        // Halley's step δ = δ_N / (1 − g g'' / (2 g'²)), Newton's δ_N = −g / g': the exponential that
        // gives g' gives g'' too, and the cubic convergence saves one exponential on a bright panel at the
        // bus voltage (2 instead of 3). Far from the root (a correction factor below 1/2) Newton's step.
        const double newton = -gx / dgx;
        const double denominator = 1.0 + 0.5 * newton * g_diode * inv_a / (g_diode + g_sh + g_s);
        const bool halley = denominator >= 0.5;
        const double step = halley ? newton / denominator : newton;
        // Converged: to leading order the error after the step is, for Halley,
        // |g''² / (4 g'²) − g''' / (6 g')| δ³ ≤ (1/4 + 1/6) δ³ / a² (|g''| ≤ |g'| / a, |g'''| ≤ |g'| / a²),
        // for Newton |g'' / (2 g')| δ² ≤ δ² / (2a). Once that is below tol, take the step and stop (checked
        // before the bracket test, which a vanishing step would fail by rounding onto the bound just moved
        // to x). The exponential follows without a call: e^{δ/a} = 1 + r + r²/2 + r³/6 (r = δ/a ≤
        // (tol / a)^(1/3), 1e-4 near the bus: the dropped r⁴/24 is below the tolerance).
        const double bound = halley ? std::abs(step) * step * step * inv_a * inv_a : 0.5 * step * step * inv_a;
        if (bound <= tol) {
            const double r = step * inv_a;
            em1 += (em1 + 1.0) * (r + r * r * (0.5 + r / 6.0));
            x += step;
            break;
        }
        // Safeguard: a step that leaves the bracket (or is not finite) becomes a bisection.
        const double next = x + step;
        x = (std::isfinite(next) && next > lo && next < hi) ? next : 0.5 * (lo + hi);
        em1 = std::expm1(x * inv_a);
        if (hi - lo <= tol) break;
    }
    // Read the current off the less sensitive branch.
    const double diode_conductance = i0 * (em1 + 1.0) * inv_a + g_sh;
    if (diode_conductance < g_s) return iph - i0 * em1 - x * g_sh;
    return (x - v) / rs;
}

DiodeModel at_temperature(const DiodeModel& ref, const PanelDatasheet& sheet, double temperature) {
    if (temperature == sheet.cell_temperature) return ref;
    if (!(temperature > 0.0) || !std::isfinite(temperature))
        throw ParameterError("panel temperature must be finite and positive (K)");
    const double dt = temperature - sheet.cell_temperature;
    DiodeModel m = ref;
    m.photocurrent_rated = ref.photocurrent_rated * (1.0 + sheet.isc_temperature_coefficient * dt);
    m.ideality_voltage = ref.ideality_voltage * temperature / sheet.cell_temperature;
    const double voc = sheet.open_circuit_voltage + sheet.voc_temperature_coefficient * dt;
    if (!(voc > 0.0) || !(m.photocurrent_rated > voc / ref.shunt_resistance))
        throw ParameterError("panel at " + std::to_string(temperature) +
                             " K: no open-circuit voltage left (isc/voc_temperature_coefficient)");
    // Open circuit at the rated irradiance: I_ph − I_0 (exp(Voc / a) − 1) − Voc / R_sh = 0.
    m.saturation_current = (m.photocurrent_rated - voc / ref.shunt_resistance) / std::expm1(voc / m.ideality_voltage);
    return m;
}

}  // namespace ssr_plant
