// fmi2Set*/fmi2Get* in each state, for the variables that the state machine of FMI 2.0.4
// (sections 3.2.3 and 4.2.4, "fmi2SetXXX" rows) allows to be set there, and reading every variable.
#include <cmath>

#include "conformance_fixture.hpp"

using namespace conformance;
using namespace fmi_loader;

CONFORMANCE_SUITE(ConformanceGetSet);

namespace {

bool settable_before_init(const ScalarVariable& v) {
    // Instantiated: variability != constant with initial exact or approx.
    return v.variability != Variability::constant && (v.initial == Initial::exact || v.initial == Initial::approx) &&
           v.start;
}
bool settable_in_init(const ScalarVariable& v) {
    // Initialization Mode: variability != constant with initial exact, or inputs.
    return v.start &&
           ((v.variability != Variability::constant && v.initial == Initial::exact) || v.causality == Causality::input);
}
bool settable_after_init(const ScalarVariable& v) {
    // Step complete (CS) / Event Mode (ME): inputs and tunable parameters.
    return v.start && (v.causality == Causality::input ||
                       (v.causality == Causality::parameter && v.variability == Variability::tunable));
}

// Numeric equality of a read-back value with the start text it was set from.
bool same_value(const ScalarVariable& v, const std::string& read) {
    if (v.type == VariableType::string) return read == *v.start;
    if (v.type == VariableType::boolean) return (read == "true") == v.start_as_boolean().value_or(false);
    const auto s = v.start_as_real();
    if (!s) return false;
    if (v.type == VariableType::real) return std::strtod(read.c_str(), nullptr) == *s;
    return std::strtoll(read.c_str(), nullptr, 10) == static_cast<long long>(*s);
}

}  // namespace

TEST_P(ConformanceGetSet, EveryStateAllowsItsVariables) {
    const FmuKind kind = preferred_kind();
    Instance inst(fmu(), kind);
    ASSERT_TRUE(inst.ok()) << inst.log().dump();
    const auto& f = inst.f();
    const Experiment ex = experiment_of(md());
    ASSERT_FMI_OK(inst, f.fmi2SetupExperiment(inst.c(), fmi2False, 0.0, ex.start, fmi2True, ex.stop));

    std::size_t set_count = 0;
    for (const auto& v : md().model_variables)
        if (settable_before_init(v)) {
            ASSERT_FMI_OK(inst, inst.set_start(v)) << " (instantiated) for " << v.name;
            ++set_count;
        }
    ASSERT_FMI_OK(inst, f.fmi2EnterInitializationMode(inst.c()));
    for (const auto& v : md().model_variables)
        if (settable_in_init(v)) {
            ASSERT_FMI_OK(inst, inst.set_start(v)) << " (initialization) for " << v.name;
        }
    for (const auto& v : md().model_variables) {
        std::string text;
        ASSERT_FMI_OK(inst, inst.get_text(v, text)) << " (initialization) reading " << v.name;
        if (settable_in_init(v)) {
            EXPECT_TRUE(same_value(v, text)) << v.name << " reads " << text << " after set to " << *v.start;
        }
    }
    ASSERT_FMI_OK(inst, f.fmi2ExitInitializationMode(inst.c()));

    auto read_all = [&](const char* state) {
        for (const auto& v : md().model_variables) {
            std::string text;
            ASSERT_FMI_OK(inst, inst.get_text(v, text)) << " (" << state << ") reading " << v.name;
            if (v.type == VariableType::real) {
                EXPECT_FALSE(std::isnan(std::strtod(text.c_str(), nullptr))) << v.name << " is NaN (" << state << ")";
            }
            if (v.variability == Variability::constant ||
                (v.causality == Causality::parameter && v.variability == Variability::fixed)) {
                EXPECT_TRUE(!v.start || same_value(v, text)) << v.name << " = " << text << " but start " << *v.start;
            }
        }
    };
    read_all(kind == FmuKind::co_simulation ? "step complete" : "event mode");
    for (const auto& v : md().model_variables)
        if (settable_after_init(v)) {
            ASSERT_FMI_OK(inst, inst.set_start(v)) << " (after initialization) for " << v.name;
            ++set_count;
        }
    if (kind == FmuKind::co_simulation) {
        ASSERT_FMI_OK(inst, f.fmi2DoStep(inst.c(), ex.start, ex.step, fmi2True));
        read_all("after a step");
    } else {
        fmi2EventInfo info{fmi2True, fmi2False, fmi2False, fmi2False, fmi2False, 0.0};
        for (int i = 0; i < 100 && info.newDiscreteStatesNeeded && !info.terminateSimulation; ++i) {
            ASSERT_FMI_OK(inst, f.fmi2NewDiscreteStates(inst.c(), &info));
        }
        ASSERT_FMI_OK(inst, f.fmi2EnterContinuousTimeMode(inst.c()));
        for (const auto& v : md().model_variables)
            if (v.causality == Causality::input && v.variability == Variability::continuous) {
                ASSERT_FMI_OK(inst, inst.set_start(v)) << " (continuous-time mode) for " << v.name;
            }
        read_all("continuous-time mode");
    }
    ASSERT_FMI_OK(inst, f.fmi2Terminate(inst.c()));
    read_all("terminated");
    RecordProperty("variables_set", static_cast<int>(set_count));
}

TEST_P(ConformanceGetSet, ResetReturnsToInstantiated) {
    const FmuKind kind = preferred_kind();
    Instance inst(fmu(), kind);
    ASSERT_TRUE(inst.ok()) << inst.log().dump();
    const Experiment ex = experiment_of(md());
    ASSERT_FMI_OK(inst, inst.initialize(ex.start, ex.stop));
    const auto first = real_output_bits(inst);
    ASSERT_FMI_OK(inst, inst.f().fmi2Reset(inst.c()));
    ASSERT_FMI_OK(inst, inst.initialize(ex.start, ex.stop));
    // Same parameters, same start: the initial outputs must be the same bits after a reset.
    EXPECT_EQ(real_output_bits(inst), first);
}
