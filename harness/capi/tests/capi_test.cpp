// The C API (pvatt/cosim.h) on a small system with a closed-form answer: an open input u = 1 through
// the test gain (y = k u) into the test integrator (dx/dt = u / tau, x(0) = 1), so x(t) = 1 + k t / tau.
#include <gtest/gtest.h>
#include <unistd.h>

#include <unistd.h>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "pvatt/cosim.h"

namespace {

const char* const fmu_dir = PVATT_CAPI_TEST_FMU_DIR;

std::filesystem::path write_ssd(const std::string& name, const std::string& extra_connection = "") {
    const auto path =
        std::filesystem::temp_directory_path() / ("pvatt_capi_" + std::to_string(::getpid()) + "_" + name + ".ssd");
    std::ofstream(path) << R"(<?xml version="1.0" encoding="UTF-8"?>
<ssd:SystemStructureDescription xmlns:ssd="http://ssp-standard.org/SSP1/SystemStructureDescription"
    xmlns:ssc="http://ssp-standard.org/SSP1/SystemStructureCommon" version="1.0" name="chain">
  <ssd:System name="chain">
    <ssd:Elements>
      <ssd:Component name="gain" source="test_gain.fmu"/>
      <ssd:Component name="integ" source="test_integrator.fmu"/>
    </ssd:Elements>
    <ssd:Connections>
      <ssd:Connection startElement="gain" startConnector="y" endElement="integ" endConnector="u"/>)"
                        << extra_connection << R"(
    </ssd:Connections>
  </ssd:System>
  <ssd:DefaultExperiment startTime="0" stopTime="1"/>
</ssd:SystemStructureDescription>
)";
    return path;
}

struct Chain : ::testing::Test {
    std::filesystem::path ssd = write_ssd(::testing::UnitTest::GetInstance()->current_test_info()->name());
    pvatt_system* system = nullptr;
    void SetUp() override {
        const char* dirs[] = {fmu_dir};
        ASSERT_EQ(pvatt_system_open(ssd.c_str(), dirs, 1, &system), PVATT_OK) << pvatt_last_error();
    }
    void TearDown() override {
        pvatt_system_close(system);
        std::filesystem::remove(ssd);
    }
    // The column `name` of a result, by name.
    static std::vector<double> column(const pvatt_result* r, const std::string& name) {
        for (std::size_t c = 0; c < pvatt_result_columns(r); ++c) {
            if (name != pvatt_result_column_name(r, c)) continue;
            std::vector<double> out(pvatt_result_rows(r));
            EXPECT_EQ(pvatt_result_read_column(r, c, out.data(), out.size()), PVATT_OK);
            return out;
        }
        ADD_FAILURE() << "no column " << name;
        return {};
    }
};

TEST_F(Chain, ListsComponentsAndVariablesWithTypesUnitsAndChoices) {
    ASSERT_EQ(pvatt_system_component_count(system), 2u);
    EXPECT_STREQ(pvatt_system_component_name(system, 0), "gain");
    EXPECT_STREQ(pvatt_system_component_name(system, 1), "integ");
    EXPECT_EQ(pvatt_system_component_name(system, 2), nullptr);
    bool saw_u = false, saw_sign = false;
    for (std::size_t v = 0; v < pvatt_system_variable_count(system, 0); ++v) {
        pvatt_variable_info info{};
        ASSERT_EQ(pvatt_system_variable(system, 0, v, &info), PVATT_OK);
        if (std::string(info.name) == "u") {
            saw_u = true;
            EXPECT_STREQ(info.type, "Real");
            EXPECT_STREQ(info.causality, "input");
            EXPECT_STREQ(info.unit, "V");
        }
        if (std::string(info.name) == "sign") {
            saw_sign = true;
            EXPECT_STREQ(info.type, "Enumeration");
            ASSERT_EQ(info.item_count, 2u);
            EXPECT_STREQ(info.items[0], "plus");
            EXPECT_STREQ(info.items[1], "minus");
        }
    }
    EXPECT_TRUE(saw_u && saw_sign);
    pvatt_variable_info info{};
    EXPECT_EQ(pvatt_system_variable(system, 0, 999, &info), PVATT_INVALID_ARGUMENT);
    EXPECT_NE(std::string(pvatt_last_error()).find("out of range"), std::string::npos);
}

TEST_F(Chain, RunFollowsTheClosedFormWithSettingsAndChoicesByName) {
    ASSERT_EQ(pvatt_system_set(system, "gain.k", "3"), PVATT_OK);
    ASSERT_EQ(pvatt_system_set(system, "gain.sign", "minus"), PVATT_OK) << pvatt_last_error();
    char text[16];
    std::size_t needed = 0;
    ASSERT_EQ(pvatt_system_get(system, "gain.sign", text, sizeof text, &needed), PVATT_OK);
    EXPECT_STREQ(text, "minus");
    EXPECT_EQ(pvatt_system_get(system, "gain.sign", text, 3, &needed), PVATT_BUFFER_TOO_SMALL);
    EXPECT_EQ(needed, 6u);

    pvatt_run_options options;
    pvatt_run_options_init(&options);
    options.output_interval = 0.125;
    const char* columns[] = {"integ.y", "gain.y"};
    pvatt_result* r = nullptr;
    ASSERT_EQ(pvatt_run(system, &options, columns, 2, &r), PVATT_OK) << pvatt_last_error();
    ASSERT_EQ(pvatt_result_rows(r), 9u);
    ASSERT_EQ(pvatt_result_columns(r), 3u);
    const auto t = column(r, "time"), x = column(r, "integ.y"), y = column(r, "gain.y");
    for (std::size_t i = 0; i < t.size(); ++i) {
        EXPECT_DOUBLE_EQ(t[i], 0.125 * static_cast<double>(i));
        EXPECT_NEAR(x[i], 1.0 - 3.0 * t[i], 1e-6);  // x = 1 + k sign u t / tau
        EXPECT_EQ(y[i], -3.0);
    }
    // Row-major in place: row 8, column 1.
    EXPECT_EQ(pvatt_result_data(r)[8 * 3 + 1], x[8]);
    std::vector<double> small(3);
    EXPECT_EQ(pvatt_result_read_column(r, 1, small.data(), small.size()), PVATT_BUFFER_TOO_SMALL);
    pvatt_result_free(r);
}

TEST_F(Chain, RefusesUnknownNamesAndBadValuesWithAMessage) {
    EXPECT_EQ(pvatt_system_set(system, "gain.nope", "1"), PVATT_INVALID_ARGUMENT);
    EXPECT_NE(std::string(pvatt_last_error()).find("no variable 'nope'"), std::string::npos);
    EXPECT_EQ(pvatt_system_set(system, "gain.sign", "sideways"), PVATT_INVALID_ARGUMENT);
    EXPECT_NE(std::string(pvatt_last_error()).find("sideways"), std::string::npos);
    EXPECT_EQ(pvatt_system_set(system, "gain.k", "abc"), PVATT_INVALID_ARGUMENT);
    EXPECT_EQ(pvatt_system_set(nullptr, "gain.k", "1"), PVATT_INVALID_ARGUMENT);
    EXPECT_EQ(pvatt_system_set(system, "nobody.k", "1"), PVATT_INVALID_ARGUMENT);
    pvatt_run_options options;
    pvatt_run_options_init(&options);
    options.stop_time = -1.0;
    pvatt_result* r = nullptr;
    EXPECT_EQ(pvatt_run(system, &options, nullptr, 0, &r), PVATT_INVALID_ARGUMENT);
    EXPECT_EQ(r, nullptr);
    pvatt_system* none = nullptr;
    EXPECT_EQ(pvatt_system_open("/nonexistent/system.ssd", nullptr, 0, &none), PVATT_ERROR);
    EXPECT_NE(std::string(pvatt_last_error()).find("/nonexistent/system.ssd"), std::string::npos);
    EXPECT_EQ(none, nullptr);
}

TEST_F(Chain, TheLastErrorIsPerThread) {
    EXPECT_EQ(pvatt_system_set(system, "gain.nope", "1"), PVATT_INVALID_ARGUMENT);
    std::string other;
    std::thread([&] { other = pvatt_last_error(); }).join();
    EXPECT_EQ(other, "");
    EXPECT_NE(std::string(pvatt_last_error()), "");
}

TEST_F(Chain, SteppingPausesAtOutputPointsAndEqualsAWholeRun) {
    ASSERT_EQ(pvatt_system_set(system, "gain.k", "2"), PVATT_OK);
    pvatt_run_options options;
    pvatt_run_options_init(&options);
    options.output_interval = 0.1;
    const char* columns[] = {"integ.y"};
    pvatt_result* whole = nullptr;
    ASSERT_EQ(pvatt_run(system, &options, columns, 1, &whole), PVATT_OK);

    pvatt_simulation* sim = nullptr;
    ASSERT_EQ(pvatt_start(system, &options, columns, 1, &sim), PVATT_OK) << pvatt_last_error();
    EXPECT_EQ(pvatt_simulation_time(sim), 0.0);
    ASSERT_EQ(pvatt_advance_to(sim, 0.5), PVATT_OK) << pvatt_last_error();
    EXPECT_DOUBLE_EQ(pvatt_simulation_time(sim), 0.5);
    double x = 0;
    ASSERT_EQ(pvatt_simulation_get_real(sim, "integ.y", &x), PVATT_OK);
    EXPECT_NEAR(x, 2.0, 1e-6);
    EXPECT_EQ(pvatt_advance_to(sim, 0.2), PVATT_WRONG_STATE);
    ASSERT_EQ(pvatt_advance_to(sim, 1.0), PVATT_OK);
    EXPECT_TRUE(pvatt_simulation_finished(sim));
    EXPECT_EQ(pvatt_advance_to(sim, 2.0), PVATT_OK);  // at most the stop time: already there
    pvatt_result* stepped = nullptr;
    ASSERT_EQ(pvatt_simulation_result(sim, &stepped), PVATT_OK);
    ASSERT_EQ(pvatt_result_rows(stepped), pvatt_result_rows(whole));
    for (std::size_t i = 0; i < 2 * pvatt_result_rows(whole); ++i)
        EXPECT_EQ(pvatt_result_data(stepped)[i], pvatt_result_data(whole)[i]) << i;
    pvatt_result_free(stepped);
    pvatt_result_free(whole);
    pvatt_simulation_free(sim);
}

TEST_F(Chain, ASetValueTakesEffectFromThePausedInstant) {
    pvatt_run_options options;
    pvatt_run_options_init(&options);
    options.output_interval = 0.25;
    pvatt_simulation* sim = nullptr;
    ASSERT_EQ(pvatt_start(system, &options, nullptr, 0, &sim), PVATT_OK);
    ASSERT_EQ(pvatt_advance_to(sim, 0.5), PVATT_OK);
    ASSERT_EQ(pvatt_simulation_set_real(sim, "gain.u", 0.0), PVATT_OK) << pvatt_last_error();  // the open input
    ASSERT_EQ(pvatt_advance_to(sim, 1.0), PVATT_OK);
    double x = 0;
    ASSERT_EQ(pvatt_simulation_get_real(sim, "integ.y", &x), PVATT_OK);
    EXPECT_NEAR(x, 1.0 + 2.0 * 0.5, 1e-6);  // k = 2 for the first half, then nothing
    char text[32];
    ASSERT_EQ(pvatt_simulation_get_text(sim, "gain.sign", text, sizeof text, nullptr), PVATT_OK);
    EXPECT_STREQ(text, "plus");  // a choice by its name
    pvatt_simulation_free(sim);
}

TEST_F(Chain, FreeingAPausedSimulationEndsItsRun) {
    pvatt_simulation* sim = nullptr;
    ASSERT_EQ(pvatt_start(system, nullptr, nullptr, 0, &sim), PVATT_OK);
    ASSERT_EQ(pvatt_advance_to(sim, 0.3), PVATT_OK);
    pvatt_simulation_free(sim);  // must not hang nor leak its thread
}

// The callback component: y = 3 u sampled every 0.25 s in place of the gain FMU.
int triple(void* user, double t, const double* in, std::size_t n_in, double* out, std::size_t n_out) {
    auto* calls = static_cast<std::vector<double>*>(user);
    calls->push_back(t);
    if (n_in != 1 || n_out != 1) return 1;
    out[0] = 3.0 * in[0];
    return 0;
}

int failing(void*, double t, const double*, std::size_t, double*, std::size_t) {
    return t > 0.4 ? 1 : 0;
}

TEST_F(Chain, ACallbackComponentReplacesAnFmuSampledAtItsOwnRate) {
    std::vector<double> calls;
    ASSERT_EQ(pvatt_system_replace(system, "gain", 0.25, triple, &calls), PVATT_OK);
    pvatt_run_options options;
    pvatt_run_options_init(&options);
    options.output_interval = 0.5;
    const char* columns[] = {"integ.y", "gain.y"};
    pvatt_result* r = nullptr;
    ASSERT_EQ(pvatt_run(system, &options, columns, 2, &r), PVATT_OK) << pvatt_last_error();
    const auto x = column(r, "integ.y");
    ASSERT_EQ(x.size(), 3u);
    EXPECT_NEAR(x[2], 1.0 + 3.0, 1e-6);
    EXPECT_EQ(column(r, "gain.y")[1], 3.0);
    ASSERT_GE(calls.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) EXPECT_DOUBLE_EQ(calls[i], 0.25 * static_cast<double>(i));
    pvatt_result_free(r);
    // Back to the FMU.
    ASSERT_EQ(pvatt_system_replace(system, "gain", 0.0, nullptr, nullptr), PVATT_OK);
    ASSERT_EQ(pvatt_run(system, &options, columns, 2, &r), PVATT_OK);
    EXPECT_EQ(column(r, "gain.y")[1], 2.0);  // the FMU's k = 2
    pvatt_result_free(r);
}

TEST_F(Chain, AFailingCallbackStopsTheRunWithItsCodeAndKeepsTheRows) {
    ASSERT_EQ(pvatt_system_replace(system, "gain", 0.25, failing, nullptr), PVATT_OK);
    pvatt_run_options options;
    pvatt_run_options_init(&options);
    options.output_interval = 0.125;
    pvatt_result* r = nullptr;
    EXPECT_EQ(pvatt_run(system, &options, nullptr, 0, &r), PVATT_CALLBACK_FAILED);
    EXPECT_NE(std::string(pvatt_last_error()).find("gain: the callback component failed"), std::string::npos);
    ASSERT_NE(r, nullptr);
    EXPECT_EQ(pvatt_result_rows(r), 4u);  // 0 .. 0.375, the rows before the failing sample at 0.5
    pvatt_result_free(r);
    EXPECT_EQ(pvatt_system_replace(system, "nobody", 0.25, failing, nullptr), PVATT_INVALID_ARGUMENT);
    EXPECT_EQ(pvatt_system_replace(system, "gain", -1.0, failing, nullptr), PVATT_INVALID_ARGUMENT);
}

// Interrupts from the callback itself: the flag is seen at the next check, the run ends cleanly.
int interrupting(void*, double t, const double* in, std::size_t, double* out, std::size_t) {
    if (t >= 0.5) pvatt_interrupt();
    out[0] = in[0];
    return 0;
}

TEST_F(Chain, AnInterruptStopsTheRunWithTheRowsSoFar) {
    ASSERT_EQ(pvatt_system_replace(system, "gain", 0.25, interrupting, nullptr), PVATT_OK);
    pvatt_run_options options;
    pvatt_run_options_init(&options);
    options.output_interval = 0.125;
    pvatt_result* r = nullptr;
    EXPECT_EQ(pvatt_run(system, &options, nullptr, 0, &r), PVATT_INTERRUPTED);
    ASSERT_NE(r, nullptr);
    EXPECT_GE(pvatt_result_rows(r), 4u);
    EXPECT_LT(pvatt_result_rows(r), 9u);
    pvatt_result_free(r);
    // The flag is cleared when the next run starts.
    ASSERT_EQ(pvatt_system_replace(system, "gain", 0.0, nullptr, nullptr), PVATT_OK);
    EXPECT_EQ(pvatt_run(system, &options, nullptr, 0, &r), PVATT_OK);
    EXPECT_EQ(pvatt_result_rows(r), 9u);
    pvatt_result_free(r);
}

// SIGINT under pvatt_catch_sigint sets the flag instead of killing the process.
int raising(void*, double t, const double* in, std::size_t, double* out, std::size_t) {
    if (t >= 0.5) std::raise(SIGINT);
    out[0] = in[0];
    return 0;
}

TEST_F(Chain, SigintStopsTheRunWhenCaught) {
    pvatt_catch_sigint(1);
    ASSERT_EQ(pvatt_system_replace(system, "gain", 0.25, raising, nullptr), PVATT_OK);
    pvatt_result* r = nullptr;
    EXPECT_EQ(pvatt_run(system, nullptr, nullptr, 0, &r), PVATT_INTERRUPTED);
    pvatt_result_free(r);
    pvatt_catch_sigint(0);
    // The previous action is back after the call.
    struct sigaction now {};
    sigaction(SIGINT, nullptr, &now);
    EXPECT_EQ(now.sa_handler, SIG_DFL);
}

TEST(CapiFmu, ALoneFmuIsASystemOfOneComponent) {
    const auto fmu = std::filesystem::path(fmu_dir) / "test_integrator.fmu";
    pvatt_system* s = nullptr;
    ASSERT_EQ(pvatt_system_open(fmu.c_str(), nullptr, 0, &s), PVATT_OK) << pvatt_last_error();
    ASSERT_EQ(pvatt_system_component_count(s), 1u);
    EXPECT_STREQ(pvatt_system_component_name(s, 0), "test_integrator");
    ASSERT_EQ(pvatt_system_set(s, "test_integrator.u", "0.5"), PVATT_OK);
    pvatt_run_options options;
    pvatt_run_options_init(&options);
    options.stop_time = 2.0;
    options.output_interval = 1.0;
    const char* columns[] = {"test_integrator.y"};
    pvatt_result* r = nullptr;
    ASSERT_EQ(pvatt_run(s, &options, columns, 1, &r), PVATT_OK) << pvatt_last_error();
    ASSERT_EQ(pvatt_result_rows(r), 3u);
    EXPECT_NEAR(pvatt_result_data(r)[2 * 2 + 1], 1.0 + 0.5 * 2.0, 1e-6);
    pvatt_result_free(r);
    pvatt_system_close(s);
}

// ---- Issue 38: handles, re-entrancy, a paused run's sets ----

// A closed system, a freed result or simulation is refused with a status and a message (the library
// keeps a registry of open handles, as the FMI layer does): no use after free, no double free.
TEST_F(Chain, ClosedAndFreedHandlesAreRefusedNotUsed) {
    pvatt_result* r = nullptr;
    ASSERT_EQ(pvatt_run(system, nullptr, nullptr, 0, &r), PVATT_OK);
    pvatt_result_free(r);
    pvatt_result_free(r);  // the second is refused
    EXPECT_NE(std::string(pvatt_last_error()).find("pvatt_result_free: the result is not open"), std::string::npos)
        << pvatt_last_error();
    EXPECT_EQ(pvatt_result_rows(r), 0u);
    double column[4];
    EXPECT_EQ(pvatt_result_read_column(r, 0, column, 4), PVATT_INVALID_ARGUMENT);

    pvatt_simulation* sim = nullptr;
    ASSERT_EQ(pvatt_start(system, nullptr, nullptr, 0, &sim), PVATT_OK);
    pvatt_simulation_free(sim);
    EXPECT_EQ(pvatt_advance_to(sim, 0.5), PVATT_INVALID_ARGUMENT);
    EXPECT_NE(std::string(pvatt_last_error()).find("simulation is not open"), std::string::npos) << pvatt_last_error();
    pvatt_simulation_free(sim);  // refused, no double free

    pvatt_system_close(system);
    EXPECT_EQ(pvatt_system_set(system, "gain.k", "3"), PVATT_INVALID_ARGUMENT);
    EXPECT_NE(std::string(pvatt_last_error()).find("system is not open"), std::string::npos) << pvatt_last_error();
    EXPECT_EQ(pvatt_system_component_count(system), 0u);
    EXPECT_EQ(pvatt_run(system, nullptr, nullptr, 0, &r), PVATT_INVALID_ARGUMENT);
    pvatt_system_close(system);  // refused, no double free
    system = nullptr;
}

// A simulation outlives a pvatt_system_close of its system: the system is freed when the simulation is.
TEST_F(Chain, ASystemClosedUnderAPausedSimulationStaysUntilItIsFreed) {
    pvatt_simulation* sim = nullptr;
    ASSERT_EQ(pvatt_start(system, nullptr, nullptr, 0, &sim), PVATT_OK);
    ASSERT_EQ(pvatt_advance_to(sim, 0.5), PVATT_OK);
    pvatt_system_close(system);
    system = nullptr;
    ASSERT_EQ(pvatt_advance_to(sim, 1.0), PVATT_OK) << pvatt_last_error();
    double x = 0;
    ASSERT_EQ(pvatt_simulation_get_real(sim, "integ.y", &x), PVATT_OK);
    EXPECT_NEAR(x, 1.0 + 2.0 * 1.0, 1e-6);
    pvatt_simulation_free(sim);
}

// What a callback running inside a simulation's advance_to tried, and the statuses it got.
struct Reentry {
    pvatt_simulation* sim = nullptr;
    pvatt_system* system = nullptr;
    std::vector<pvatt_status> statuses;
    std::vector<std::string> messages;
    bool tried = false;
};

int reentering(void* user, double t, const double* in, std::size_t, double* out, std::size_t) {
    auto* r = static_cast<Reentry*>(user);
    out[0] = 2.0 * in[0];
    if (t < 0.5 || r->tried || !r->sim) return 0;
    r->tried = true;
    const auto note = [&](pvatt_status s) {
        r->statuses.push_back(s);
        r->messages.emplace_back(pvatt_last_error());
    };
    note(pvatt_advance_to(r->sim, 1.0));  // would wait for itself
    pvatt_simulation_free(r->sim);        // would join its own thread
    note(pvatt_simulation_time(r->sim) == pvatt_simulation_time(r->sim) ? PVATT_OK : PVATT_ERROR);  // still open
    double x = 0;
    note(pvatt_simulation_get_real(r->sim, "integ.y", &x));  // the run is mid-step
    note(pvatt_simulation_set_real(r->sim, "integ.u", 1.0));
    pvatt_simulation* nested = nullptr;
    note(pvatt_start(r->system, nullptr, nullptr, 0, &nested));
    return 0;
}

TEST_F(Chain, ReentrantCallsFromACallbackAreRefusedWithAStatus) {
    Reentry reentry;
    reentry.system = system;
    ASSERT_EQ(pvatt_system_replace(system, "gain", 0.25, reentering, &reentry), PVATT_OK);
    pvatt_run_options options;
    pvatt_run_options_init(&options);
    options.output_interval = 0.25;
    ASSERT_EQ(pvatt_start(system, &options, nullptr, 0, &reentry.sim), PVATT_OK);
    ASSERT_EQ(pvatt_advance_to(reentry.sim, 1.0), PVATT_OK) << pvatt_last_error();
    ASSERT_TRUE(reentry.tried);
    ASSERT_EQ(reentry.statuses.size(), 5u);
    EXPECT_EQ(reentry.statuses[0], PVATT_WRONG_STATE);
    EXPECT_NE(reentry.messages[0].find("pvatt_advance_to was called from inside a callback"), std::string::npos)
        << reentry.messages[0];
    EXPECT_EQ(reentry.statuses[1], PVATT_OK);  // not freed: its time still reads
    EXPECT_EQ(reentry.statuses[2], PVATT_WRONG_STATE);
    EXPECT_NE(reentry.messages[2].find("the simulation is running"), std::string::npos) << reentry.messages[2];
    EXPECT_EQ(reentry.statuses[3], PVATT_WRONG_STATE);
    EXPECT_EQ(reentry.statuses[4], PVATT_WRONG_STATE);
    // The run went on to its end, computing what it would have.
    double x = 0;
    ASSERT_EQ(pvatt_simulation_get_real(reentry.sim, "integ.y", &x), PVATT_OK);
    EXPECT_NEAR(x, 1.0 + 2.0 * 1.0, 1e-6);
    pvatt_simulation_free(reentry.sim);
}

// pvatt_system_close from a callback during pvatt_run: the run ends normally, the system is freed after.
int closing(void* user, double t, const double* in, std::size_t, double* out, std::size_t) {
    auto** system = static_cast<pvatt_system**>(user);
    out[0] = 2.0 * in[0];
    if (t >= 0.5 && *system) {
        pvatt_system_close(*system);
        *system = nullptr;
    }
    return 0;
}

TEST_F(Chain, AClosingCallbackLetsTheRunFinish) {
    pvatt_system* handle = system;
    ASSERT_EQ(pvatt_system_replace(system, "gain", 0.25, closing, &handle), PVATT_OK);
    system = nullptr;  // the callback closes it
    pvatt_result* r = nullptr;
    ASSERT_EQ(pvatt_run(handle, nullptr, nullptr, 0, &r), PVATT_OK) << pvatt_last_error();
    EXPECT_EQ(handle, nullptr);
    EXPECT_GT(pvatt_result_rows(r), 2u);
    pvatt_result_free(r);
}

// A set a paused run cannot take is refused before the FMU sees it: the run can still advance (before,
// the FMU went to its error state and every later advance failed).
TEST_F(Chain, ARefusedSetLeavesAPausedRunAbleToAdvance) {
    pvatt_run_options options;
    pvatt_run_options_init(&options);
    options.output_interval = 0.25;
    pvatt_simulation* sim = nullptr;
    ASSERT_EQ(pvatt_start(system, &options, nullptr, 0, &sim), PVATT_OK);
    ASSERT_EQ(pvatt_advance_to(sim, 0.5), PVATT_OK);
    const struct {
        const char* name;
        const char* value;
        const char* expected;
    } refused[] = {
        {"integ.y", "5", "integ.y is a continuous output: while a run is paused only inputs and tunable parameters"},
        {"integ.tau", "2", "integ.tau is a fixed parameter"},
        // Tunable, but gain runs as Model Exchange: Continuous-Time Mode takes only continuous inputs.
        {"gain.k", "3", "gain.k is a tunable parameter of gain, which runs as Model Exchange"},
        {"gain.u", "nan", "gain.u: nan is not a finite number"},
        {"gain.u", "inf", "gain.u: inf is not a finite number"},
        {"gain.u", "abc", "is not a number"},
    };
    for (const auto& c : refused) {
        EXPECT_EQ(pvatt_simulation_set_text(sim, c.name, c.value), PVATT_INVALID_ARGUMENT) << c.name;
        EXPECT_NE(std::string(pvatt_last_error()).find(c.expected), std::string::npos) << pvatt_last_error();
    }
    EXPECT_EQ(pvatt_simulation_set_real(sim, "gain.u", NAN), PVATT_INVALID_ARGUMENT);
    ASSERT_EQ(pvatt_advance_to(sim, 1.0), PVATT_OK) << pvatt_last_error();
    double x = 0;
    ASSERT_EQ(pvatt_simulation_get_real(sim, "integ.y", &x), PVATT_OK);
    EXPECT_NEAR(x, 1.0 + 2.0 * 1.0, 1e-6);  // nothing of the refused sets took effect
    pvatt_simulation_free(sim);
}

}  // namespace

namespace {

// The chain with the gain's k a system parameter (gain_k = 2): x = 1 + gain_k t / tau.
std::filesystem::path write_scenario(const std::string& dir_tag) {
    const auto dir =
        std::filesystem::temp_directory_path() / ("pvatt_capi_scenario_" + std::to_string(::getpid()) + dir_tag);
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "chain.ssd") << R"(<?xml version="1.0" encoding="UTF-8"?>
<ssd:SystemStructureDescription xmlns:ssd="http://ssp-standard.org/SSP1/SystemStructureDescription"
    xmlns:ssc="http://ssp-standard.org/SSP1/SystemStructureCommon"
    xmlns:ssv="http://ssp-standard.org/SSP1/SystemStructureParameterValues" version="1.0" name="chain">
  <ssd:System name="chain">
    <ssd:Connectors><ssd:Connector name="gain_k" kind="parameter"><ssc:Real unit="1"/></ssd:Connector></ssd:Connectors>
    <ssd:ParameterBindings><ssd:ParameterBinding><ssd:ParameterValues>
      <ssv:ParameterSet version="1.0" name="s"><ssv:Parameters>
        <ssv:Parameter name="gain_k"><ssv:Real value="2"/></ssv:Parameter>
      </ssv:Parameters></ssv:ParameterSet>
    </ssd:ParameterValues></ssd:ParameterBinding></ssd:ParameterBindings>
    <ssd:Elements>
      <ssd:Component name="gain" source="test_gain.fmu"/>
      <ssd:Component name="integ" source="test_integrator.fmu"/>
    </ssd:Elements>
    <ssd:Connections>
      <ssd:Connection startElement="gain" startConnector="y" endElement="integ" endConnector="u"/>
      <ssd:Connection startConnector="gain_k" endElement="gain" endConnector="k"/>
    </ssd:Connections>
  </ssd:System>
  <ssd:DefaultExperiment startTime="0" stopTime="1"/>
</ssd:SystemStructureDescription>
)";
    std::ofstream(dir / "five.ssv") << R"(<?xml version="1.0" encoding="UTF-8"?>
<ssv:ParameterSet xmlns:ssv="http://ssp-standard.org/SSP1/SystemStructureParameterValues" version="1.0" name="p">
  <ssv:Parameters>
    <ssv:Parameter name="gain_k"><ssv:Real value="5"/></ssv:Parameter>
    <ssv:Parameter name="integ.tau"><ssv:Real value="2"/></ssv:Parameter>
  </ssv:Parameters>
</ssv:ParameterSet>
)";
    std::ofstream(dir / "bad.ssv") << R"(<?xml version="1.0" encoding="UTF-8"?>
<ssv:ParameterSet xmlns:ssv="http://ssp-standard.org/SSP1/SystemStructureParameterValues" version="1.0" name="p">
  <ssv:Parameters>
    <ssv:Parameter name="integ.tau"><ssv:Real value="3"/></ssv:Parameter>
    <ssv:Parameter name="gain_kk"><ssv:Real value="5"/></ssv:Parameter>
  </ssv:Parameters>
</ssv:ParameterSet>
)";
    return dir;
}

double final_x(pvatt_system* system) {
    pvatt_run_options options;
    pvatt_run_options_init(&options);
    options.output_interval = 0.5;
    const char* columns[] = {"integ.y"};
    pvatt_result* r = nullptr;
    EXPECT_EQ(pvatt_run(system, &options, columns, 1, &r), PVATT_OK) << pvatt_last_error();
    const double x = pvatt_result_data(r)[(pvatt_result_rows(r) - 1) * 2 + 1];
    pvatt_result_free(r);
    return x;
}

}  // namespace

TEST(CapiSystemParameters, SetByNameLoadedFromAParameterFileAndListed) {
    const auto dir = write_scenario("a");
    const char* dirs[] = {fmu_dir};
    pvatt_system* system = nullptr;
    ASSERT_EQ(pvatt_system_open((dir / "chain.ssd").c_str(), dirs, 1, &system), PVATT_OK) << pvatt_last_error();
    ASSERT_EQ(pvatt_system_parameter_count(system), 1u);
    EXPECT_STREQ(pvatt_system_parameter_name(system, 0), "gain_k");
    EXPECT_EQ(pvatt_system_parameter_name(system, 1), nullptr);
    char text[16];
    ASSERT_EQ(pvatt_system_get(system, "gain_k", text, sizeof text, nullptr), PVATT_OK) << pvatt_last_error();
    EXPECT_STREQ(text, "2");
    EXPECT_NEAR(final_x(system), 1.0 + 2.0, 1e-6);  // tau = 1
    ASSERT_EQ(pvatt_system_set(system, "gain_k", "3"), PVATT_OK) << pvatt_last_error();
    EXPECT_NEAR(final_x(system), 1.0 + 3.0, 1e-6);
    EXPECT_EQ(pvatt_system_set(system, "gain_k", "fast"), PVATT_INVALID_ARGUMENT);
    ASSERT_EQ(pvatt_system_load_parameters(system, (dir / "five.ssv").c_str()), PVATT_OK) << pvatt_last_error();
    ASSERT_EQ(pvatt_system_get(system, "gain_k", text, sizeof text, nullptr), PVATT_OK);
    EXPECT_STREQ(text, "5");
    EXPECT_NEAR(final_x(system), 1.0 + 5.0 / 2.0, 1e-6);
    // A bad file is refused with its file, line and name, and changes nothing (tau stays 2).
    EXPECT_EQ(pvatt_system_load_parameters(system, (dir / "bad.ssv").c_str()), PVATT_INVALID_ARGUMENT);
    const std::string error = pvatt_last_error();
    EXPECT_NE(error.find((dir / "bad.ssv").string() + ":5: "), std::string::npos) << error;
    EXPECT_NE(error.find("gain_kk"), std::string::npos) << error;
    EXPECT_NEAR(final_x(system), 1.0 + 5.0 / 2.0, 1e-6);
    EXPECT_EQ(pvatt_system_load_parameters(system, (dir / "none.ssv").c_str()), PVATT_INVALID_ARGUMENT);
    pvatt_system_close(system);
    std::filesystem::remove_all(dir);
}

// A campaign's aims judged from a table written here (no run): JSON and the command's lines, the caller's buffer
// sized as for pvatt_system_get, and a missing argument or a table of another spec refused with a message.
TEST(CapiCampaign, AimsOfAWrittenTableAsJsonAndAsTheCommandsLines) {
    const auto dir = std::filesystem::temp_directory_path() / ("pvatt_capi_aims_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const auto spec = dir / "spec.toml", table = dir / "results.csv";
    std::ofstream(spec)
        << "system = \"never_opened.ssd\"\nruns = 3\nseed = 1\n[[metric]]\nname = \"x\"\nkind = \"column\"\n"
           "column = \"gain.y\"\nstats = [\"final\"]\n[[aim]]\ncolumn = \"x.final\"\nbelow = 2\n";
    std::ofstream(table) << "run,x.final,wall_time,status,message\n0,1.5,1,ok,\n1,2.5,1,ok,\n2,,1,failed,boom\n";
    std::size_t needed = 0;
    ASSERT_EQ(pvatt_campaign_aims(spec.c_str(), table.c_str(), 0, nullptr, 0, &needed), PVATT_BUFFER_TOO_SMALL);
    std::string json(needed, '\0');
    ASSERT_EQ(pvatt_campaign_aims(spec.c_str(), table.c_str(), 0, json.data(), json.size(), nullptr), PVATT_OK)
        << pvatt_last_error();
    json.resize(needed - 1);
    EXPECT_EQ(json,
              "{\"finished\": 2, \"failed\": 1, \"every\": 1, \"missing_any\": [1], \"aims\": [{\"column\": "
              "\"x.final\", \"condition\": \"x.final < 2\", \"kind\": \"below\", \"low\": null, \"high\": 2, "
              "\"skip_empty\": false, \"met\": 1, \"missed\": 1, \"not_judged\": 0, \"missing_runs\": [1]}], "
              "\"by_category\": []}");
    char text[512];
    ASSERT_EQ(pvatt_campaign_aims(spec.c_str(), table.c_str(), 1, text, sizeof text, nullptr), PVATT_OK)
        << pvatt_last_error();
    EXPECT_STREQ(text,
                 "aims, per run (2 finished runs, 1 failed, not judged):\n  x.final < 2: 1 met, 1 missed (run 1)\n"
                 "  every aim: 1 of 2 runs\n");

    EXPECT_EQ(pvatt_campaign_aims(nullptr, table.c_str(), 0, text, sizeof text, nullptr), PVATT_INVALID_ARGUMENT);
    std::ofstream(table, std::ios::trunc) << "run,y.final,wall_time,status,message\n0,1,1,ok,\n";
    EXPECT_EQ(pvatt_campaign_aims(spec.c_str(), table.c_str(), 0, text, sizeof text, nullptr), PVATT_ERROR);
    EXPECT_NE(std::string(pvatt_last_error()).find("no column 'x.final'"), std::string::npos) << pvatt_last_error();
    std::filesystem::remove_all(dir);
}
