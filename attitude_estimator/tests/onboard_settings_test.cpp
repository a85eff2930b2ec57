// Every declared parameter of the estimator reaches the on-board computer (issue 25): the block's
// onboard_settings_from copies some fifty parameters into the core's settings by hand, and a parameter it
// forgets would be accepted, documented and ignored. Table-driven: for each parameter of the block's
// variable table (each element of an array on its own), the value is changed through the table, the block
// reconfigured, and the settings must differ from those of the unchanged block. A parameter that matters
// only in some configuration (the Kelly table, a sun method's own noise, the on-board references) is
// changed in that configuration; those that never reach the computer are named below, each with its reason.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "attitude_estimator/estimator_block.hpp"
#include "fmu/errors.hpp"
#include "fmu/testing/block_driver.hpp"
#include "fmu/testing/changed_value.hpp"
#include "fmu/value_access.hpp"
#include "magnetometer/spacecraft_field.hpp"
#include "orbit/tle.hpp"

namespace attitude_estimator {
namespace {

using Driver = fmu::testing::BlockDriver<EstimatorBlock>;

// Two element sets of one satellite a day apart (harness/systems/leo_orbit.ssd's truth and computer).
constexpr const char* kLine1 = "1 90001U          26079.00000000  .00002000  00000-0  15000-3 0  9995";
constexpr const char* kLine2 = "2 90001  64.9000   0.0000 0012000  90.0000 270.0000 14.98524078  1001";
constexpr const char* kOtherLine1 = "1 90001U          26078.00000000  .00002000  00000-0  15000-3 0  9994";
constexpr const char* kOtherLine2 = "2 90001  64.9000   3.1277 0012000  90.3760 275.3137 14.98524078  1006";

// The settings as numbers. Composite parts are read through what they compute where their layout is not
// a plain list of numbers: the on-board references through their models evaluated at two times.
template <class T>
void put_adc(std::vector<double>& out, const AdcConfig<T>& a) {
    out.insert(out.end(), {static_cast<double>(a.bits), a.min, a.max});
}

std::vector<double> numbers(const OnboardSettings<double>& s) {
    std::vector<double> out;
    auto put = [&out](std::initializer_list<double> xs) { out.insert(out.end(), xs); };
    auto put_all = [&out](const auto& array) {
        for (const auto x : array) out.push_back(static_cast<double>(x));
    };
    const EstimatorConfig<double>& c = s.estimator;
    put_all(c.i_sc_norm);
    put({c.mag_sensitivity, c.sun_weight, c.mag_weight, static_cast<double>(c.solver), c.min_sun_norm,
         c.mag_rail_margin, c.min_field, c.min_separation_sin});
    for (const auto& a : c.sun_adc) put_adc(out, a);
    for (const auto& a : c.mag_adc) put_adc(out, a);
    put_adc(out, c.mag_ref_adc);
    for (const auto& a : c.face_adc) put_adc(out, a);
    const SunMethodConfig<double>& m = c.sun;
    put({static_cast<double>(m.method), static_cast<double>(m.response.law), static_cast<double>(m.response.n),
         m.response.cos_join, m.dark_threshold, m.min_sun_norm, static_cast<double>(m.min_lit_axes), m.cone_tolerance,
         m.cone_cluster_angle, static_cast<double>(m.cube_refusals_before_reset), m.cube_max_step,
         m.normalization_tolerance, m.printed_tolerance, m.cone_earth_sin_radius, m.cone_fit_tolerance,
         m.cone_albedo_max});
    put_all(m.i_face_norm);
    put_all(m.response.x);
    put_all(m.response.y);
    put_all(m.response.d);
    put({static_cast<double>(s.set_reset.period_samples), static_cast<double>(s.set_reset.offset_window),
         static_cast<double>(s.rate.measure), static_cast<double>(s.rate.window), s.rate.min_interval,
         s.rate.max_interval, static_cast<double>(s.filter), static_cast<double>(s.filter_scale),
         static_cast<double>(s.mag_calibration), s.sample_period, s.rate_interval,
         static_cast<double>(s.reference_source)});
    const MekfConfig<double>& f = s.mekf;
    put({f.attitude_noise,
         f.rate_noise,
         f.offset_noise,
         f.scale_noise,
         f.sun_sigma,
         f.mag_sigma,
         f.face_sigma,
         f.sun_correlation_time,
         static_cast<double>(f.sun_turn_correlation),
         f.mag_ref_sigma,
         f.mag_ref_rms,
         f.mag_ref_correlation,
         f.mag_ref_tilt,
         f.mag_sigma_calibrated,
         f.mag_sigma_calibrated_eclipse,
         f.mag_hard_iron_sigma,
         f.init_attitude_sigma,
         f.init_rate_sigma,
         f.init_offset_sigma,
         f.init_scale_sigma,
         static_cast<double>(f.estimate_offset),
         static_cast<double>(f.estimate_scale),
         f.gate,
         f.face_gate,
         static_cast<double>(f.reset_after),
         f.valid_bound,
         f.max_init_gap,
         f.watch_time,
         f.watch_gate,
         static_cast<double>(f.watch_sun),
         static_cast<double>(f.hold_field_axis),
         static_cast<double>(f.gravity_gradient),
         f.torque_noise,
         f.start_rate_sigma,
         f.drag.drag_coefficient,
         f.drag_density_scale,
         f.drag_density_sigma,
         f.drag_correlation_time});
    put_all(f.inertia);
    put_all(f.dipole);
    put_all(f.drag.size);
    put_all(f.drag.centre_of_mass);
    const MagCalibrationConfig<double>& k = s.mag_cal;
    put({k.sigma, static_cast<double>(k.every), static_cast<double>(k.min_equations),
         static_cast<double>(k.solve_every), k.max_distortion, k.max_offset, k.max_gain_sigma, k.max_offset_sigma,
         k.prior_offset_sigma, k.prior_field_sigma, k.prior_field_fluctuation, k.prior_field_correlation});
    put_all(k.prior_offset);
    const OnboardReferenceConfig<double>& r = s.references;
    put({r.period, r.tle_minutes_at_midnight, static_cast<double>(r.field.degree), r.clock.midnight_days,
         r.clock.epoch_seconds, r.clock.epoch_year});
    for (const double t : {0.0, 5000.0}) {
        const ReferenceKnot<double> knot = evaluate_references(r, t);
        put_all(knot.sun);
        put_all(knot.field);
        put_all(knot.position);
        put({knot.sun_distance, static_cast<double>(knot.valid)});
    }
    const FaultDetectionConfig<double>& d = s.faults;
    put({static_cast<double>(d.enabled), d.confirm_time, d.face_min_response, d.face_deficit, d.face_excess,
         d.others_min_irradiance, d.others_min_predicted, d.bus_tolerance, d.flip_min_field, d.flip_fraction,
         d.norm_tolerance, d.flip_min_field_calibrated});
    // The panel tests (ratio, scale, dark, stuck) and the magnetometer's frozen, spike and bias tests.
    put({d.face_ratio_min_response, d.face_ratio, d.face_scale_min, d.face_dark_max, d.face_stuck_change,
         d.face_stuck_tolerance, d.face_direct_min});
    put({d.frozen_min_field, d.frozen_tolerance, d.spike_sigma, d.spike_gate, d.spike_window,
         static_cast<double>(d.spike_count), d.bias_window, d.bias_threshold, d.bias_noise_factor});
    for (const auto& k : s.string_field_per_amp) put_all(k);
    return out;
}

// A different value of the parameter (fmu/testing/changed_value.hpp); for the element set's text, the other
// set; for its epoch as a number, half a day later (5 % of a Julian date is 300 centuries).
void change(std::span<std::byte> bytes, const fmu::Variable& v) {
    if (v.name == "tle_elements[1]")
        fmu::write_real(bytes, v, fmu::read_real(bytes, v) + 0.5);
    else if (!fmu::testing::write_changed_value(bytes, v))
        fmu::write_string(bytes, v, v.name == "tle_line1" ? kOtherLine1 : kOtherLine2);
}

// The configuration each parameter is changed in (by the start of its name); the block's defaults otherwise.
void onboard_references(EstimatorData& d) {
    d.reference_source = ReferenceSource::onboard;
    d.tle_line1.assign(kLine1);
    d.tle_line2.assign(kLine2);
}
void onboard_references_from_numbers(EstimatorData& d) {
    d.reference_source = ReferenceSource::onboard;
    d.tle_elements = orbit::elements_of(orbit::parse_tle(kLine1, kLine2));
}
std::function<void(EstimatorData&)> configuration_for(const std::string& name) {
    auto sun_method_of_element = [name](EstimatorData& d) {  // "filter_sun_sigma_method[3]": method 2 (cones)
        d.sun_method = static_cast<SunMethod>(name[name.find('[') + 1] - '1');
    };
    if (name.starts_with("kelly_")) return [](EstimatorData& d) { d.angular_response = AngularResponse::kelly; };
    if (name.starts_with("filter_sun_sigma_method[") || name.starts_with("filter_sun_correlation["))
        return sun_method_of_element;
    if (name.starts_with("tle_elements")) return onboard_references_from_numbers;
    // The box's geometry reaches the filter only with its drag model on (off, the geometry stays zero), and
    // the switch shows only with a geometry (leo_orbit's 3U).
    if (name == "filter_drag")
        return [](EstimatorData& d) {
            d.body_size = {0.1, 0.1, 0.34};
            d.drag_coefficient = 2.2;
        };
    for (const char* prefix : {"body_size", "centre_of_mass", "drag_coefficient"})
        if (name.starts_with(prefix)) return [](EstimatorData& d) { d.filter_drag = true; };
    if (name.starts_with("mag_prior_"))  // the ground calibration, of leo_orbit's 0.05 A m² dipole
        return [](EstimatorData& d) {
            d.mag_calibration = true;
            d.mag_prior_offset_sigma = 0.5e-6;
            d.mag_prior_dipole = {0.0, 0.0, 0.05};
        };
    if (name.starts_with("mag_string_"))  // the strings' field of the magnetometer's default layout
        return [name](EstimatorData& d) {
            const magnetometer::SpacecraftLayout layout = magnetometer::default_layout();
            for (std::size_t f = 0; f < 6; ++f)
                for (std::size_t i = 0; i < 3; ++i) {
                    d.mag_string_loop_center[3 * f + i] = layout.string_loop[f].center[i];
                    d.mag_string_loop_side_a[3 * f + i] = layout.string_loop[f].side_a[i];
                    d.mag_string_loop_side_b[3 * f + i] = layout.string_loop[f].side_b[i];
                }
            d.mag_string_field = name != "mag_string_field";
        };
    if (name == "reference_source")  // from the inputs to the computer's own models: it has an element set
        return [](EstimatorData& d) {
            onboard_references(d);
            d.reference_source = ReferenceSource::inputs;
        };
    for (const char* prefix :
         {"tle_line", "field_degree", "clock_epoch_", "clock_offset", "uplink_age", "reference_period"})
        if (name.starts_with(prefix)) return onboard_references;
    return [](EstimatorData&) {};
}

// The block's own, never the computer's: the FFT window of the spin-rate analysis the block runs beside
// the computer, and the arithmetic it runs in (which of the two settings, double or float, is used).
const std::map<std::string, std::string> kNotOnBoard = {
    {"spin_window", "the block's spin-rate analysis"},
    {"precision", "chooses between the double and the float settings"},
};

// Parameters that hold one value only, and the block refuses any other with an error naming them (rather
// than take it and let the computer ignore it): the Kelly table's knots that panel_response::table fixes.
const std::map<std::string, std::string> kFixedValue = {
    {"kelly_angle[1]", "the table's first knot is at 0 deg"},
    {"kelly_value[1]", "the table's first knot is 1"},
    {"kelly_value[2]", "the cosine holds up to the second knot: its value is the cosine of its angle"},
};

std::vector<double> configured_numbers(Driver& driver) {
    driver.block().configure();
    return numbers(onboard_settings_from<double>(driver.data()));
}

TEST(OnboardSettings, EveryDeclaredParameterReachesTheComputer) {
    const EstimatorBlock block;
    std::size_t checked = 0;
    for (const fmu::Variable& v : block.table().variables()) {
        if (v.causality != fmu::Causality::parameter) continue;
        if (kNotOnBoard.contains(v.base_name) || kNotOnBoard.contains(v.name)) continue;
        SCOPED_TRACE(v.name);
        Driver driver;
        configuration_for(v.name)(driver.data());
        const std::vector<double> before = configured_numbers(driver);
        change(driver.runner.model().bytes(), v);
        if (kFixedValue.contains(v.name)) {
            try {
                driver.block().validate();  // the runtime's parameter checks, before configure()
                driver.block().configure();
                ADD_FAILURE() << v.name << " changed was taken, though " << kFixedValue.at(v.name);
            } catch (const fmu::Error& e) {
                EXPECT_NE(std::string(e.what()).find(v.name), std::string::npos) << e.what();
            }
            ++checked;
            continue;
        }
        std::vector<double> after;
        try {
            after = configured_numbers(driver);
        } catch (const std::exception& e) {
            ADD_FAILURE() << v.name << " changed: " << e.what();
            continue;
        }
        EXPECT_NE(before, after) << v.name << " changed, the on-board settings did not";
        ++checked;
    }
    // The loop went over the table (96 parameters today, arrays counted by element, less kNotOnBoard).
    EXPECT_GE(checked, 90u);
}

// The exceptions are parameters of the table still (a renamed one would leave a stale exception behind).
TEST(OnboardSettings, TheExceptionsAreDeclaredParameters) {
    const EstimatorBlock block;
    for (const auto& exceptions : {kNotOnBoard, kFixedValue})
        for (const auto& [name, why] : exceptions)
            EXPECT_EQ(block.table().by_name(name).causality, fmu::Causality::parameter) << name << ": " << why;
}

}  // namespace
}  // namespace attitude_estimator
