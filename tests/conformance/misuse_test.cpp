// Misuse must be answered with fmi2Error and a logged message, never a crash (FMI 2.0.4 section
// 2.1.3: "fmi2Error ... the FMU encountered an error"; the call-sequence tables of sections 3.2.3 and
// 4.2.4). Every misuse runs in a forked child so a crash fails only its own check.
#include <cmath>
#include <limits>

#include "conformance_fixture.hpp"

using namespace conformance;
using namespace fmi_loader;

CONFORMANCE_SUITE(ConformanceMisuse);

namespace {

using Prepare = std::function<bool(Instance&)>;  // brings the instance to the state under test
using Misuse = std::function<fmi2Status(Instance&)>;

bool initialized(Instance& inst) {
    const Experiment ex = experiment_of(inst.md());
    return inst.initialize(ex.start, ex.stop) <= fmi2Warning;
}

bool in_initialization_mode(Instance& inst) {
    const Experiment ex = experiment_of(inst.md());
    return inst.f().fmi2SetupExperiment(inst.c(), fmi2False, 0.0, ex.start, fmi2False, 0.0) <= fmi2Warning &&
           inst.f().fmi2EnterInitializationMode(inst.c()) <= fmi2Warning;
}

bool instantiated(Instance&) {
    return true;
}

// Runs `misuse` on a fresh instance brought to a state by `prepare`; expects `expected` and a log
// message at least as severe, or only "no crash and not fmi2OK" when `require_log` is false.
void expect_rejected(Fmu& fmu, FmuKind kind, const Prepare& prepare, const Misuse& misuse, const char* what,
                     bool require_log = true, fmi2Status expected = fmi2Error) {
    const IsolatedResult r = run_isolated([&](bool& logged, std::string& log) {
        Instance inst(fmu, kind);
        if (!inst.ok() || !prepare(inst)) {
            log = "PREPARE FAILED\n" + inst.log().dump();
            return fmi2Pending;
        }
        const std::size_t mark = inst.log_mark();
        const fmi2Status s = misuse(inst);
        logged = inst.log().has_since(mark, expected);
        log = inst.log().dump();
        inst.free();
        return s;
    });
    ASSERT_TRUE(r.completed) << what << ": " << r.crash;
    ASSERT_NE(r.status, fmi2Pending) << what << ": could not reach the state under test\n" << r.log;
    if (require_log) {
        EXPECT_EQ(r.status, expected) << what << " returned " << status_name(r.status) << "\nFMU log:\n" << r.log;
        EXPECT_TRUE(r.logged) << what << ": no message of severity >= " << status_name(expected)
                              << " reached the logger\nFMU log:\n"
                              << r.log;
    } else {
        EXPECT_GE(r.status, fmi2Error) << what << " returned " << status_name(r.status);
    }
}

const ScalarVariable* first_real(const ModelDescription& md) {
    for (const auto& v : md.model_variables)
        if (v.type == VariableType::real) return &v;
    return nullptr;
}

std::uint32_t unused_value_reference(const ModelDescription& md) {
    std::uint32_t max = 0;
    for (const auto& v : md.model_variables) max = std::max(max, v.value_reference);
    return max + 1000;
}

}  // namespace

TEST_P(ConformanceMisuse, DoStepBeforeInitialization) {
    if (!md().co_simulation) GTEST_SKIP() << "no CoSimulation";
    expect_rejected(
        fmu(), FmuKind::co_simulation, instantiated,
        [](Instance& i) { return i.f().fmi2DoStep(i.c(), 0.0, 0.1, fmi2True); }, "fmi2DoStep in Instantiated");
}

TEST_P(ConformanceMisuse, DoStepAfterTerminate) {
    if (!md().co_simulation) GTEST_SKIP() << "no CoSimulation";
    expect_rejected(
        fmu(), FmuKind::co_simulation,
        [](Instance& i) { return initialized(i) && i.f().fmi2Terminate(i.c()) <= fmi2Warning; },
        [](Instance& i) { return i.f().fmi2DoStep(i.c(), 0.0, 0.1, fmi2True); }, "fmi2DoStep in Terminated");
}

TEST_P(ConformanceMisuse, ExitInitializationWithoutEnter) {
    expect_rejected(
        fmu(), preferred_kind(), instantiated, [](Instance& i) { return i.f().fmi2ExitInitializationMode(i.c()); },
        "fmi2ExitInitializationMode in Instantiated");
}

TEST_P(ConformanceMisuse, GetDerivativesOnCoSimulationInstance) {
    if (!md().co_simulation) GTEST_SKIP() << "no CoSimulation";
    if (!fmu().library(FmuKind::co_simulation)->fmi2GetDerivatives)
        GTEST_SKIP() << "binary has no Model Exchange functions";
    const std::size_t nx = std::max<std::size_t>(1, md().number_of_continuous_states());
    expect_rejected(
        fmu(), FmuKind::co_simulation, initialized,
        [nx](Instance& i) {
            std::vector<double> dx(nx);
            return i.f().fmi2GetDerivatives(i.c(), dx.data(), nx);
        },
        "fmi2GetDerivatives on a Co-Simulation instance");
}

TEST_P(ConformanceMisuse, SetFixedParameterAfterInitialization) {
    const ScalarVariable* p = nullptr;
    for (const auto& v : md().model_variables)
        if (v.causality == Causality::parameter && v.variability == Variability::fixed && v.start) {
            p = &v;
            break;
        }
    if (!p) GTEST_SKIP() << "no fixed parameter";
    expect_rejected(
        fmu(), preferred_kind(), initialized, [p](Instance& i) { return i.set_start(*p); },
        ("setting fixed parameter '" + p->name + "' after initialization").c_str());
}

TEST_P(ConformanceMisuse, NullValueReferenceArray) {
    double values[1] = {0.0};
    expect_rejected(
        fmu(), preferred_kind(), in_initialization_mode,
        [&](Instance& i) { return i.f().fmi2GetReal(i.c(), nullptr, 1, values); }, "fmi2GetReal with vr=NULL, nvr=1");
    expect_rejected(
        fmu(), preferred_kind(), in_initialization_mode,
        [&](Instance& i) { return i.f().fmi2SetReal(i.c(), nullptr, 1, values); }, "fmi2SetReal with vr=NULL, nvr=1");
}

TEST_P(ConformanceMisuse, NullValueArray) {
    const ScalarVariable* v = first_real(md());
    if (!v) GTEST_SKIP() << "no Real variable";
    const fmi2ValueReference vr = v->value_reference;
    expect_rejected(
        fmu(), preferred_kind(), in_initialization_mode,
        [vr](Instance& i) { return i.f().fmi2GetReal(i.c(), &vr, 1, nullptr); }, "fmi2GetReal with value=NULL");
    expect_rejected(
        fmu(), preferred_kind(), in_initialization_mode,
        [vr](Instance& i) { return i.f().fmi2SetReal(i.c(), &vr, 1, nullptr); }, "fmi2SetReal with value=NULL");
}

TEST_P(ConformanceMisuse, NullComponentDoesNotCrash) {
    // No instance means no logger to call: only "no crash, not OK" can be asked for.
    const fmi2ValueReference vr = 0;
    double value = 0.0;
    const FmuKind kind = preferred_kind();
    expect_rejected(
        fmu(), kind, instantiated, [&](Instance& i) { return i.f().fmi2GetReal(nullptr, &vr, 1, &value); },
        "fmi2GetReal(NULL component)", false);
    expect_rejected(
        fmu(), kind, instantiated, [&](Instance& i) { return i.f().fmi2SetReal(nullptr, &vr, 1, &value); },
        "fmi2SetReal(NULL component)", false);
    expect_rejected(
        fmu(), kind, instantiated, [](Instance& i) { return i.f().fmi2EnterInitializationMode(nullptr); },
        "fmi2EnterInitializationMode(NULL component)", false);
    expect_rejected(
        fmu(), kind, instantiated, [](Instance& i) { return i.f().fmi2SetDebugLogging(nullptr, fmi2True, 0, nullptr); },
        "fmi2SetDebugLogging(NULL component)", false);
    if (kind == FmuKind::co_simulation)
        expect_rejected(
            fmu(), kind, instantiated, [](Instance& i) { return i.f().fmi2DoStep(nullptr, 0.0, 0.1, fmi2True); },
            "fmi2DoStep(NULL component)", false);
    // fmi2FreeInstance(NULL) returns nothing; it just must not crash.
    expect_rejected(
        fmu(), kind, instantiated,
        [](Instance& i) {
            i.f().fmi2FreeInstance(nullptr);
            return fmi2Error;
        },
        "fmi2FreeInstance(NULL)", false);
}

TEST_P(ConformanceMisuse, UnknownValueReference) {
    const fmi2ValueReference vr = unused_value_reference(md());
    expect_rejected(
        fmu(), preferred_kind(), in_initialization_mode,
        [vr](Instance& i) {
            double x;
            return i.f().fmi2GetReal(i.c(), &vr, 1, &x);
        },
        "fmi2GetReal of an unknown vr");
    expect_rejected(
        fmu(), preferred_kind(), in_initialization_mode, [vr](Instance& i) { return i.set_real(vr, 1.0); },
        "fmi2SetReal of an unknown vr");
    expect_rejected(
        fmu(), preferred_kind(), in_initialization_mode,
        [vr](Instance& i) {
            fmi2Integer x;
            return i.f().fmi2GetInteger(i.c(), &vr, 1, &x);
        },
        "fmi2GetInteger of an unknown vr");
}

TEST_P(ConformanceMisuse, NaNForRealInput) {
    const ScalarVariable* u = nullptr;
    for (const auto& v : md().model_variables)
        if (v.causality == Causality::input && v.type == VariableType::real) {
            u = &v;
            break;
        }
    if (!u) GTEST_SKIP() << "no Real input";
    const fmi2ValueReference vr = u->value_reference;
    expect_rejected(
        fmu(), preferred_kind(), initialized,
        [vr](Instance& i) { return i.set_real(vr, std::numeric_limits<double>::quiet_NaN()); },
        ("NaN into input '" + u->name + "'").c_str());
}

TEST_P(ConformanceMisuse, OutOfRangeParameter) {
    const ScalarVariable* p = nullptr;
    for (const auto& v : md().model_variables)
        if (v.causality == Causality::parameter && (v.min || v.max) && v.start &&
            (v.type == VariableType::real || v.type == VariableType::integer || v.type == VariableType::enumeration)) {
            p = &v;
            break;
        }
    if (!p) GTEST_SKIP() << "no parameter declares min or max";
    // Just beyond the bound: one unit (or the bound's magnitude) outside.
    const double beyond =
        p->max ? *p->max + std::max(1.0, std::fabs(*p->max)) : *p->min - std::max(1.0, std::fabs(*p->min));
    const fmi2ValueReference vr = p->value_reference;
    const bool real = p->type == VariableType::real;
    expect_rejected(
        fmu(), preferred_kind(), instantiated,
        [=](Instance& i) { return real ? i.set_real(vr, beyond) : i.set_integer(vr, static_cast<int>(beyond)); },
        ("out-of-range value " + std::to_string(beyond) + " into parameter '" + p->name + "'").c_str());
}

TEST_P(ConformanceMisuse, WrongGuidIsRefused) {
    const FmuKind kind = preferred_kind();
    const IsolatedResult r = run_isolated([&](bool& logged, std::string& log) {
        Instance inst(fmu(), kind, "wrong_guid",
                      std::string("{00000000-0000-0000-0000-000000000000}-not-") + md().guid);
        logged = inst.log().has_since(0, fmi2Error);
        log = inst.log().dump();
        return inst.ok() ? fmi2OK : fmi2Error;
    });
    ASSERT_TRUE(r.completed) << r.crash;
    EXPECT_EQ(r.status, fmi2Error) << "fmi2Instantiate with a wrong GUID did not return NULL";
    EXPECT_TRUE(r.logged) << "no error message for the wrong GUID\nFMU log:\n" << r.log;
}

// FMI 2.0.4 section 2.1.3: after fmi2Error "the simulation cannot be continued with this FMU instance"
// unless a state saved before the error is restored (canGetAndSetFMUstate) or the instance is reset.
// Our FMUs enforce it: after an error a step is refused; a restore continues from the saved state; a
// reset starts over.
TEST_P(ConformanceMisuse, AfterAnErrorOnlyARestoreOrAResetContinues) {
    if (!md().co_simulation || !md().co_simulation->can_get_and_set_fmu_state)
        GTEST_SKIP() << "no Co-Simulation with FMU states";
    const ScalarVariable* p = nullptr;
    for (const auto& v : md().model_variables)
        if (v.causality == Causality::parameter && v.variability == Variability::fixed && v.start) {
            p = &v;
            break;
        }
    if (!p) GTEST_SKIP() << "no fixed parameter to provoke an error with";
    const IsolatedResult r = run_isolated([&](bool& logged, std::string& log) -> fmi2Status {
        Instance inst(fmu(), FmuKind::co_simulation);
        const Experiment ex = experiment_of(inst.md());
        auto fail = [&](const char* why) {
            log = std::string(why) + "\n" + inst.log().dump();
            return fmi2Fatal;
        };
        if (!inst.ok() || !initialized(inst)) return fail("could not initialize");
        const auto& f = inst.f();
        fmi2FMUstate saved = nullptr;
        if (f.fmi2GetFMUstate(inst.c(), &saved) != fmi2OK) return fail("fmi2GetFMUstate failed");
        if (inst.set_start(*p) != fmi2Error) return fail("setting a fixed parameter was not an error");
        logged = true;
        if (f.fmi2DoStep(inst.c(), ex.start, ex.step, fmi2True) != fmi2Error)
            return fail("fmi2DoStep was accepted after an error");
        if (f.fmi2SetFMUstate(inst.c(), saved) != fmi2OK) return fail("fmi2SetFMUstate after the error failed");
        if (f.fmi2DoStep(inst.c(), ex.start, ex.step, fmi2True) > fmi2Warning)
            return fail("fmi2DoStep after restoring the state saved before the error failed");
        f.fmi2FreeFMUstate(inst.c(), &saved);
        if (inst.set_start(*p) != fmi2Error) return fail("the second error was not one");
        if (f.fmi2Reset(inst.c()) != fmi2OK) return fail("fmi2Reset after the error failed");
        if (!initialized(inst)) return fail("initialization after fmi2Reset failed");
        if (f.fmi2DoStep(inst.c(), ex.start, ex.step, fmi2True) > fmi2Warning)
            return fail("fmi2DoStep after fmi2Reset failed");
        inst.free();
        return fmi2OK;
    });
    ASSERT_TRUE(r.completed) << r.crash;
    EXPECT_EQ(r.status, fmi2OK) << r.log;
}

// A restore out of the error mode on an instance that has no Co-Simulation solver (reset, or never
// initialized) must continue or refuse, never crash: issue 24's first finding, a null solver reached
// through fmi2Reset -> a refused call -> fmi2SetFMUstate (or a deserialized state) -> fmi2DoStep.
TEST_P(ConformanceMisuse, ARestoreIntoAnInstanceWithoutASolverSteps) {
    if (!md().co_simulation || !md().co_simulation->can_get_and_set_fmu_state)
        GTEST_SKIP() << "no Co-Simulation with FMU states";
    for (const bool through_bytes : {false, true}) {
        const IsolatedResult r = run_isolated([&](bool& logged, std::string& log) -> fmi2Status {
            Instance donor(fmu(), FmuKind::co_simulation, "donor");
            const Experiment ex = experiment_of(donor.md());
            auto fail = [&](const char* why) {
                log = std::string(why) + "\n" + donor.log().dump();
                return fmi2Fatal;
            };
            if (!donor.ok() || !initialized(donor)) return fail("could not initialize");
            const auto& f = donor.f();
            fmi2FMUstate saved = nullptr;
            if (f.fmi2GetFMUstate(donor.c(), &saved) != fmi2OK) return fail("fmi2GetFMUstate failed");
            // The instance under test: the donor itself after a reset, or a fresh one never initialized.
            Instance fresh(fmu(), FmuKind::co_simulation, "fresh");
            Instance& inst = through_bytes ? fresh : donor;
            if (!through_bytes && f.fmi2Reset(donor.c()) != fmi2OK) return fail("fmi2Reset failed");
            if (f.fmi2DoStep(inst.c(), ex.start, ex.step, fmi2True) != fmi2Error)
                return fail("fmi2DoStep before initialization was not refused");
            logged = true;
            fmi2FMUstate target = saved;
            if (through_bytes) {
                std::size_t size = 0;
                if (f.fmi2SerializedFMUstateSize(donor.c(), saved, &size) != fmi2OK) return fail("size failed");
                std::vector<fmi2Byte> bytes(size);
                if (f.fmi2SerializeFMUstate(donor.c(), saved, bytes.data(), size) != fmi2OK)
                    return fail("fmi2SerializeFMUstate failed");
                target = nullptr;
                if (f.fmi2DeSerializeFMUstate(inst.c(), bytes.data(), size, &target) != fmi2OK)
                    return fail("fmi2DeSerializeFMUstate failed");
            }
            if (f.fmi2SetFMUstate(inst.c(), target) != fmi2OK) return fail("fmi2SetFMUstate after the error failed");
            if (f.fmi2DoStep(inst.c(), ex.start, ex.step, fmi2True) > fmi2Warning)
                return fail("fmi2DoStep after the restore failed");
            if (through_bytes) f.fmi2FreeFMUstate(inst.c(), &target);
            f.fmi2FreeFMUstate(donor.c(), &saved);
            fresh.free();
            donor.free();
            return fmi2OK;
        });
        ASSERT_TRUE(r.completed) << (through_bytes ? "deserialized into a fresh instance: " : "after fmi2Reset: ")
                                 << r.crash;
        EXPECT_EQ(r.status, fmi2OK) << r.log;
    }
}
