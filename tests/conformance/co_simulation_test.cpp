// The Co-Simulation call sequence of FMI 2.0.4 section 4.2.4 over the DefaultExperiment window.
#include <cmath>

#include "conformance_fixture.hpp"

using namespace conformance;
using namespace fmi_loader;

CONFORMANCE_SUITE(ConformanceCoSimulation);

TEST_P(ConformanceCoSimulation, FullCallSequenceOverDefaultExperiment) {
    if (!md().co_simulation) GTEST_SKIP() << "no CoSimulation declared";
    Instance inst(fmu(), FmuKind::co_simulation);
    ASSERT_TRUE(inst.ok()) << "fmi2Instantiate returned NULL\n" << inst.log().dump();
    const auto& f = inst.f();
    const Experiment ex = experiment_of(md());
    ASSERT_FMI_OK(inst, inst.initialize(ex.start, ex.stop));
    const std::size_t n = ex.steps();
    for (std::size_t k = 0; k < n; ++k) {
        // Communication points from the integer step count, so they never drift.
        const double t = ex.start + static_cast<double>(k) * ex.step;
        ASSERT_FMI_OK(inst, f.fmi2DoStep(inst.c(), t, ex.step, fmi2True));
        for (const auto& v : md().model_variables) {
            if (v.causality != Causality::output) continue;
            std::string text;
            ASSERT_FMI_OK(inst, inst.get_text(v, text));
            if (v.type == VariableType::real) {
                ASSERT_TRUE(std::isfinite(std::strtod(text.c_str(), nullptr)))
                    << v.name << " = " << text << " after step " << k;
            }
        }
    }
    fmi2Real last_time = 0.0;
    // fmi2GetStatus may legitimately answer fmi2Discard when the status is not available.
    if (f.fmi2GetRealStatus(inst.c(), fmi2LastSuccessfulTime, &last_time) == fmi2OK) {
        EXPECT_NEAR(last_time, ex.start + static_cast<double>(n) * ex.step, 1e-9 * std::max(1.0, std::fabs(ex.stop)));
    }
    ASSERT_FMI_OK(inst, f.fmi2Terminate(inst.c()));
    inst.free();
}

// Communication points as most masters compute them, t += h, drift from the instants a block schedules by
// a few ulps per step: a time event within rounding of t must be taken, not refused (OMSimulator 2.1.3
// stepping ssr_plant by 0.1 ms found one that the runtime found due and the plant not yet).
TEST_P(ConformanceCoSimulation, CommunicationPointsAsARunningSum) {
    if (!md().co_simulation) GTEST_SKIP() << "no CoSimulation declared";
    Instance inst(fmu(), FmuKind::co_simulation);
    ASSERT_TRUE(inst.ok()) << inst.log().dump();
    const double h =
        md().default_experiment && md().default_experiment->step_size ? *md().default_experiment->step_size : 0.001;
    ASSERT_FMI_OK(inst, inst.initialize(0.0, 3000 * h));
    double t = 0.0;
    for (int k = 0; k < 3000; ++k) {  // ssr_plant, h = 1 ms: t is 2.0e-13 below a PWM edge at step 2840
        ASSERT_FMI_OK(inst, inst.f().fmi2DoStep(inst.c(), t, h, fmi2True)) << "step " << k << " at t = " << t;
        t += h;
    }
    ASSERT_FMI_OK(inst, inst.f().fmi2Terminate(inst.c()));
}

TEST_P(ConformanceCoSimulation, VariableStepSizesWhenDeclared) {
    if (!md().co_simulation) GTEST_SKIP() << "no CoSimulation declared";
    if (!md().co_simulation->can_handle_variable_communication_step_size)
        GTEST_SKIP() << "canHandleVariableCommunicationStepSize=false";
    Instance inst(fmu(), FmuKind::co_simulation);
    ASSERT_TRUE(inst.ok()) << inst.log().dump();
    const Experiment ex = experiment_of(md());
    ASSERT_FMI_OK(inst, inst.initialize(ex.start, ex.stop));
    double t = ex.start;
    // Steps of h/2, h, 2h in turn: all must be accepted.
    for (int k = 0; t < ex.stop - 1e-12; ++k) {
        const double h = std::min(ex.step * (k % 3 == 0 ? 0.5 : k % 3 == 1 ? 1.0 : 2.0), ex.stop - t);
        ASSERT_FMI_OK(inst, inst.f().fmi2DoStep(inst.c(), t, h, fmi2True));
        t += h;
    }
    ASSERT_FMI_OK(inst, inst.f().fmi2Terminate(inst.c()));
}
