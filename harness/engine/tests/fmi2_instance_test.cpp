// The master's side of an FMI 2.0 instance: what it does not ask the FMU again. A Model Exchange master
// sets the time and states at an instant its integrator just checked the event indicators at; the same bits
// again, with no other call in between, are not passed on, and the values it read stay valid while nothing
// that could change them was called (values_version).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <string>

#include "engine/fmi2_instance.hpp"
#include "fmi_loader/fmu.hpp"

namespace cosim {
namespace {

const std::filesystem::path fmu_dir = COSIM_TEST_FMU_DIR;

// The FMU logs every call it receives (logAll): how many of `function` it has seen.
long calls_of(const Fmi2Instance& instance, const std::string& function) {
    return std::count_if(instance.messages().begin(), instance.messages().end(),
                         [&](const auto& m) { return m.second == function; });
}

TEST(CosimFmi2Instance, TheSameTimeAndStatesAreNotGivenAgain) {
    fmi_loader::Fmu fmu(fmu_dir / "test_integrator.fmu");
    Fmi2Instance in(fmu, fmi_loader::FmuKind::model_exchange, "int", true);
    in.setup_experiment(0.0, 1.0, std::nullopt);
    in.enter_initialization_mode();
    in.exit_initialization_mode();
    in.new_discrete_states();
    in.enter_continuous_time_mode();

    in.set_time(0.5);
    std::array<double, 1> x{0.25};
    in.set_states(x.data(), x.size());
    const long times = calls_of(in, "fmi2SetTime"), states = calls_of(in, "fmi2SetContinuousStates");
    ASSERT_GE(times, 1);
    ASSERT_GE(states, 1);
    const auto version = in.values_version();
    ASSERT_TRUE(version.has_value());

    in.set_time(0.5);
    in.set_states(x.data(), x.size());
    EXPECT_EQ(calls_of(in, "fmi2SetTime"), times);
    EXPECT_EQ(calls_of(in, "fmi2SetContinuousStates"), states);
    EXPECT_EQ(in.get_real(fmu.description().find_variable("y")->value_reference), 0.25);
    EXPECT_EQ(in.values_version(), version);  // nothing set, a value read

    x[0] = -0.0;  // another state, if only in its sign bit
    in.set_states(x.data(), x.size());
    EXPECT_EQ(calls_of(in, "fmi2SetContinuousStates"), states + 1);
    EXPECT_NE(in.values_version(), version);
    in.set_time(0.75);
    EXPECT_EQ(calls_of(in, "fmi2SetTime"), times + 1);

    // An event may move the states: after it the same time and states are given again.
    in.enter_event_mode();
    in.new_discrete_states();
    in.enter_continuous_time_mode();
    in.set_time(0.75);
    in.set_states(x.data(), x.size());
    EXPECT_EQ(calls_of(in, "fmi2SetTime"), times + 2);
    EXPECT_EQ(calls_of(in, "fmi2SetContinuousStates"), states + 2);
}

}  // namespace
}  // namespace cosim
