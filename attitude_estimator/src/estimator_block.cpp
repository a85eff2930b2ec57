#include "attitude_estimator/estimator_block.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "fmu/errors.hpp"

namespace attitude_estimator {

namespace {

constexpr const char* kSolverNames[] = {"qmethod", "fast"};  // SolverKind, in the core's spelling

AdcConfig<double> adc(std::int32_t bits, double min, double max) {
    return AdcConfig<double>{static_cast<unsigned>(bits), min, max};
}

}  // namespace

SolverKind solver_from(std::string_view name) {
    if (name == kSolverNames[0]) return SolverKind::qmethod;
    if (name == kSolverNames[1]) return SolverKind::fast;
    throw fmu::Error("solver = '" + std::string(name) + "' is not one of: qmethod, fast");
}

EstimatorConfig<double> config_from(const EstimatorData& d) {
    EstimatorConfig<double> c;
    c.i_sc_norm = d.i_sc_norm;
    c.mag_sensitivity = d.mag_sensitivity;
    c.sun_weight = d.weight_sun;
    c.mag_weight = d.weight_mag;
    const auto current = adc(d.adc_bits, d.i_adc_min, d.i_adc_max);
    const auto voltage = adc(d.adc_bits, d.v_adc_min, d.v_adc_max);
    c.sun_adc = {current, current, current};
    c.mag_adc = {voltage, voltage, voltage};
    c.mag_ref_adc = voltage;  // the zero-field reference goes through a channel of the same kind
    c.solver = solver_from(d.solver.view());
    c.min_sun_norm = d.min_sun_norm;
    c.mag_rail_margin = d.mag_rail_margin;
    c.min_field = d.min_field;
    c.min_separation_sin = d.min_separation_sin;
    return c;
}

SampleInputs<double> inputs_from(const EstimatorData& d) {
    return SampleInputs<double>{
        .i_sh = d.i_sh, .v_mag = d.v_mag, .v_mag_ref = d.v_mag_ref, .sun_ref = d.sun_ref, .mag_ref = d.mag_ref};
}

void EstimatorBlock::declare(fmu::Table<EstimatorData>& t) {
    using D = EstimatorData;
    t.input("i_sh", &D::i_sh, "A",
            "Sample/hold differential currents I_sc+k - I_sc-k of the x, y, z panel pairs (ssr_plant i_sh)");
    t.input("v_mag", &D::v_mag, "V", "Magnetometer output voltages X, Y, Z (magnetometer v_out)");
    t.input("v_mag_ref", &D::v_mag_ref, "V", "Magnetometer zero-field reference voltage (magnetometer v_ref)");
    t.input("sun_ref", &D::sun_ref, "1", "Sun direction in the inertial frame, any nonzero length (environment sun_eci)");
    t.input("mag_ref", &D::mag_ref, "T",
            "Geomagnetic field in the inertial frame, any nonzero length (environment mag_eci)");

    t.parameter("sample_period", &D::sample_period, "s",
                "Time between samples; sample k is taken at start time + k*sample_period (default 20 Hz)")
        .min(1e-6);
    t.parameter("i_sc_norm", &D::i_sc_norm, "A",
                "Differential current of each axis with one panel facing the sun squarely (000 eq. 5 "
                "denominators; default ssr_plant's short-circuit current at 1367 W/m2)")
        .min(1e-6);
    t.parameter("mag_sensitivity", &D::mag_sensitivity, "V/T",
                "Magnetometer sensitivity (HMC2003: 1 V/gauss = 1e4 V/T)")
        .min(1e-3);
    t.parameter("weight_sun", &D::weight_sun, "1", "Weight of the sun observation in Wahba's loss (000 eq. 8)")
        .min(0.0);
    t.parameter("weight_mag", &D::weight_mag, "1", "Weight of the field observation in Wahba's loss (000 eq. 8)")
        .min(0.0);
    t.parameter("adc_bits", &D::adc_bits, "", "Resolution of every A/D channel in bits (TMS320F2808: 12); 0 = ideal")
        .range(0.0, 24.0);
    t.parameter("i_adc_min", &D::i_adc_min, "A", "Lower end of the current channels' full-scale range");
    t.parameter("i_adc_max", &D::i_adc_max, "A", "Upper end of the current channels' full-scale range");
    t.parameter("v_adc_min", &D::v_adc_min, "V",
                "Lower end of the voltage channels' full-scale range; also the magnetometer's lower rail");
    t.parameter("v_adc_max", &D::v_adc_max, "V",
                "Upper end of the voltage channels' full-scale range; also the magnetometer's upper rail");
    t.parameter("solver", &D::solver, "",
                "Wahba solver: qmethod (default; largest eigenpair of K, 000 eq. 15) or fast (closed form for "
                "two observations)")
        .one_of({kSolverNames[0], kSolverNames[1]});
    t.parameter("min_sun_norm", &D::min_sun_norm, "1",
                "The sun vector is invalid (eclipse, albedo only) when |s| is below this")
        .min(0.0);
    t.parameter("mag_rail_margin", &D::mag_rail_margin, "V",
                "A magnetometer channel this close to a range end counts as saturated (field invalid)")
        .min(0.0);
    t.parameter("min_field", &D::min_field, "T", "The field vector is invalid when |B| is below this").min(0.0);
    t.parameter("min_separation_sin", &D::min_separation_sin, "1",
                "The attitude is invalid unless sun and field are more than asin(this) from (anti)parallel")
        .range(0.0, 1.0);

    t.output("q_est", &D::q_est, "1", "Estimated attitude quaternion, scalar-last [x, y, z, w], w >= 0")
        .discrete()
        .depends_on({});
    t.output("A_est", &D::A_est, "1", "Estimated attitude matrix, row-major, w_body = A v_ref")
        .discrete()
        .depends_on({});
    t.output("sun_meas", &D::sun_meas, "1", "Measured sun direction, body axes, unit (zero when sun_valid is false)")
        .discrete()
        .depends_on({});
    t.output("mag_meas", &D::mag_meas, "1", "Measured field direction, body axes, unit (zero when mag_valid is false)")
        .discrete()
        .depends_on({});
    t.output("mag_field", &D::mag_field, "T", "Measured geomagnetic field, body axes")
        .discrete()
        .depends_on({});
    t.output("sun_norm", &D::sun_norm, "1", "|s| of 000 eq. 5 before normalization: 1 in full sun")
        .discrete()
        .depends_on({});
    t.output("loss", &D::loss, "1", "Wahba loss L(A) of the estimate (000 eq. 8); 0 when not valid")
        .discrete()
        .depends_on({});
    t.output("valid", &D::valid, "", "The estimate is valid (sun and field valid and separated)")
        .discrete()
        .depends_on({});
    t.output("sun_valid", &D::sun_valid, "", "The sun vector is valid (not in eclipse)")
        .discrete()
        .depends_on({});
    t.output("mag_valid", &D::mag_valid, "", "The field vector is valid (no channel saturated, field not tiny)")
        .discrete()
        .depends_on({});
    t.output("samples", &D::samples, "", "Number of samples taken, the one at the start time included")
        .discrete()
        .depends_on({});

    t.local("t_start", &D::t_start, "s", "Start time: sample k is due at t_start + k*sample_period").discrete();
}

fmu::ModelInfo EstimatorBlock::describe() {
    fmu::ModelInfo info;
    info.model_identifier = "attitude_estimator";
    info.model_name = "attitude_estimator";
    info.description = "On-board attitude computer: sun vector from panel currents, HMC2003 field, Q-method, sampled";
    info.documentation_html =
        "<p>The attitude computer of seed paper 000 sections 6-8 (fig. 11) as a sampled-data block. At each "
        "sample instant t<sub>k</sub> = t<sub>0</sub> + k&middot;<code>sample_period</code> (time events, "
        "t<sub>0</sub> the start time, k an integer count so the instants never drift; the sample at "
        "t<sub>0</sub> is taken in initialization) it digitizes the inputs with <code>adc_bits</code>-bit "
        "converters (currents over [<code>i_adc_min</code>, <code>i_adc_max</code>], voltages over "
        "[<code>v_adc_min</code>, <code>v_adc_max</code>]), forms the sun vector "
        "s<sub>k</sub> = i<sub>sh,k</sub>/i<sub>sc_norm,k</sub> (000 eq. 5) and the field "
        "B = (v<sub>mag</sub> &minus; v<sub>mag_ref</sub>)/S, and solves Wahba's problem (000 eq. 7-9) against "
        "the inertial references <code>sun_ref</code> and <code>mag_ref</code> with the Q-method "
        "(<code>solver = qmethod</code>, 000 eq. 15) or its closed form for two observations "
        "(<code>solver = fast</code>). Every output is discrete: held between samples.</p>"
        "<p>Conventions: quaternion scalar-last [x, y, z, w] with w &ge; 0; A row-major with "
        "w<sub>body</sub> = A v<sub>ref</sub>. Validity: the sun vector is invalid when |s| &lt; "
        "<code>min_sun_norm</code> (eclipse); the field is invalid when a channel is within "
        "<code>mag_rail_margin</code> of a range end (saturated) or |B| &lt; <code>min_field</code>; the "
        "estimate is invalid when either is, or when the two directions are within "
        "asin(<code>min_separation_sin</code>) of (anti)parallel. An invalid sample outputs the identity "
        "attitude and loss 0 (do not use it), and is still counted in <code>samples</code>.</p>"
        "<p>Defaults match the other blocks: <code>i_sc_norm</code> = 0.84754 A is ssr_plant's short-circuit "
        "current of one panel at normal incidence and 1367 W/m<sup>2</sup>, current range &plusmn;1.2 A; "
        "magnetometer 0-5 V, 2.5 V reference, 1e4 V/T. In Co-Simulation the inputs are held over each "
        "communication step, so a sample on a communication point sees the inputs of the step that ends "
        "there.</p>";
    info.default_experiment = {.start_time = 0.0, .stop_time = 2.0, .tolerance = 1e-6, .step_size = 0.01};
    return info;
}

void EstimatorBlock::validate() const {
    const auto& d = data();
    solver_from(d.solver.view());
    if (!(d.i_adc_max > d.i_adc_min)) throw fmu::Error("i_adc_max must be above i_adc_min");
    if (!(d.v_adc_max - d.v_adc_min > 2.0 * d.mag_rail_margin))
        throw fmu::Error("v_adc_max - v_adc_min must exceed twice mag_rail_margin (else every field reads saturated)");
    if (!(d.weight_sun + d.weight_mag > 0.0)) throw fmu::Error("weight_sun + weight_mag must be positive");
    if (!(d.sample_period > 0.0)) throw fmu::Error("sample_period must be positive");
}

void EstimatorBlock::take_sample(double) {
    auto& d = data();
    const SampleResult<double> r = estimate_sample(inputs_from(d), config_from(d));
    d.q_est = {r.q.x, r.q.y, r.q.z, r.q.w};
    d.A_est = r.a;
    d.sun_meas = r.sun_meas;
    d.mag_meas = r.mag_meas;
    d.mag_field = r.mag_field;
    d.sun_norm = r.sun_norm;
    d.loss = r.loss;
    d.valid = r.valid;
    d.sun_valid = r.sun_valid;
    d.mag_valid = r.mag_valid;
    if (d.samples < std::numeric_limits<std::int32_t>::max()) ++d.samples;
}

void EstimatorBlock::initialize(double t) {
    auto& d = data();
    // From scratch every time (initialize runs on each read in initialization mode): the sample at the
    // start time sees the inputs as they are when initialization ends.
    d.t_start = t;
    d.samples = 0;
    take_sample(t);
    d.next_index = 1;
}

fmu::EventUpdate EstimatorBlock::event_update(double t, bool time_event_due) {
    auto& d = data();
    if (!time_event_due || !fmu::reached(t, next_time_event())) return {};
    take_sample(t);
    ++d.next_index;
    // A host that stepped over sample instants (it should not) gets the next one after t, not a burst.
    const double periods = std::floor((t - d.t_start) / d.sample_period);
    if (periods > static_cast<double>(d.next_index)) d.next_index = static_cast<std::int64_t>(periods);
    while (fmu::reached(t, next_time_event())) ++d.next_index;
    return {};
}

double EstimatorBlock::next_time_event() const {
    const auto& d = data();
    // From the integer count, not a running sum: instant k is as exact as one multiply-add can make it.
    return d.t_start + static_cast<double>(d.next_index) * d.sample_period;
}

}  // namespace attitude_estimator

FMU_BLOCK(attitude_estimator::EstimatorBlock)
