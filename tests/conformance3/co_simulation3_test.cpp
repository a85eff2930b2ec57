// Co-Simulation of the FMI 3.0 archives: without event mode the steps are the FMI 2.0 archive's, bit
// for bit; with event mode the FMU stops at each of its events (early return inside a step, or at a
// step's end without early return), the host runs the discrete update in Event Mode, and the run
// ends where the run without event mode ends, within the integration tolerance. A block with a
// `sample_period` (the on-board computer) stops exactly at its samples.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "fixture3.hpp"

namespace {

using conformance3::Instance3;

CONFORMANCE3_SUITE(Conformance3CoSimulation);

TEST_P(Conformance3CoSimulation, StepsAsTheFmi2ArchiveWithoutEventMode) {
    Instance3 inst(fmu3(), Instance3::Kind::co_simulation);
    conformance::Instance inst2(fmu2(), fmi_loader::FmuKind::co_simulation);
    ASSERT_EQ(inst.initialize(), fmi3OK) << inst.log().dump();
    ASSERT_EQ(inst2.initialize(md().start_time, md().stop_time), fmi2OK);
    const double h = md().step_size, stop = conformance3::run_stop(md());
    const auto bits = conformance::real_output_bits(inst2);
    std::vector<double> out = inst.outputs();
    ASSERT_EQ(out.size(), bits.size());
    for (double t = md().start_time; t < stop - 1e-12; t += h) {
        fmi3Boolean event = false, terminate = false, early = false;
        double last = 0.0;
        ASSERT_EQ(inst.f().do_step(inst.c(), t, h, true, &event, &terminate, &early, &last), fmi3OK)
            << inst.log().dump();
        EXPECT_FALSE(event);
        EXPECT_FALSE(early);
        ASSERT_EQ(inst2.f().fmi2DoStep(inst2.c(), t, h, fmi2True), fmi2OK);
        out = inst.outputs();
        const auto bits2 = conformance::real_output_bits(inst2);
        ASSERT_EQ(std::memcmp(out.data(), bits2.data(), out.size() * sizeof(double)), 0) << "t = " << t + h;
    }
}

struct EventRun {
    std::vector<double> outputs, event_times;
    int early_returns = 0;
};

// Steps of `step` to `stop`, continuing from wherever a step ended, with the events in Event Mode.
EventRun run_with_event_mode(conformance3::Fmu3& fmu, bool early_return_allowed, double step, double stop) {
    Instance3 inst(fmu, Instance3::Kind::co_simulation, true, early_return_allowed);
    EventRun run;
    EXPECT_EQ(inst.initialize(), fmi3OK) << inst.log().dump();
    const auto& md = fmu.md();
    auto update = [&] {
        fmi3Boolean again = true, terminate = false, nominals = false, values = false, defined = false;
        double next = 0.0;
        for (int round = 0; again && round < 100; ++round)
            EXPECT_EQ(
                inst.f().update_discrete_states(inst.c(), &again, &terminate, &nominals, &values, &defined, &next),
                fmi3OK);
        EXPECT_EQ(inst.f().enter_step_mode(inst.c()), fmi3OK);
    };
    update();  // Event Mode after initialization
    double t = md.start_time;
    for (int guard = 0; t < stop - 1e-12 && guard < 100000; ++guard) {
        const double h = std::min(step, stop - t);
        fmi3Boolean event = false, terminate = false, early = false;
        double last = 0.0;
        EXPECT_EQ(inst.f().do_step(inst.c(), t, h, true, &event, &terminate, &early, &last), fmi3OK)
            << inst.log().dump();
        EXPECT_FALSE(early && !early_return_allowed);
        run.early_returns += early ? 1 : 0;
        t = early ? last : t + h;
        if (event) {
            run.event_times.push_back(last);
            EXPECT_EQ(inst.f().enter_event_mode(inst.c()), fmi3OK) << inst.log().dump();
            update();
        }
    }
    run.outputs = inst.outputs();
    EXPECT_FALSE(inst.log().has_error()) << inst.log().dump();
    return run;
}

// The outputs at `stop` of a run without event mode in steps of h (the last one shortened to end at stop).
std::vector<double> plain_run(conformance3::Fmu3& fmu, double h_max, double stop) {
    Instance3 plain(fmu, Instance3::Kind::co_simulation);
    EXPECT_EQ(plain.initialize(), fmi3OK);
    for (double t = fmu.md().start_time; t < stop - 1e-12;) {
        const double h = std::min(h_max, stop - t);
        fmi3Boolean event = false, terminate = false, early = false;
        double last = 0.0;
        EXPECT_EQ(plain.f().do_step(plain.c(), t, h, true, &event, &terminate, &early, &last), fmi3OK);
        t += h;
    }
    return plain.outputs();
}

// Event mode changes the communication points (a step ends at each event), and the outputs of a block
// depend on those within its integration error: the bound is four times the spread of runs without
// event mode on three grids (h, h/2, h/4), and at least 1e-5 relative. For most blocks the spread is
// at rounding level; ssr_plant's instantaneous bus voltage moves by 0.3 % with the grid (measured:
// 15.00 to 15.06 V at 1 s over these grids, the same in its FMI 2.0 archive), its switching ripple
// sampled at event times that move with the grid.
TEST_P(Conformance3CoSimulation, EventModeEndsWhereInternalEventsEnd) {
    const double stop = conformance3::run_stop(md()), h = md().step_size;
    const auto expected = plain_run(fmu3(), h, stop);
    const auto half = plain_run(fmu3(), h / 2, stop), quarter = plain_run(fmu3(), h / 4, stop);
    for (const bool early : {true, false}) {
        const EventRun run = run_with_event_mode(fmu3(), early, h, stop);
        ASSERT_EQ(run.outputs.size(), expected.size());
        for (std::size_t i = 0; i < expected.size(); ++i) {
            const double spread =
                std::max({expected[i], half[i], quarter[i]}) - std::min({expected[i], half[i], quarter[i]});
            EXPECT_NEAR(run.outputs[i], expected[i], std::max(4 * spread, 1e-5 * std::max(1.0, std::abs(expected[i]))))
                << "output element " << i << (early ? " with" : " without") << " early return";
        }
        if (!early) {
            EXPECT_EQ(run.early_returns, 0);
        }
    }
}

// The sampled block's samples are events a host without clocks sees: one every sample_period.
TEST_P(Conformance3CoSimulation, SampledBlockStopsAtEachSample) {
    const auto period = std::find_if(md().variables.begin(), md().variables.end(),
                                     [](const auto& v) { return v.name == "sample_period"; });
    if (period == md().variables.end()) GTEST_SKIP() << "no sample_period: not a sampled block";
    const double dt = std::stod(period->start.at(0));
    // Steps longer than a sample: only early returns can stop at each.
    const EventRun run = run_with_event_mode(fmu3(), true, 2.5 * dt, md().start_time + 10 * dt);
    ASSERT_GE(run.event_times.size(), 10u);
    for (std::size_t k = 1; k < run.event_times.size(); ++k)
        EXPECT_NEAR(run.event_times[k] - run.event_times[k - 1], dt, 1e-9) << "event " << k;
    EXPECT_GT(run.early_returns, 0);
}

// With an intermediate-update callback the host decides at each event inside a step: the step goes
// on through the events it declines and ends at the first one it asks to return at.
struct Asked {
    std::vector<double> times;
    std::size_t return_at = 3;  // the call (1-based) at which the host requests an early return
};
Asked asked;  // the callback has no environment of its own (the instance's is its log)

void ask_host(fmi3InstanceEnvironment, fmi3Float64 time, fmi3Boolean, fmi3Boolean, fmi3Boolean,
              fmi3Boolean can_return_early, fmi3Boolean* requested, fmi3Float64*) {
    asked.times.push_back(time);
    *requested = can_return_early && asked.times.size() == asked.return_at;
}

TEST_P(Conformance3CoSimulation, IntermediateUpdateDecidesTheEarlyReturn) {
    const auto period = std::find_if(md().variables.begin(), md().variables.end(),
                                     [](const auto& v) { return v.name == "sample_period"; });
    if (period == md().variables.end()) GTEST_SKIP() << "no sample_period: no events at known times";
    const double dt = std::stod(period->start.at(0));
    asked = {};
    Instance3 inst(fmu3(), Instance3::Kind::co_simulation, true, true, "", ask_host);
    ASSERT_EQ(inst.initialize(), fmi3OK);
    fmi3Boolean again = true, terminate = false, nominals = false, values = false, defined = false;
    double next = 0.0;
    while (again)
        ASSERT_EQ(inst.f().update_discrete_states(inst.c(), &again, &terminate, &nominals, &values, &defined, &next),
                  fmi3OK);
    ASSERT_EQ(inst.f().enter_step_mode(inst.c()), fmi3OK);
    fmi3Boolean event = false, early = false;
    double last = 0.0;
    ASSERT_EQ(inst.f().do_step(inst.c(), md().start_time, 10 * dt, true, &event, &terminate, &early, &last), fmi3OK)
        << inst.log().dump();
    ASSERT_EQ(asked.times.size(), asked.return_at);
    for (std::size_t k = 0; k < asked.times.size(); ++k)
        EXPECT_NEAR(asked.times[k], md().start_time + static_cast<double>(k + 1) * dt, 1e-9) << "call " << k + 1;
    EXPECT_TRUE(early);
    EXPECT_TRUE(event);
    EXPECT_EQ(last, asked.times.back());
}

// Issue 38: the callback runs in Intermediate Update Mode, where the standard allows only the get/set of
// intermediate-update variables (none here). fmi3DoStep (a step inside the step) and fmi3EnterEventMode
// from inside it are refused with fmi3Error and a message, and the outer step is abandoned; fmi3FreeInstance
// from inside is refused (the step is on the stack).
struct Inside {
    const Instance3* instance = nullptr;
    int call = 0;  // 0: fmi3DoStep, 1: fmi3EnterEventMode
    std::vector<fmi3Status> statuses;
};
Inside inside;

void call_from_inside(fmi3InstanceEnvironment, fmi3Float64 time, fmi3Boolean, fmi3Boolean, fmi3Boolean, fmi3Boolean,
                      fmi3Boolean* requested, fmi3Float64*) {
    *requested = false;
    if (!inside.instance || !inside.statuses.empty()) return;
    const auto& f = inside.instance->f();
    fmi3Boolean event = false, terminate = false, early = false;
    double last = 0.0;
    inside.statuses.push_back(inside.call == 0
                                  ? f.do_step(inside.instance->c(), time, 1e-3, true, &event, &terminate, &early, &last)
                                  : f.enter_event_mode(inside.instance->c()));
    f.free_instance(inside.instance->c());  // refused: the instance is freed by its owner after the step
}

TEST_P(Conformance3CoSimulation, CallsFromInsideTheIntermediateUpdateCallbackAreRefused) {
    const auto period = std::find_if(md().variables.begin(), md().variables.end(),
                                     [](const auto& v) { return v.name == "sample_period"; });
    if (period == md().variables.end()) GTEST_SKIP() << "no sample_period: no events inside a step";
    const double dt = std::stod(period->start.at(0));
    for (int call : {0, 1}) {
        Instance3 inst(fmu3(), Instance3::Kind::co_simulation, true, true, "", call_from_inside);
        ASSERT_EQ(inst.initialize(), fmi3OK);
        fmi3Boolean again = true, terminate = false, nominals = false, values = false, defined = false;
        double next = 0.0;
        while (again)
            ASSERT_EQ(
                inst.f().update_discrete_states(inst.c(), &again, &terminate, &nominals, &values, &defined, &next),
                fmi3OK);
        ASSERT_EQ(inst.f().enter_step_mode(inst.c()), fmi3OK);
        inside = {&inst, call, {}};
        fmi3Boolean event = false, early = false;
        double last = 0.0;
        EXPECT_EQ(inst.f().do_step(inst.c(), md().start_time, 10 * dt, true, &event, &terminate, &early, &last),
                  fmi3Error);
        inside.instance = nullptr;
        ASSERT_EQ(inside.statuses.size(), 1u);
        EXPECT_EQ(inside.statuses[0], fmi3Error);
        const std::string log = inst.log().dump();
        EXPECT_NE(log.find(call == 0 ? "fmi3DoStep is not allowed in Intermediate Update Mode"
                                     : "fmi3EnterEventMode is not allowed in Intermediate Update Mode"),
                  std::string::npos)
            << log;
        EXPECT_NE(log.find("fmi3FreeInstance is not allowed in Intermediate Update Mode"), std::string::npos) << log;
        EXPECT_NE(log.find("the step is abandoned"), std::string::npos) << log;
    }
}

// Issue 38: a non-finite communication point is refused naming it, in FMI 3.0's words.
TEST_P(Conformance3CoSimulation, NonFiniteStepArgumentsAreRefusedByName) {
    Instance3 inst(fmu3(), Instance3::Kind::co_simulation);
    ASSERT_EQ(inst.initialize(), fmi3OK);
    fmi3Boolean event = false, terminate = false, early = false;
    double last = 0.0;
    EXPECT_EQ(inst.f().do_step(inst.c(), std::nan(""), 0.1, true, &event, &terminate, &early, &last), fmi3Error);
    const std::string log = inst.log().dump();
    EXPECT_NE(log.find("fmi3DoStep: currentCommunicationPoint must be finite (got nan)"), std::string::npos) << log;
    EXPECT_EQ(log.find("fmi2DoStep"), std::string::npos) << log;
}

}  // namespace
