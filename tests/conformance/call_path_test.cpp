// The runtime's FMI call path allocates nothing once an instance runs with logging off: a host calling
// fmi2GetReal / fmi2SetReal thousands of times a second pays no allocator (and no lock in it). Counted by
// malloc_counter.hpp over the whole process, the FMU's shared library included. This is this toolkit's
// promise for the FMUs built on its runtime, not an FMI 2.0 rule.
// fmi2DoStep is counted for the FMUs without continuous states only: with states, SUNDIALS 6's dense
// difference-quotient Jacobian (cvLsDenseDQJac) allocates a vector header each time CVODE rebuilds the
// Jacobian inside a step (1 to 3 allocations a step here). Our own allocation-free Jacobian needs the step
// size CVODE is attempting, which its API does not give before the first step (tried: the e2e runs moved).
#include "conformance_fixture.hpp"
#include "malloc_counter.hpp"

using namespace conformance;
using namespace fmi_loader;

CONFORMANCE_SUITE(ConformanceCallPath);

namespace {

void quiet_logger(fmi2ComponentEnvironment, fmi2String, fmi2Status, fmi2String, fmi2String, ...) {}

}  // namespace

TEST_P(ConformanceCallPath, GetSetAndStepAllocateNothingWithLoggingOff) {
    if (!md().co_simulation) GTEST_SKIP() << "no Co-Simulation";
    const auto& f = fmu().library(FmuKind::co_simulation).functions();
    const fmi2CallbackFunctions callbacks{quiet_logger, calloc, free, nullptr, nullptr};
    fmi2Component c =
        f.fmi2Instantiate("call_path", fmi2CoSimulation, md().guid.c_str(), "", &callbacks, fmi2False, fmi2False);
    ASSERT_NE(c, nullptr);
    const Experiment ex = experiment_of(md());
    ASSERT_LE(f.fmi2SetupExperiment(c, fmi2False, 0.0, ex.start, fmi2False, 0.0), fmi2Warning);
    ASSERT_LE(f.fmi2EnterInitializationMode(c), fmi2Warning);
    ASSERT_LE(f.fmi2ExitInitializationMode(c), fmi2Warning);

    std::vector<fmi2ValueReference> reals, integers, booleans, real_inputs;
    for (const auto& v : md().model_variables) {
        if (v.type == VariableType::real) reals.push_back(v.value_reference);
        if (v.type == VariableType::integer || v.type == VariableType::enumeration)
            integers.push_back(v.value_reference);
        if (v.type == VariableType::boolean) booleans.push_back(v.value_reference);
        if (v.type == VariableType::real && v.causality == Causality::input) real_inputs.push_back(v.value_reference);
    }
    std::vector<fmi2Real> real_values(reals.size()), input_values(real_inputs.size());
    std::vector<fmi2Integer> integer_values(integers.size());
    std::vector<fmi2Boolean> boolean_values(booleans.size());
    const std::vector<fmi2Integer> orders(real_inputs.size(), 1);
    const std::vector<fmi2Real> slopes(real_inputs.size(), 0.0);
    double t = ex.start;
    const bool count_steps = md().number_of_continuous_states() == 0;
    auto round = [&] {
        fmi2Status s = f.fmi2GetReal(c, reals.data(), reals.size(), real_values.data());
        s = std::max(s, f.fmi2GetInteger(c, integers.data(), integers.size(), integer_values.data()));
        s = std::max(s, f.fmi2GetBoolean(c, booleans.data(), booleans.size(), boolean_values.data()));
        s = std::max(s, f.fmi2GetReal(c, real_inputs.data(), real_inputs.size(), input_values.data()));
        s = std::max(s, f.fmi2SetReal(c, real_inputs.data(), real_inputs.size(), input_values.data()));
        // A Co-Simulation host that interpolates gives the inputs' slopes at every step.
        if (md().co_simulation->can_interpolate_inputs && !real_inputs.empty())
            s = std::max(s, f.fmi2SetRealInputDerivatives(c, real_inputs.data(), real_inputs.size(), orders.data(),
                                                          slopes.data()));
        return s;
    };
    long allocations = 0;
    auto step = [&] {
        const long before = allocation_count();
        const fmi2Status s = f.fmi2DoStep(c, t, ex.step, fmi2True);
        t += ex.step;
        if (count_steps) allocations += allocation_count() - before;
        return s;
    };
    ASSERT_LE(std::max(round(), step()), fmi2Warning);  // the first step may build what later steps reuse
    allocations = 0;
    for (int i = 0; i < 20; ++i) {
        const long before = allocation_count();
        ASSERT_LE(round(), fmi2Warning) << "round " << i;
        allocations += allocation_count() - before;
        ASSERT_LE(step(), fmi2Warning) << "step " << i;
    }
    EXPECT_EQ(allocations, 0) << "allocations in 20 rounds of get/set" << (count_steps ? " and step" : "")
                              << " with logging off";
    f.fmi2Terminate(c);
    f.fmi2FreeInstance(c);
}
