// The on-board attitude computer as an FMU block (attitude_estimator.fmu): a sampled-data system. At each
// sample instant t_k = t_start + k·sample_period it runs one `estimate_sample` of the core on the inputs
// present at that instant and holds the results as discrete outputs until the next instant, as the DSP's
// timer interrupt does (000 §7, fig. 11). No continuous states, no state events.
#pragma once

#include <array>
#include <cstdint>

#include "attitude_estimator/estimator.hpp"
#include "fmu/block.hpp"

namespace attitude_estimator {

using Vec3d = std::array<double, 3>;

// Every variable of the block (double precision throughout). Defaults of the sensor chain match the other
// blocks: i_sc_norm is ssr_plant's short-circuit current of one panel at normal incidence and 1367 W/m²,
// the voltage channel and sensitivity are the HMC2003's (magnetometer block).
struct EstimatorData {
    // inputs. Their start values describe a consistent, lit, identity attitude (+x face towards the sun,
    // a 30 µT field along +z), so the block alone, unconnected, produces a valid estimate.
    Vec3d i_sh{0.84754, 0.0, 0.0};  // A, held differential currents I_sc+k − I_sc−k
    Vec3d v_mag{2.5, 2.5, 2.8};     // V, magnetometer outputs X, Y, Z
    double v_mag_ref = 2.5;         // V, magnetometer zero-field reference output
    Vec3d sun_ref{1.0, 0.0, 0.0};   // 1, sun direction, inertial frame (any length)
    Vec3d mag_ref{0.0, 0.0, 30e-6}; // T, geomagnetic field, inertial frame (any length)

    // parameters
    double sample_period = 0.05;                     // s: 20 Hz, the seed asks for more than 10 Hz
    Vec3d i_sc_norm{0.84754, 0.84754, 0.84754};      // A: ssr_plant's i_sc0 (000 eq. 5 denominators)
    double mag_sensitivity = kHmc2003Sensitivity<double>;  // V/T: 1 V/gauss
    double weight_sun = 0.5;                          // a_1 of 000 eq. 8 (normalized with weight_mag)
    double weight_mag = 0.5;                          // a_2
    std::int32_t adc_bits = 12;                       // TMS320F2808: 12 bits; 0 = ideal converter
    double i_adc_min = -1.2;                          // A: current channels' full-scale range, ±1.4 i_sc0
    double i_adc_max = 1.2;
    double v_adc_min = 0.0;                           // V: voltage channels (HMC2003 outputs 0…5 V)
    double v_adc_max = 5.0;
    fmu::FixedString<16> solver = "qmethod";          // "qmethod" (default, the seeds' method) or "fast"
    double min_sun_norm = kDefaultMinSunNorm<double>;         // 1: eclipse threshold on |s|
    double mag_rail_margin = kDefaultRailMargin<double>;      // V: saturation margin at the range ends
    double min_field = kDefaultMinField<double>;              // T
    double min_separation_sin = kDefaultMinSeparationSin<double>;  // 1: sin 5°

    // outputs (discrete: set at sample instants, held in between). Before the first sample: identity.
    std::array<double, 4> q_est{0.0, 0.0, 0.0, 1.0};  // scalar-last [x, y, z, w], w >= 0
    std::array<double, 9> A_est{1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0};  // row-major, w_body = A v_ref
    Vec3d sun_meas{};   // 1, unit sun vector in body axes (zero when sun_valid is false)
    Vec3d mag_meas{};   // 1, unit field vector in body axes (zero when mag_valid is false)
    Vec3d mag_field{};  // T, measured field in body axes
    double sun_norm = 0.0;  // 1, |s| of 000 eq. 5 before normalization
    double loss = 0.0;      // 1, L(A) of 000 eq. 8
    bool valid = false;
    bool sun_valid = false;
    bool mag_valid = false;
    std::int32_t samples = 0;  // samples taken so far (saturates at 2^31 − 1)

    // discrete state
    double t_start = 0.0;  // s, the start time: sample k is due at t_start + k·sample_period
    // Index k of the next sample. 64 bits (not an FMI Integer, so not declared): never overflows, and
    // t_start + k·sample_period is computed from it afresh each time, so sample instants never drift.
    std::int64_t next_index = 0;
};

class EstimatorBlock : public fmu::Block<EstimatorBlock, EstimatorData> {
public:
    static void declare(fmu::Table<EstimatorData>& t);
    static fmu::ModelInfo describe();

    void initialize(double t) override;
    fmu::EventUpdate event_update(double t, bool time_event_due) override;
    double next_time_event() const override;
    void validate() const override;

private:
    void take_sample(double t);
};

// The core's configuration and inputs from the block's variables (exposed for the tests).
EstimatorConfig<double> config_from(const EstimatorData& d);
SampleInputs<double> inputs_from(const EstimatorData& d);
// SolverKind of the `solver` parameter's text; throws fmu::Error for any other text.
SolverKind solver_from(std::string_view name);

}  // namespace attitude_estimator
