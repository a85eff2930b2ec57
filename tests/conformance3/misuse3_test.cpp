// Misuse of the FMI 3.0 archives is refused by the FMI 3.0 call rules with fmi3Error and a message,
// and what these FMUs do not offer is named: Scheduled Execution, Configuration Mode, clocks' types.
#include "fixture3.hpp"

namespace {

using conformance3::Instance3;
using Kind = Instance3::Kind;

CONFORMANCE3_SUITE(Conformance3Misuse);

bool logged(Instance3& inst, const std::string& words) {
    return inst.log().dump().find(words) != std::string::npos;
}

TEST_P(Conformance3Misuse, WrongTokenIsRefused) {
    Instance3 inst(fmu3(), Kind::co_simulation, false, false, "{00000000-0000-0000-0000-000000000000}");
    EXPECT_EQ(inst.c(), nullptr);
    EXPECT_TRUE(logged(inst, "instantiation token")) << inst.log().dump();
}

TEST_P(Conformance3Misuse, ScheduledExecutionIsRefusedByName) {
    conformance3::Log3 log;
    const fmi3Instance c = fmu3().f().instantiate_se(
        "se", md().token.c_str(), nullptr, false, false, &log,
        [](fmi3InstanceEnvironment env, fmi3Status s, fmi3String, fmi3String m) {
            static_cast<conformance3::Log3*>(env)->records.emplace_back(s, m);
        },
        nullptr, nullptr, nullptr);
    EXPECT_EQ(c, nullptr);
    EXPECT_NE(log.dump().find("Scheduled Execution is not supported"), std::string::npos) << log.dump();
}

TEST_P(Conformance3Misuse, StepBeforeInitializationIsRefused) {
    Instance3 inst(fmu3(), Kind::co_simulation);
    fmi3Boolean event = false, terminate = false, early = false;
    double last = 0.0;
    EXPECT_EQ(inst.f().do_step(inst.c(), 0.0, 0.1, true, &event, &terminate, &early, &last), fmi3Error);
    EXPECT_TRUE(logged(inst, "fmi3DoStep is not allowed in Instantiated")) << inst.log().dump();
}

TEST_P(Conformance3Misuse, EventModeNeedsEventModeUsed) {
    Instance3 inst(fmu3(), Kind::co_simulation, false);
    ASSERT_EQ(inst.initialize(), fmi3OK);
    EXPECT_EQ(inst.f().enter_event_mode(inst.c()), fmi3Error);
    EXPECT_TRUE(logged(inst, "eventModeUsed")) << inst.log().dump();
}

TEST_P(Conformance3Misuse, UpdateDiscreteStatesOutsideEventModeIsRefused) {
    Instance3 inst(fmu3(), Kind::co_simulation, true);
    ASSERT_EQ(inst.initialize(), fmi3OK);
    ASSERT_EQ(inst.f().enter_step_mode(inst.c()), fmi3OK);
    fmi3Boolean a, b, c, d, e;
    double next;
    EXPECT_EQ(inst.f().update_discrete_states(inst.c(), &a, &b, &c, &d, &e, &next), fmi3Error);
    EXPECT_TRUE(logged(inst, "not allowed in Step Mode")) << inst.log().dump();
}

TEST_P(Conformance3Misuse, ModelExchangeCallsAreRefusedInCoSimulation) {
    Instance3 inst(fmu3(), Kind::co_simulation);
    ASSERT_EQ(inst.initialize(), fmi3OK);
    EXPECT_EQ(inst.f().enter_continuous_time_mode(inst.c()), fmi3Error);
}

TEST_P(Conformance3Misuse, ConfigurationModeIsRefusedByName) {
    Instance3 inst(fmu3(), Kind::co_simulation);
    EXPECT_EQ(inst.f().enter_configuration_mode(inst.c()), fmi3Error);
    EXPECT_TRUE(logged(inst, "no structural parameters")) << inst.log().dump();
}

// A fixed parameter after initialization is refused; after the error only a reset brings the
// instance back, and it then runs again.
TEST_P(Conformance3Misuse, FixedParameterAfterInitializationThenReset) {
    const auto fixed = std::find_if(md().variables.begin(), md().variables.end(), [](const auto& v) {
        return v.causality == "parameter" && v.variability == "fixed" && v.type == "Float64";
    });
    if (fixed == md().variables.end()) GTEST_SKIP() << "no fixed Float64 parameter";
    Instance3 inst(fmu3(), Kind::co_simulation);
    ASSERT_EQ(inst.initialize(), fmi3OK);
    std::vector<double> x = inst.get_float64(*fixed);
    EXPECT_EQ(inst.f().set_float64(inst.c(), &fixed->value_reference, 1, x.data(), x.size()), fmi3Error);
    fmi3Boolean event = false, terminate = false, early = false;
    double last = 0.0;
    EXPECT_EQ(inst.f().do_step(inst.c(), md().start_time, md().step_size, true, &event, &terminate, &early, &last),
              fmi3Error);
    EXPECT_TRUE(logged(inst, "not allowed in Error")) << inst.log().dump();
    ASSERT_EQ(inst.f().reset(inst.c()), fmi3OK);
    ASSERT_EQ(inst.initialize(), fmi3OK) << inst.log().dump();
    EXPECT_EQ(inst.f().do_step(inst.c(), md().start_time, md().step_size, true, &event, &terminate, &early, &last),
              fmi3OK);
}

}  // namespace
