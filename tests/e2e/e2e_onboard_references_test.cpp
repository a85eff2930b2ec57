// The bundled leo_orbit feeds the on-board computer nothing of the truth's (issue 26): no connection from the
// environment into the estimator, and the estimator set to compute its references from its own element set.
#include <gtest/gtest.h>

#include <string>

#include "system_description.hpp"

namespace {

std::string parameter(const cosim::ComponentDescription& c, const std::string& name) {
    for (const auto& p : c.parameters)
        if (p.name == name) return p.value;
    return "";
}

TEST(E2eOnboardReferences, LeoOrbitConnectsNoTruthIntoTheEstimator) {
    const cosim::SystemDescription s = cosim::read_system_description(PVATT_SYSTEMS_DIR "/leo_orbit.ssd");
    int into_est = 0;
    for (const auto& c : s.connections) {
        if (c.end_element != "est") continue;
        ++into_est;
        // The estimator's inputs are its sensors: the panels' currents and the magnetometer's voltages.
        EXPECT_TRUE(c.start_element == "plant" || c.start_element == "mag")
            << c.start_element << "." << c.start_connector << " -> est." << c.end_connector;
    }
    EXPECT_EQ(into_est, 3 + 6 + 4);  // i_sh, i_face, v_mag and v_mag_ref
    bool found = false;
    for (const auto& c : s.components) {
        if (c.name != "est") continue;
        found = true;
        EXPECT_EQ(parameter(c, "reference_source"), "onboard");
        EXPECT_EQ(parameter(c, "field_degree"), "8");
        EXPECT_EQ(parameter(c, "tle_line1").size(), 69u);
        EXPECT_EQ(parameter(c, "tle_line2").size(), 69u);
        for (const auto& k : c.connectors)
            EXPECT_TRUE(k.name.rfind("sun_ref", 0) != 0 && k.name.rfind("mag_ref", 0) != 0 && k.name != "sun_distance")
                << k.name;
    }
    EXPECT_TRUE(found);
}

}  // namespace
