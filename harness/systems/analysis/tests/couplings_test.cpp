// The bundled leo_orbit's blocks that share a physical fact (harness/systems/analysis/couplings.hpp):
// accepted as bundled, refused when one side is changed alone, with the value that would agree.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "analysis/couplings.hpp"
#include "engine/cosim_error.hpp"
#include "engine/system.hpp"

namespace {

std::vector<std::string> mismatches(const std::vector<std::string>& settings) {
    cosim::SystemOptions options;
    options.fmu_dirs = {PVATT_FMU_DIR};
    options.settings = settings;
    const cosim::System system(cosim::read_system_description(PVATT_SYSTEMS_SOURCE_DIR "/leo_orbit.ssd"), options);
    return analysis::coupling_mismatches(system);
}

TEST(Couplings, TheBundledOrbitAgrees) {
    EXPECT_EQ(mismatches({}), std::vector<std::string>{});
}

TEST(Couplings, TheEstimatorsAngularResponseMustBeThePanels) {
    const auto m = mismatches({"est.angular_response=cosine"});
    ASSERT_EQ(m.size(), 1u);
    EXPECT_NE(m[0].find("est.angular_response is cosine but plant.angular_response is kelly"), std::string::npos)
        << m[0];
    // The plant changed alone: the estimator and the environment's albedo weighting both disagree.
    EXPECT_EQ(mismatches({"plant.angular_response=cosine"}).size(), 2u);
    EXPECT_EQ(
        mismatches({"plant.angular_response=cosine", "est.angular_response=cosine", "env.albedo_response=cosine"}),
        std::vector<std::string>{});
}

TEST(Couplings, TheEstimatorsAltitudeMustBeTheTruths) {
    // A circular truth at 400 km above the equatorial radius: an orbit radius of 6778.137 km. The
    // estimator's sphere is 6371 km: 407 km agrees, its 570 km default is 163 km off.
    // (With reference_source = inputs: on board the computer takes its altitude from its own element set.)
    EXPECT_EQ(mismatches({"est.reference_source=inputs", "env.orbit_model=circular", "env.orbit_altitude=400e3",
                          "est.orbit_altitude=407e3"}),
              std::vector<std::string>{});
    const auto m = mismatches({"est.reference_source=inputs", "env.orbit_model=circular", "env.orbit_altitude=400e3"});
    ASSERT_EQ(m.size(), 1u);
    EXPECT_NE(m[0].find("est.orbit_altitude 570 km"), std::string::npos) << m[0];
    EXPECT_NE(m[0].find("set est.orbit_altitude=407000"), std::string::npos) << m[0];
    // The bundled element set: 14.98524078 rev/day, a semi-major axis near 6949.6 km (Kepler's third law,
    // mu 3.986004418e14; SGP4's mean semi-major axis is 6948 km): 400 km on board is refused.
    EXPECT_EQ(mismatches({"est.reference_source=inputs", "est.orbit_altitude=400e3"}).size(), 1u);
    EXPECT_EQ(mismatches({"est.orbit_altitude=400e3"}), std::vector<std::string>{});  // onboard: not used
}

// The uplink (reference_source = onboard): the computer's clock, its set's epoch and its orbit at t = 0
// against the truth's, each with the values that would agree.
TEST(Couplings, MovingTheDateAloneIsRefused) {
    const auto m = mismatches({"env.epoch_month=9"});
    ASSERT_EQ(m.size(), 1u);
    for (const char* part :
         {"est's clock at t = 0", "2026-03-20 00:00:00.000 UTC", "2026-09-20 00:00:00.000 UTC", "max_clock_difference",
          "set est.clock_epoch_year=2026 est.clock_epoch_month=9 est.clock_epoch_day=20"})
        EXPECT_NE(m[0].find(part), std::string::npos) << m[0];
    // A clock error is a named parameter: within 10 s it is a study, beyond it a mismatch.
    EXPECT_EQ(mismatches({"est.clock_offset=5"}), std::vector<std::string>{});
    EXPECT_EQ(mismatches({"est.clock_offset=-30"}).size(), 1u);
}

TEST(Couplings, TheOnboardSetMustBeTheTruthsSatellite) {
    // Thirty days older: beyond max_uplink_age_days; the value that agrees is the bound's age.
    auto m = mismatches({"est.uplink_age=2592000"});
    ASSERT_EQ(m.size(), 1u);
    for (const char* part : {"30 days older", "max_uplink_age_days", "est.uplink_age=604800",
                             "est.tle_elements=[2461119.5, 14.98524078, 0.0012, 64.9, 0, 90, 270, 0.00015]"})
        EXPECT_NE(m[0].find(part), std::string::npos) << m[0];
    // Another phase (mean anomaly 300 deg, not 270): the computer's satellite is 3600 km from the truth's.
    // (Another plane alone would not show at t = 0: the bundled satellite starts at its ascending node.)
    m = mismatches({"est.tle_elements[7]=300"});
    ASSERT_EQ(m.size(), 1u);
    EXPECT_NE(m[0].find("max_orbit_position_difference"), std::string::npos) << m[0];
    EXPECT_NE(m[0].find("est.uplink_age=86400"), std::string::npos) << m[0];
    // A recorded uplink: the older set given as it is (the study script's text), no age on board.
    EXPECT_EQ(mismatches({"est.uplink_age=0",
                          "est.tle_line1=1 90001U          26078.00000000  .00002000  00000-0  15000-3 0  9994",
                          "est.tle_line2=2 90001  64.9000   3.1277 0012000  90.3760 275.3137 14.98524078  1006"}),
              std::vector<std::string>{});
}

TEST(Couplings, ARunIsRefusedUnlessAllowed) {
    cosim::SystemOptions options;
    options.fmu_dirs = {PVATT_FMU_DIR};
    options.settings = {"est.angular_response=cosine"};
    const cosim::System system(cosim::read_system_description(PVATT_SYSTEMS_SOURCE_DIR "/leo_orbit.ssd"), options);
    std::ostringstream warn;
    EXPECT_THROW(analysis::check_couplings(system, false, warn), cosim::CosimError);
    analysis::check_couplings(system, true, warn);
    EXPECT_NE(warn.str().find("warning: est.angular_response"), std::string::npos);
}

TEST(Couplings, TheOrbitPeriodIsDerivedAsTheEnvironmentComputesIt) {
    // leo_orbit's <Stop orbits="1"/>: one period of env's element set, which must be the environment's own
    // calculated orbit_period (read from the FMU after initialization), not the 5764 s written for other tools.
    cosim::SystemOptions options;
    options.fmu_dirs = {PVATT_FMU_DIR};
    cosim::System system(cosim::read_system_description(PVATT_SYSTEMS_SOURCE_DIR "/leo_orbit.ssd"), options);
    const auto derived = analysis::default_stop_time(system);
    ASSERT_TRUE(derived.has_value());
    system.initialize(0.0, std::nullopt);
    const std::size_t env = system.component_index("env");
    const auto* period = system.components()[env].description().find_variable("orbit_period");
    ASSERT_NE(period, nullptr);
    const double computed = system.components()[env].instance->get_real(period->value_reference);
    EXPECT_NEAR(*derived, computed, 1e-6);
    EXPECT_NEAR(*derived, 5763.86, 0.01);  // environment_block_test's figure for the bundled set
}

}  // namespace
