// Model Exchange of the FMI 3.0 archives, driven side by side with the FMI 2.0 archive of the same
// block by one explicit Euler loop: the same states, derivatives, event indicators and time events
// (a sampled block's samples), bit for bit, through the FMI 3.0 mode machine.
#include <cmath>
#include <cstring>

#include "fixture3.hpp"

namespace {

using conformance3::Instance3;

CONFORMANCE3_SUITE(Conformance3ModelExchange);

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

struct Next {
    bool defined = false;
    double time = 0.0;
};

Next update3(Instance3& inst) {
    fmi3Boolean again = true, terminate = false, nominals = false, values = false, defined = false;
    double next = 0.0;
    for (int round = 0; again && round < 100; ++round)
        EXPECT_EQ(inst.f().update_discrete_states(inst.c(), &again, &terminate, &nominals, &values, &defined, &next),
                  fmi3OK);
    return {static_cast<bool>(defined), next};
}

Next update2(conformance::Instance& inst) {
    fmi2EventInfo info{};
    info.newDiscreteStatesNeeded = fmi2True;
    for (int round = 0; info.newDiscreteStatesNeeded && round < 100; ++round)
        EXPECT_EQ(inst.f().fmi2NewDiscreteStates(inst.c(), &info), fmi2OK);
    return {info.nextEventTimeDefined != fmi2False, info.nextEventTime};
}

TEST_P(Conformance3ModelExchange, EulerRunAgreesWithTheFmi2Archive) {
    Instance3 inst(fmu3(), Instance3::Kind::model_exchange);
    ASSERT_NE(inst.c(), nullptr);
    conformance::Instance inst2(fmu2(), fmi_loader::FmuKind::model_exchange);
    ASSERT_TRUE(inst2.ok());
    ASSERT_EQ(inst.initialize(), fmi3OK) << inst.log().dump();
    ASSERT_EQ(inst2.initialize(md().start_time, md().stop_time), fmi2OK);

    std::size_t nx = 0, nz = 0;
    ASSERT_EQ(inst.f().get_number_of_states(inst.c(), &nx), fmi3OK);
    ASSERT_EQ(inst.f().get_number_of_event_indicators(inst.c(), &nz), fmi3OK);
    EXPECT_EQ(nx, md().count_of(md().derivatives));
    EXPECT_EQ(nz, md().count_of(md().event_indicators));

    Next next3 = update3(inst), next2 = update2(inst2);
    ASSERT_EQ(inst.f().enter_continuous_time_mode(inst.c()), fmi3OK);
    ASSERT_EQ(inst2.f().fmi2EnterContinuousTimeMode(inst2.c()), fmi2OK);

    std::vector<double> x(nx), dx(nx), x2(nx), dx2(nx), z(nz), z2(nz);
    const double h = md().step_size, stop = conformance3::run_stop(md());
    int time_events = 0;
    for (double t = md().start_time; t < stop - 1e-12;) {
        ASSERT_EQ(next3.defined, next2.defined) << "t = " << t;
        if (next3.defined) {
            ASSERT_EQ(next3.time, next2.time) << "t = " << t;
        }
        ASSERT_EQ(inst.f().get_continuous_states(inst.c(), x.data(), nx), fmi3OK);
        ASSERT_EQ(inst.f().get_derivatives(inst.c(), dx.data(), nx), fmi3OK) << inst.log().dump();
        ASSERT_EQ(inst2.f().fmi2GetContinuousStates(inst2.c(), x2.data(), nx), fmi2OK);
        ASSERT_EQ(inst2.f().fmi2GetDerivatives(inst2.c(), dx2.data(), nx), fmi2OK);
        ASSERT_TRUE(same_bits(x, x2)) << "states differ at t = " << t;
        ASSERT_TRUE(same_bits(dx, dx2)) << "derivatives differ at t = " << t;
        ASSERT_EQ(inst.f().get_event_indicators(inst.c(), z.data(), nz), fmi3OK);
        ASSERT_EQ(inst2.f().fmi2GetEventIndicators(inst2.c(), z2.data(), nz), fmi2OK);
        ASSERT_TRUE(same_bits(z, z2)) << "event indicators differ at t = " << t;
        // Step to the next time event or by h, whichever comes first (both FMUs agree on it).
        const double t_next = next3.defined && next3.time < t + h ? next3.time : std::min(t + h, stop);
        for (std::size_t i = 0; i < nx; ++i) x[i] += (t_next - t) * dx[i];
        t = t_next;
        ASSERT_EQ(inst.f().set_time(inst.c(), t), fmi3OK);
        ASSERT_EQ(inst2.f().fmi2SetTime(inst2.c(), t), fmi2OK);
        ASSERT_EQ(inst.f().set_continuous_states(inst.c(), x.data(), nx), fmi3OK);
        ASSERT_EQ(inst2.f().fmi2SetContinuousStates(inst2.c(), x.data(), nx), fmi2OK);
        fmi3Boolean enter = false, terminate = false;
        ASSERT_EQ(inst.f().completed_integrator_step(inst.c(), true, &enter, &terminate), fmi3OK);
        if (next3.defined && t >= next3.time) {
            ++time_events;
            ASSERT_EQ(inst.f().enter_event_mode(inst.c()), fmi3OK);
            ASSERT_EQ(inst2.f().fmi2EnterEventMode(inst2.c()), fmi2OK);
            next3 = update3(inst);
            next2 = update2(inst2);
            ASSERT_EQ(inst.f().enter_continuous_time_mode(inst.c()), fmi3OK);
            ASSERT_EQ(inst2.f().fmi2EnterContinuousTimeMode(inst2.c()), fmi2OK);
        }
    }
    RecordProperty("time_events", time_events);
    EXPECT_FALSE(inst.log().has_error()) << inst.log().dump();
}

}  // namespace
