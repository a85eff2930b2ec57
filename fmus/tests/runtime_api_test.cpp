// The FMI 2.0 C API of the runtime, called directly on the test ball block: the mode machine, bad
// arguments, logging, FMU states and their serialization. Each misuse must give fmi2Error (or
// fmi2Discard) and a logged message, never a crash.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdarg>
#include <limits>
#include <string>
#include <vector>

#include "fmi2/fmi2Functions.h"
#include "fmu/description.hpp"
#include "test_blocks.hpp"

FMU_BLOCK(fmu_test::Ball)

namespace {

struct Log {
    std::vector<std::pair<fmi2Status, std::string>> messages;
};

void logger(fmi2ComponentEnvironment env, fmi2String, fmi2Status status, fmi2String, fmi2String message, ...) {
    // The runtime always passes the text through "%s": the first variadic argument is the message.
    va_list args;
    va_start(args, message);
    const char* text = va_arg(args, const char*);
    va_end(args);
    static_cast<Log*>(env)->messages.emplace_back(status, text);
}

const fmu::TableBase& table() {
    return fmu_test::Ball::static_table();
}
fmi2ValueReference vr(const char* name) {
    return table().by_name(name).value_reference;
}

class Api : public ::testing::Test {
protected:
    Log log;
    fmi2CallbackFunctions callbacks{logger, nullptr, nullptr, nullptr, &log};
    std::string guid = fmu::description_guid(*fmu::make_model());

    fmi2Component make(fmi2Type type) {
        return fmi2Instantiate("ball", type, guid.c_str(), nullptr, &callbacks, fmi2False, fmi2False);
    }
    bool logged_error() const {
        for (const auto& [status, text] : log.messages)
            if (status >= fmi2Discard && !text.empty()) return true;
        return false;
    }
    void expect_refused(fmi2Status status) {
        EXPECT_TRUE(status == fmi2Error || status == fmi2Discard) << status;
        EXPECT_TRUE(logged_error());
        log.messages.clear();
    }
    // Reset the instance (leaving the error mode a refusal put it in) and bring it to `stage`.
    enum class Stage { instantiated, initialization, initialized };
    void back_to(fmi2Component c, Stage stage, bool reset = true) {
        if (reset) {
            ASSERT_EQ(fmi2Reset(c), fmi2OK);
        }
        if (stage == Stage::instantiated) return;
        ASSERT_EQ(fmi2EnterInitializationMode(c), fmi2OK);
        if (stage == Stage::initialization) return;
        ASSERT_EQ(fmi2ExitInitializationMode(c), fmi2OK);
    }
};

TEST_F(Api, WrongGuidOrEmptyNameIsRefusedWithAMessage) {
    EXPECT_EQ(fmi2Instantiate("ball", fmi2CoSimulation, "{wrong}", nullptr, &callbacks, 0, 0), nullptr);
    EXPECT_TRUE(logged_error());
    EXPECT_EQ(fmi2Instantiate("", fmi2CoSimulation, guid.c_str(), nullptr, &callbacks, 0, 0), nullptr);
    EXPECT_EQ(fmi2Instantiate("ball", fmi2CoSimulation, guid.c_str(), nullptr, nullptr, 0, 0), nullptr);
}

TEST_F(Api, NullAndFreedHandlesGiveErrors) {
    EXPECT_EQ(fmi2EnterInitializationMode(nullptr), fmi2Error);
    fmi2Component c = make(fmi2CoSimulation);
    ASSERT_NE(c, nullptr);
    fmi2FreeInstance(c);
    EXPECT_EQ(fmi2EnterInitializationMode(c), fmi2Error);  // freed: recognised, not dereferenced
    fmi2FreeInstance(c);                                   // a second free is ignored
    int not_an_instance = 0;
    EXPECT_EQ(fmi2Terminate(&not_an_instance), fmi2Error);
}

TEST_F(Api, CallsInTheWrongModeAreRefused) {
    // Each refusal leaves the instance in the error mode (ErrorModeHoldsUntilResetOrRestore); a reset
    // brings it back to the mode the next check needs.
    fmi2Component c = make(fmi2CoSimulation);
    expect_refused(fmi2DoStep(c, 0.0, 0.1, fmi2True));  // before initialization
    back_to(c, Stage::instantiated);
    fmi2Real x[2];
    expect_refused(fmi2GetContinuousStates(c, x, 2));  // a Model Exchange function
    back_to(c, Stage::initialization);
    expect_refused(fmi2SetupExperiment(c, 0, 0, 0, 0, 0));
    back_to(c, Stage::initialized);
    const fmi2ValueReference g = vr("g");
    const fmi2Real value = 1.0;
    expect_refused(fmi2SetReal(c, &g, 1, &value));  // fixed parameter after initialization
    back_to(c, Stage::initialized);
    expect_refused(fmi2CancelStep(c));
    fmi2FreeInstance(c);
}

TEST_F(Api, BadArgumentsAreRefused) {
    fmi2Component c = make(fmi2CoSimulation);
    const fmi2ValueReference unknown = 100000, g = vr("g"), e = vr("e"), label = vr("label"), material = vr("material");
    fmi2Real r = 0;
    expect_refused(fmi2GetReal(c, &g, 1, &r));  // reading before initialization mode
    back_to(c, Stage::initialization);
    expect_refused(fmi2GetReal(c, &unknown, 1, &r));
    back_to(c, Stage::initialization);
    expect_refused(fmi2GetReal(c, nullptr, 1, &r));
    back_to(c, Stage::initialization);
    expect_refused(fmi2GetReal(c, &g, 1, nullptr));
    back_to(c, Stage::initialization);
    fmi2Integer i = 0;
    expect_refused(fmi2GetInteger(c, &g, 1, &i));  // g is a Real
    back_to(c, Stage::initialization);
    const fmi2Real nan = std::numeric_limits<double>::quiet_NaN(), too_big = 2.0;
    expect_refused(fmi2SetReal(c, &g, 1, &nan));
    back_to(c, Stage::initialization);
    expect_refused(fmi2SetReal(c, &e, 1, &too_big));
    // Nothing was written by the refused call (values stay readable in the error mode, for diagnosis).
    ASSERT_EQ(fmi2GetReal(c, &e, 1, &r), fmi2OK);
    EXPECT_DOUBLE_EQ(r, 0.8);
    back_to(c, Stage::initialization);
    const fmi2String null_label = nullptr;
    expect_refused(fmi2SetString(c, &label, 1, &null_label));
    back_to(c, Stage::initialization);
    const fmi2Integer no_such_item = 7;
    expect_refused(fmi2SetInteger(c, &material, 1, &no_such_item));
    back_to(c, Stage::initialization);
    const fmi2String categories[] = {"noSuchCategory"};
    expect_refused(fmi2SetDebugLogging(c, fmi2True, 1, categories));
    fmi2FreeInstance(c);
}

TEST_F(Api, ChoiceIsAnEnumerationSetByItemValue) {
    fmi2Component c = make(fmi2CoSimulation);
    const fmi2ValueReference material = vr("material");
    const fmi2Integer steel = 2;  // BallMaterial::steel (test_blocks.hpp)
    ASSERT_EQ(fmi2SetInteger(c, &material, 1, &steel), fmi2OK);
    back_to(c, Stage::initialized, false);
    fmi2Integer read = 0;
    ASSERT_EQ(fmi2GetInteger(c, &material, 1, &read), fmi2OK);
    EXPECT_EQ(read, 2);
    fmi2FreeInstance(c);
}

TEST_F(Api, ErrorModeHoldsUntilResetOrRestore) {
    fmi2Component c = make(fmi2CoSimulation);
    back_to(c, Stage::initialized, false);
    ASSERT_EQ(fmi2DoStep(c, 0.0, 0.1, fmi2True), fmi2OK);
    fmi2FMUstate saved = nullptr;
    ASSERT_EQ(fmi2GetFMUstate(c, &saved), fmi2OK);
    const fmi2ValueReference g = vr("g"), h = vr("h");
    const fmi2Real value = 1.0;
    expect_refused(fmi2SetReal(c, &g, 1, &value));  // an error: the instance is now in the error mode
    expect_refused(fmi2DoStep(c, 0.1, 0.1, fmi2True));
    fmi2FMUstate in_error = nullptr;
    expect_refused(fmi2GetFMUstate(c, &in_error));  // a state taken now could not be continued from
    fmi2Real height = 0.0;
    EXPECT_EQ(fmi2GetReal(c, &h, 1, &height), fmi2OK);  // reads stay possible, for diagnosis
    // Restoring a state saved before the error continues from it, in its mode.
    ASSERT_EQ(fmi2SetFMUstate(c, saved), fmi2OK);
    EXPECT_EQ(fmi2DoStep(c, 0.1, 0.1, fmi2True), fmi2OK);
    ASSERT_EQ(fmi2FreeFMUstate(c, &saved), fmi2OK);
    // So does a reset, from the start.
    expect_refused(fmi2SetReal(c, &g, 1, &value));
    back_to(c, Stage::initialized);
    EXPECT_EQ(fmi2DoStep(c, 0.0, 0.1, fmi2True), fmi2OK);
    fmi2FreeInstance(c);
}

TEST_F(Api, RefusedTunableChangeIsRolledBack) {
    fmi2Component c = make(fmi2CoSimulation);
    const fmi2ValueReference e = vr("e"), drag = vr("drag");
    const fmi2Real high_e = 0.95, high_drag = 6.0;
    ASSERT_EQ(fmi2SetReal(c, &e, 1, &high_e), fmi2OK);
    ASSERT_EQ(fmi2EnterInitializationMode(c), fmi2OK);
    ASSERT_EQ(fmi2ExitInitializationMode(c), fmi2OK);
    expect_refused(fmi2SetReal(c, &drag, 1, &high_drag));  // validate() refuses drag > 5 with e > 0.9
    fmi2Real value = -1;
    ASSERT_EQ(fmi2GetReal(c, &drag, 1, &value), fmi2OK);
    EXPECT_DOUBLE_EQ(value, 0.0);
    fmi2FreeInstance(c);
}

std::vector<double> run_heights(fmi2Component c, double from, int steps) {
    std::vector<double> heights;
    const fmi2ValueReference h = vr("h");
    for (int k = 0; k < steps; ++k) {
        EXPECT_EQ(fmi2DoStep(c, from + 0.05 * k, 0.05, fmi2True), fmi2OK);
        fmi2Real value;
        fmi2GetReal(c, &h, 1, &value);
        heights.push_back(value);
    }
    return heights;
}

TEST_F(Api, SerializedStateContinuesBitIdentically) {
    fmi2Component c = make(fmi2CoSimulation);
    ASSERT_EQ(fmi2EnterInitializationMode(c), fmi2OK);
    ASSERT_EQ(fmi2ExitInitializationMode(c), fmi2OK);
    run_heights(c, 0.0, 7);  // 0.35 s, just before the first bounce
    fmi2FMUstate state = nullptr;
    ASSERT_EQ(fmi2GetFMUstate(c, &state), fmi2OK);
    size_t size = 0;
    ASSERT_EQ(fmi2SerializedFMUstateSize(c, state, &size), fmi2OK);
    std::vector<fmi2Byte> bytes(size);
    ASSERT_EQ(fmi2SerializeFMUstate(c, state, bytes.data(), size), fmi2OK);
    ASSERT_EQ(fmi2FreeFMUstate(c, &state), fmi2OK);
    EXPECT_EQ(state, nullptr);
    const auto uninterrupted = run_heights(c, 0.35, 20);

    fmi2FMUstate restored = nullptr;
    ASSERT_EQ(fmi2DeSerializeFMUstate(c, bytes.data(), size, &restored), fmi2OK);
    ASSERT_EQ(fmi2SetFMUstate(c, restored), fmi2OK);
    const auto resumed = run_heights(c, 0.35, 20);
    EXPECT_EQ(uninterrupted, resumed);  // bit-identical
    fmi2FreeFMUstate(c, &restored);

    // Garbage bytes, a truncated buffer and a foreign pointer are refused.
    std::vector<fmi2Byte> garbage(size, 'x');
    fmi2FMUstate out = nullptr;
    expect_refused(fmi2DeSerializeFMUstate(c, garbage.data(), size, &out));
    expect_refused(fmi2DeSerializeFMUstate(c, bytes.data(), size - 1, &out));
    int foreign = 0;
    expect_refused(fmi2SetFMUstate(c, &foreign));
    fmi2FreeInstance(c);
}

TEST_F(Api, TwoInstancesAreIndependent) {
    fmi2Component a = make(fmi2CoSimulation), b = make(fmi2CoSimulation);
    const fmi2ValueReference h0 = vr("h0");
    const fmi2Real high = 5.0;
    ASSERT_EQ(fmi2SetReal(b, &h0, 1, &high), fmi2OK);
    for (auto c : {a, b}) {
        ASSERT_EQ(fmi2SetupExperiment(c, fmi2True, 1e-10, 0.0, fmi2False, 0.0), fmi2OK);  // tight: closed form below
        ASSERT_EQ(fmi2EnterInitializationMode(c), fmi2OK);
        ASSERT_EQ(fmi2ExitInitializationMode(c), fmi2OK);
    }
    const auto ha = run_heights(a, 0.0, 3), hb = run_heights(b, 0.0, 3);
    EXPECT_NEAR(ha.back(), 1.0 - 0.5 * 9.81 * 0.15 * 0.15, 1e-6);
    EXPECT_NEAR(hb.back(), 5.0 - 0.5 * 9.81 * 0.15 * 0.15, 1e-6);
    fmi2FreeInstance(a);
    fmi2FreeInstance(b);
}

TEST_F(Api, ModelExchangeSequenceWithEventsAndLogging) {
    fmi2Component c = make(fmi2ModelExchange);
    const fmi2String categories[] = {"logEvents"};
    ASSERT_EQ(fmi2SetDebugLogging(c, fmi2True, 1, categories), fmi2OK);
    ASSERT_EQ(fmi2SetupExperiment(c, fmi2False, 0, 0.0, fmi2False, 0), fmi2OK);
    ASSERT_EQ(fmi2EnterInitializationMode(c), fmi2OK);
    ASSERT_EQ(fmi2ExitInitializationMode(c), fmi2OK);
    fmi2EventInfo info{};
    ASSERT_EQ(fmi2NewDiscreteStates(c, &info), fmi2OK);
    EXPECT_TRUE(info.nextEventTimeDefined);
    EXPECT_DOUBLE_EQ(info.nextEventTime, 0.25);
    ASSERT_EQ(fmi2EnterContinuousTimeMode(c), fmi2OK);
    // Forward Euler to the first time event, as a simple host would.
    double x[2], dx[2], z[1];
    double t = 0.0;
    const double dt = 1e-3;
    while (t < 0.25 - 1e-12) {
        ASSERT_EQ(fmi2GetContinuousStates(c, x, 2), fmi2OK);
        ASSERT_EQ(fmi2GetDerivatives(c, dx, 2), fmi2OK);
        t += dt;
        ASSERT_EQ(fmi2SetTime(c, t), fmi2OK);
        for (int i = 0; i < 2; ++i) x[i] += dt * dx[i];
        ASSERT_EQ(fmi2SetContinuousStates(c, x, 2), fmi2OK);
        fmi2Boolean enter = fmi2True, stop = fmi2True;
        ASSERT_EQ(fmi2CompletedIntegratorStep(c, fmi2True, &enter, &stop), fmi2OK);
        EXPECT_FALSE(enter);
    }
    ASSERT_EQ(fmi2GetEventIndicators(c, z, 1), fmi2OK);
    EXPECT_GT(z[0], 0.0);
    fmi2FMUstate before = nullptr;
    ASSERT_EQ(fmi2GetFMUstate(c, &before), fmi2OK);
    expect_refused(fmi2GetEventIndicators(c, z, 2));  // wrong count: the instance enters the error mode
    ASSERT_EQ(fmi2SetFMUstate(c, before), fmi2OK);    // and continues from the state saved before it
    ASSERT_EQ(fmi2FreeFMUstate(c, &before), fmi2OK);
    ASSERT_EQ(fmi2SetTime(c, 0.25), fmi2OK);
    ASSERT_EQ(fmi2EnterEventMode(c), fmi2OK);
    ASSERT_EQ(fmi2NewDiscreteStates(c, &info), fmi2OK);
    EXPECT_DOUBLE_EQ(info.nextEventTime, 0.5);
    bool saw_event_log = false;
    for (const auto& [status, text] : log.messages)
        saw_event_log = saw_event_log || text.find("time event") != std::string::npos;
    EXPECT_TRUE(saw_event_log);
    const fmi2ValueReference ticks = vr("ticks");
    fmi2Integer n = 0;
    ASSERT_EQ(fmi2GetInteger(c, &ticks, 1, &n), fmi2OK);
    EXPECT_EQ(n, 1);
    ASSERT_EQ(fmi2Terminate(c), fmi2OK);
    fmi2FreeInstance(c);
}

TEST_F(Api, ResetReturnsToDefaults) {
    fmi2Component c = make(fmi2CoSimulation);
    const fmi2ValueReference h0 = vr("h0");
    const fmi2Real value = 3.0;
    fmi2SetReal(c, &h0, 1, &value);
    ASSERT_EQ(fmi2Reset(c), fmi2OK);
    ASSERT_EQ(fmi2EnterInitializationMode(c), fmi2OK);
    fmi2Real read = 0;
    ASSERT_EQ(fmi2GetReal(c, &h0, 1, &read), fmi2OK);
    EXPECT_DOUBLE_EQ(read, 1.0);
    fmi2FreeInstance(c);
}

}  // namespace
