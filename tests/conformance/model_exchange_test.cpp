// The full Model Exchange call sequence of FMI 2.0.4 section 3.2.4, driven by a fixed-step forward
// Euler integrator with state-event detection on the event indicators' signs and time events.
#include <cmath>

#include "conformance_fixture.hpp"

using namespace conformance;
using namespace fmi_loader;

CONFORMANCE_SUITE(ConformanceModelExchange);

namespace {

// Event iteration: fmi2NewDiscreteStates until no new discrete states are needed.
::testing::AssertionResult event_iteration(Instance& inst, fmi2EventInfo& info) {
    info = fmi2EventInfo{fmi2True, fmi2False, fmi2False, fmi2False, fmi2False, 0.0};
    for (int i = 0; i < 1000 && info.newDiscreteStatesNeeded && !info.terminateSimulation; ++i) {
        const fmi2Status s = inst.f().fmi2NewDiscreteStates(inst.c(), &info);
        if (s > fmi2Warning)
            return ::testing::AssertionFailure() << "fmi2NewDiscreteStates returned " << status_name(s) << "\n"
                                                 << inst.log().dump();
    }
    if (info.newDiscreteStatesNeeded && !info.terminateSimulation)
        return ::testing::AssertionFailure() << "event iteration did not converge in 1000 calls";
    return ::testing::AssertionSuccess();
}

bool sign_changed(double before, double after) {
    // A zero crossing in the sense of section 3.1: the indicator changes from > 0 to <= 0 or back.
    return (before > 0) != (after > 0);
}

}  // namespace

TEST_P(ConformanceModelExchange, FullCallSequenceWithEulerIntegrator) {
    if (!md().model_exchange) GTEST_SKIP() << "no ModelExchange declared";
    Instance inst(fmu(), FmuKind::model_exchange);
    ASSERT_TRUE(inst.ok()) << "fmi2Instantiate returned NULL\n" << inst.log().dump();
    const auto& f = inst.f();
    const Experiment ex = experiment_of(md(), 3.0, 3000);
    const std::size_t nx = md().number_of_continuous_states();
    const std::size_t nz = md().number_of_event_indicators;

    ASSERT_FMI_OK(inst, f.fmi2SetupExperiment(inst.c(), fmi2False, 0.0, ex.start, fmi2True, ex.stop));
    ASSERT_FMI_OK(inst, f.fmi2EnterInitializationMode(inst.c()));
    ASSERT_FMI_OK(inst, f.fmi2ExitInitializationMode(inst.c()));
    fmi2EventInfo info;
    ASSERT_TRUE(event_iteration(inst, info));
    ASSERT_FMI_OK(inst, f.fmi2EnterContinuousTimeMode(inst.c()));

    std::vector<double> x(nx), dx(nx), nominal(nx), z(nz), z_prev(nz);
    if (nx > 0) {
        ASSERT_FMI_OK(inst, f.fmi2GetContinuousStates(inst.c(), x.data(), nx));
        ASSERT_FMI_OK(inst, f.fmi2GetNominalsOfContinuousStates(inst.c(), nominal.data(), nx));
        for (double n : nominal) {
            EXPECT_GT(n, 0.0) << "nominal of a continuous state must be positive";
        }
    }
    if (nz > 0) {
        ASSERT_FMI_OK(inst, f.fmi2GetEventIndicators(inst.c(), z_prev.data(), nz));
    }

    double t = ex.start;
    const double h = ex.step;
    std::size_t steps = 0, state_events = 0, time_events = 0, step_events = 0;
    bool terminated = info.terminateSimulation;
    while (!terminated && t < ex.stop - 1e-12 * std::max(1.0, std::fabs(ex.stop))) {
        ASSERT_LT(++steps, 100000u) << "time does not advance";
        double t_next = std::min(t + h, ex.stop);
        const bool time_event = info.nextEventTimeDefined && info.nextEventTime <= t_next;
        if (time_event) t_next = std::max(t, info.nextEventTime);
        if (nx > 0) {
            ASSERT_FMI_OK(inst, f.fmi2GetDerivatives(inst.c(), dx.data(), nx));
            for (std::size_t i = 0; i < nx; ++i) {
                ASSERT_TRUE(std::isfinite(dx[i])) << "derivative " << i << " not finite at t=" << t;
                x[i] += (t_next - t) * dx[i];  // forward Euler
            }
        }
        t = t_next;
        ASSERT_FMI_OK(inst, f.fmi2SetTime(inst.c(), t));
        if (nx > 0) {
            ASSERT_FMI_OK(inst, f.fmi2SetContinuousStates(inst.c(), x.data(), nx));
        }
        bool state_event = false;
        if (nz > 0) {
            ASSERT_FMI_OK(inst, f.fmi2GetEventIndicators(inst.c(), z.data(), nz));
            for (std::size_t i = 0; i < nz; ++i) state_event = state_event || sign_changed(z_prev[i], z[i]);
        }
        fmi2Boolean enter_event_mode = fmi2False, terminate = fmi2False;
        ASSERT_FMI_OK(inst, f.fmi2CompletedIntegratorStep(inst.c(), fmi2True, &enter_event_mode, &terminate));
        if (terminate) break;
        if (enter_event_mode || time_event || state_event) {
            state_events += state_event;
            time_events += time_event;
            step_events += enter_event_mode != fmi2False;
            ASSERT_FMI_OK(inst, f.fmi2EnterEventMode(inst.c()));
            ASSERT_TRUE(event_iteration(inst, info));
            terminated = info.terminateSimulation;
            if (terminated) break;
            ASSERT_FMI_OK(inst, f.fmi2EnterContinuousTimeMode(inst.c()));
            if (nx > 0) {
                ASSERT_FMI_OK(inst, f.fmi2GetContinuousStates(inst.c(), x.data(), nx));
            }
            if (nz > 0) {
                ASSERT_FMI_OK(inst, f.fmi2GetEventIndicators(inst.c(), z.data(), nz));
            }
        }
        z_prev = z;
    }
    // Every output can be read at the end and is a number.
    for (const auto& v : md().model_variables) {
        std::string text;
        ASSERT_FMI_OK(inst, inst.get_text(v, text));
        if (v.type == VariableType::real) {
            EXPECT_TRUE(std::isfinite(std::strtod(text.c_str(), nullptr))) << v.name << " = " << text;
        }
    }
    RecordProperty("steps", static_cast<int>(steps));
    RecordProperty("state_events", static_cast<int>(state_events));
    RecordProperty("time_events", static_cast<int>(time_events));
    RecordProperty("step_events", static_cast<int>(step_events));
    ASSERT_FMI_OK(inst, f.fmi2Terminate(inst.c()));
    inst.free();
}
