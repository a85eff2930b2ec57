// Two instances of one FMU share nothing (FMI 2.0.4 section 2.1.5: every instance owns its state):
// different inputs give different outputs, and stepping them in turn gives the very bits of two
// separate runs.
#include <cmath>

#include "conformance_fixture.hpp"

using namespace conformance;
using namespace fmi_loader;

CONFORMANCE_SUITE(ConformanceInstances);

namespace {

// The variable the two instances differ in: a Real or Integer input, else a parameter.
struct Knob {
    const ScalarVariable* var = nullptr;
    double a = 0.0, b = 0.0;
};

Knob choose_knob(const ModelDescription& md) {
    auto pick = [&](auto accept) -> const ScalarVariable* {
        for (const auto& v : md.model_variables)
            if (accept(v) && v.start && (v.type == VariableType::real || v.type == VariableType::integer) &&
                v.start_as_real())
                return &v;
        return nullptr;
    };
    const ScalarVariable* v = pick([](const ScalarVariable& s) { return s.causality == Causality::input; });
    if (!v) v = pick([](const ScalarVariable& s) { return s.causality == Causality::parameter; });
    Knob k;
    if (!v) return k;
    k.var = v;
    k.a = *v->start_as_real();
    const double delta = std::max(1.0, std::fabs(k.a) * 0.5);
    // Stay inside [min, max]: prefer going up, go down if that leaves the range.
    k.b = k.a + delta;
    if (v->max && k.b > *v->max) k.b = v->min ? std::max(*v->min, k.a - delta) : k.a - delta;
    if (v->type == VariableType::integer) k.b = std::round(k.b);
    return k;
}

using Trace = std::vector<std::vector<std::uint64_t>>;

fmi2Status prepare(Instance& inst, const Knob& k, double value, const Experiment& ex) {
    const auto& f = inst.f();
    fmi2Status s = f.fmi2SetupExperiment(inst.c(), fmi2False, 0.0, ex.start, fmi2True, ex.stop);
    if (s > fmi2Warning) return s;
    s = f.fmi2EnterInitializationMode(inst.c());
    if (s > fmi2Warning) return s;
    s = k.var->type == VariableType::real ? inst.set_real(k.var->value_reference, value)
                                          : inst.set_integer(k.var->value_reference, static_cast<int>(value));
    if (s > fmi2Warning) return s;
    return f.fmi2ExitInitializationMode(inst.c());
}

}  // namespace

TEST_P(ConformanceInstances, AreIndependent) {
    if (!md().co_simulation) GTEST_SKIP() << "needs CoSimulation";
    const Knob k = choose_knob(md());
    if (!k.var) GTEST_SKIP() << "no input or parameter with a numeric start value";
    if (k.a == k.b) GTEST_SKIP() << "no second value inside [min, max] for " << k.var->name;
    bool has_output = false;
    for (const auto& v : md().model_variables)
        has_output = has_output || (v.causality == Causality::output && v.type == VariableType::real);
    if (!has_output) GTEST_SKIP() << "no Real output to compare";
    const Experiment ex = experiment_of(md(), 1.0, 200);
    const std::size_t n = ex.steps();

    auto separate = [&](double value, Trace& trace) {
        Instance inst(fmu(), FmuKind::co_simulation, "separate");
        ASSERT_TRUE(inst.ok()) << inst.log().dump();
        ASSERT_FMI_OK(inst, prepare(inst, k, value, ex));
        trace.push_back(real_output_bits(inst));
        for (std::size_t i = 0; i < n; ++i) {
            ASSERT_FMI_OK(
                inst, inst.f().fmi2DoStep(inst.c(), ex.start + static_cast<double>(i) * ex.step, ex.step, fmi2True));
            trace.push_back(real_output_bits(inst));
        }
    };
    Trace alone_a, alone_b;
    ASSERT_NO_FATAL_FAILURE(separate(k.a, alone_a));
    ASSERT_NO_FATAL_FAILURE(separate(k.b, alone_b));
    EXPECT_NE(alone_a, alone_b) << "setting " << k.var->name << " to " << k.a << " or " << k.b
                                << " changes no output in " << n << " steps";

    Instance a(fmu(), FmuKind::co_simulation, "a");
    Instance b(fmu(), FmuKind::co_simulation, "b");
    ASSERT_TRUE(a.ok() && b.ok());
    ASSERT_FMI_OK(a, prepare(a, k, k.a, ex));
    ASSERT_FMI_OK(b, prepare(b, k, k.b, ex));
    Trace both_a{real_output_bits(a)}, both_b{real_output_bits(b)};
    for (std::size_t i = 0; i < n; ++i) {
        const double t = ex.start + static_cast<double>(i) * ex.step;
        ASSERT_FMI_OK(a, a.f().fmi2DoStep(a.c(), t, ex.step, fmi2True));
        ASSERT_FMI_OK(b, b.f().fmi2DoStep(b.c(), t, ex.step, fmi2True));
        both_a.push_back(real_output_bits(a));
        both_b.push_back(real_output_bits(b));
    }
    EXPECT_EQ(both_a, alone_a) << "instance a changed by running next to b";
    EXPECT_EQ(both_b, alone_b) << "instance b changed by running next to a";
}
