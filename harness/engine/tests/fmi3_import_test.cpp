// FMI 3.0 import: the master runs fmi3_probe (an FMU written by hand against the FMI 3.0 C API,
// tests/fmus3/fmi3_probe.c) in Model Exchange and in Co-Simulation with and without event mode, with
// its arrays, Float32, integer, Enumeration, Binary and String variables, beside an FMI 2.0 FMU. The
// expected values are the closed forms worked out here (exp(-k t), the bouncing ball's parabolas, the
// counter's ticks), not outputs of the code under test.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <tuple>

#include "engine/cosim_error.hpp"
#include "engine/execution.hpp"
#include "engine/fmi3_instance.hpp"
#include "engine/ssp_archive.hpp"
#include "engine/system.hpp"
#include "engine/system_description.hpp"
#include "fmi_loader/loader_error.hpp"

namespace cosim {
namespace {

const std::filesystem::path fmu_dir = COSIM_TEST_FMU_DIR;

struct Ssd {
    std::filesystem::path path;
    explicit Ssd(const std::string& elements, const std::string& connections = "") {
        path = std::filesystem::temp_directory_path() /
               ("cosim_fmi3_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + ".ssd");
        std::ofstream(path) << R"(<?xml version="1.0" encoding="UTF-8"?>
<ssd:SystemStructureDescription xmlns:ssd="http://ssp-standard.org/SSP1/SystemStructureDescription"
    version="1.0" name="fmi3">
  <ssd:System name="fmi3"><ssd:Elements>)"
                            << elements << "</ssd:Elements><ssd:Connections>" << connections
                            << R"(</ssd:Connections></ssd:System>
  <ssd:DefaultExperiment startTime="0" stopTime="1.5"/>
</ssd:SystemStructureDescription>
)";
    }
    ~Ssd() { std::filesystem::remove(path); }
};

std::string component(const std::string& name, const std::string& fmu) {
    return "<ssd:Component name=\"" + name + "\" source=\"" + fmu + ".fmu\"/>";
}
std::string connect(const std::string& a, const std::string& ac, const std::string& b, const std::string& bc) {
    return "<ssd:Connection startElement=\"" + a + "\" startConnector=\"" + ac + "\" endElement=\"" + b +
           "\" endConnector=\"" + bc + "\"/>";
}

// The ball of fmi3_probe: dropped from h = 1 m at rest, g = 9.81, bounces with v := -0.7 v.
double ball_height(double t) {
    const double g = 9.81, e = 0.7;
    double t0 = 0.0, h0 = 1.0, v0 = 0.0;
    for (;;) {
        const double impact = t0 + (v0 + std::sqrt(v0 * v0 + 2 * g * h0)) / g;
        if (t <= impact) return h0 + v0 * (t - t0) - 0.5 * g * (t - t0) * (t - t0);
        v0 = e * g * (impact - t0) - e * v0;  // speed at impact, reversed and reduced
        t0 = impact;
        h0 = 0.0;
    }
}

// Samples named variables of one component as text (any type) and as numbers.
struct Recorder : Observer {
    std::size_t component;
    std::vector<const fmi_loader::ScalarVariable*> vars;
    std::vector<double> times;
    std::vector<std::vector<std::string>> rows;
    Recorder(System& s, const std::string& comp, const std::vector<std::string>& names)
        : component(s.component_index(comp)) {
        for (const auto& n : names) {
            const auto* v = s.components()[component].description().find_variable(n);
            if (!v) throw CosimError("no variable " + n);
            vars.push_back(v);
        }
    }
    void sample(double t, System& s) override {
        times.push_back(t);
        std::vector<std::string> row;
        for (const auto* v : vars) row.push_back(s.components()[component].instance->get_as_text(*v));
        rows.push_back(std::move(row));
    }
    double at(std::size_t row, std::size_t column) const { return std::stod(rows[row][column]); }
};

RunStatistics run(System& system, Observer& recorder, double stop, double interval) {
    ExecutionOptions ex;
    ex.stop_time = stop;
    ex.output_interval = interval;
    ex.relative_tolerance = 1e-10;
    return Execution(system, ex).run({&recorder});
}

SystemOptions options(std::vector<std::string> cs = {}, bool event_mode = true) {
    SystemOptions o;
    o.fmu_dirs = {fmu_dir};
    o.co_simulation = std::move(cs);
    o.fmi3_event_mode = event_mode;
    return o;
}

// The array state, the ball and the counter against their closed forms, in one interface.
void expect_closed_form(const SystemOptions& o, double tolerance) {
    Ssd ssd(component("p", "fmi3_probe"));
    System system(read_system_description(ssd.path), o);
    Recorder rec(system, "p", {"x[1]", "x[2]", "x[3]", "h", "counter"});
    run(system, rec, 1.5, 0.1);
    ASSERT_EQ(rec.times.size(), 16u);
    for (std::size_t i = 0; i < rec.times.size(); ++i) {
        const double t = rec.times[i];
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(rec.at(i, j), std::exp(-(j + 1) * t), tolerance) << "x at t = " << t;
        EXPECT_NEAR(rec.at(i, 3), ball_height(t), tolerance) << "h at t = " << t;
        // A tick at every multiple of 0.25 s (samples at a tick itself are left out: before or after it).
        if (std::abs(t / 0.25 - std::round(t / 0.25)) > 1e-6) {
            EXPECT_EQ(rec.at(i, 4), std::floor(t / 0.25)) << "counter at t = " << t;
        }
    }
}

}  // namespace

TEST(CosimFmi3, ModelExchangeMatchesTheClosedForms) {
    expect_closed_form(options(), 1e-6);
}

TEST(CosimFmi3, CoSimulationWithEventModeMatchesTheClosedForms) {
    expect_closed_form(options({"p"}, true), 1e-12);
}

TEST(CosimFmi3, CoSimulationWithoutEventModeMatchesTheClosedForms) {
    expect_closed_form(options({"p"}, false), 1e-12);
}

TEST(CosimFmi3, ModelExchangeLocatesTheBouncesAndTicks) {
    Ssd ssd(component("p", "fmi3_probe"));
    System system(read_system_description(ssd.path), options());
    Recorder rec(system, "p", {"h"});
    const auto stats = run(system, rec, 1.5, 0.5);
    // Impacts at 0.4515 s and 1.0837 s (the next at 1.526 s is after the stop); ticks at 0.25 s steps.
    EXPECT_EQ(stats.state_events, 2);
    EXPECT_GE(stats.time_events, 5);
}

// Every FMI 3.0 type the probe has, through connections between two instances: Float32 y32 = 2 u32,
// UInt64 into Int16 (u64 = i16 + 10), Binary as hexadecimal text (bin_out = bin_in reversed), an
// Enumeration and a String set by name.
void expect_types_travel(const SystemOptions& base) {
    Ssd ssd(component("a", "fmi3_probe") + component("b", "fmi3_probe"),
            connect("a", "y32", "b", "u32") + connect("a", "u64", "b", "i16") + connect("a", "bin_out", "b", "bin_in"));
    SystemOptions o = base;
    o.settings = {"a.u32=1.5", "a.i16=7", "a.bin_in=0102ab", "a.label=hello", "a.pace=double"};
    System system(read_system_description(ssd.path), o);
    Recorder rec_a(system, "a", {"label_out", "counter"});
    Recorder rec_b(system, "b", {"y32", "u64", "bin_out", "bin_in"});
    run(system, rec_b, 0.6, 0.3);
    EXPECT_EQ(rec_b.at(2, 0), 6.0);         // 2 * (2 * 1.5)
    EXPECT_EQ(rec_b.at(2, 1), 27.0);        // (7 + 10) + 10
    EXPECT_EQ(rec_b.rows[2][2], "0102ab");  // reversed twice
    EXPECT_EQ(rec_b.rows[2][3], "ab0201");
    const auto& a = system.components()[system.component_index("a")];
    EXPECT_EQ(a.instance->get_as_text(*a.description().find_variable("label_out")), "hello!");
    EXPECT_EQ(a.instance->get_as_text(*a.description().find_variable("counter")), "4");  // 2 ticks of 2
}

TEST(CosimFmi3, EveryTypeTravelsInModelExchange) {
    expect_types_travel(options());
}

TEST(CosimFmi3, EveryTypeTravelsInCoSimulationWithEventMode) {
    // The probe refuses a discrete input set in Step Mode: the instance must set i16 and bin_in in Event Mode.
    expect_types_travel(options({"a", "b"}, true));
}

TEST(CosimFmi3, EveryTypeTravelsInCoSimulationWithoutEventMode) {
    expect_types_travel(options({"a", "b"}, false));
}

// An array element connected alone, into an FMI 2.0 component: gain.y = 2 x[2] = 2 exp(-2 t).
TEST(CosimFmi3, ArrayElementFeedsAnFmi2Component) {
    Ssd ssd(component("p", "fmi3_probe") + component("gain", "test_gain"), connect("p", "x[2]", "gain", "u"));
    System system(read_system_description(ssd.path), options());
    Recorder rec(system, "gain", {"y"});
    run(system, rec, 1.0, 0.25);
    for (std::size_t i = 0; i < rec.times.size(); ++i)
        EXPECT_NEAR(rec.at(i, 0), 2 * std::exp(-2 * rec.times[i]), 1e-6) << "t = " << rec.times[i];
}

// Arrays connected whole (x -> w: each element to its own) and one element into another array's.
TEST(CosimFmi3, ArraysConnectWholeOrByElement) {
    const auto wsum = [](const std::string& from, const std::string& to) {
        Ssd ssd(component("a", "fmi3_probe") + component("b", "fmi3_probe"), connect("a", from, "b", to));
        System system(read_system_description(ssd.path), options());
        Recorder rec(system, "b", {"wsum"});
        run(system, rec, 1.0, 0.5);
        std::vector<std::pair<double, double>> samples;
        for (std::size_t i = 0; i < rec.times.size(); ++i) samples.emplace_back(rec.times[i], rec.at(i, 0));
        return samples;
    };
    const auto whole = wsum("x", "w");
    ASSERT_EQ(whole.size(), 3u);
    for (const auto& [t, y] : whole)
        EXPECT_NEAR(y, std::exp(-t) + 2 * std::exp(-2 * t) + 3 * std::exp(-3 * t), 1e-6) << "t = " << t;
    for (const auto& [t, y] : wsum("x[3]", "w[2]")) EXPECT_NEAR(y, 2 * std::exp(-3 * t), 1e-6) << "t = " << t;
    EXPECT_THROW(wsum("x", "u32"), CosimError);  // 3 elements to 1
}

// An element of an array parameter set before initialization (where FMI 3.0 allows no get: the other
// elements keep their start values): k = (1, 5, 3) makes x[2] = exp(-5 t).
TEST(CosimFmi3, ArrayParameterElementIsSetBeforeInitialization) {
    Ssd ssd(component("p", "fmi3_probe"));
    SystemOptions o = options();
    o.settings = {"p.k[2]=5"};
    System system(read_system_description(ssd.path), o);
    Recorder rec(system, "p", {"x[1]", "x[2]", "x[3]"});
    run(system, rec, 1.0, 0.5);
    for (std::size_t i = 0; i < rec.times.size(); ++i) {
        const double t = rec.times[i];
        EXPECT_NEAR(rec.at(i, 0), std::exp(-t), 1e-6);
        EXPECT_NEAR(rec.at(i, 1), std::exp(-5 * t), 1e-6);
        EXPECT_NEAR(rec.at(i, 2), std::exp(-3 * t), 1e-6);
    }
}

// FMU state: back to a snapshot and on again gives the same values bit for bit, also through the
// serialized form.
TEST(CosimFmi3, FmuStateReturnsToTheSnapshot) {
    fmi_loader::Fmu fmu(fmu_dir / "fmi3_probe.fmu");
    Fmi3Instance p(fmu, fmi_loader::FmuKind::co_simulation, "p");
    const auto vr = p.description().find_variable("h")->value_reference;
    p.setup_experiment(0.0, 2.0, std::nullopt);
    p.enter_initialization_mode();
    p.exit_initialization_mode();
    p.do_step(0.0, 0.3);
    auto snapshot = p.get_state();
    const auto bytes = p.serialize(snapshot);
    p.do_step(0.3, 0.7);
    const double first = p.get_real(vr);
    EXPECT_NEAR(first, ball_height(1.0), 1e-12);
    p.set_state(snapshot);
    p.do_step(0.3, 0.7);
    EXPECT_EQ(p.get_real(vr), first);
    auto restored = p.deserialize(bytes);
    p.set_state(restored);
    p.do_step(0.3, 0.7);
    EXPECT_EQ(p.get_real(vr), first);
    p.free_state(snapshot);
    p.free_state(restored);
}

// The runtime's own test blocks (harness/cosim/tests/fmus) as FMI 3.0 archives (test_fmus/fmi3/) run
// bit for bit as their FMI 2.0 archives: the ball's state and time events, and an FMI 3.0 integrator in
// a feedback loop with an FMI 2.0 gain (x' = -0.5 x: exp(-0.5 t)).
TEST(CosimFmi3, RuntimeBlocksRunAsTheirFmi2ArchivesAndMixWithThem) {
    const auto ball = [](const std::vector<std::filesystem::path>& dirs) {
        Ssd ssd(component("ball", "test_ball"));
        SystemOptions o = options();
        o.fmu_dirs = dirs;
        System system(read_system_description(ssd.path), o);
        Recorder rec(system, "ball", {"h", "v", "bounces", "ticks"});
        const auto stats = run(system, rec, 1.5, 0.05);
        return std::tuple{rec.rows, stats.state_events, stats.time_events};
    };
    const auto fmi2 = ball({fmu_dir});
    const auto fmi3 = ball({fmu_dir / "fmi3"});
    EXPECT_EQ(std::get<0>(fmi3), std::get<0>(fmi2));
    EXPECT_EQ(std::get<1>(fmi3), std::get<1>(fmi2));
    EXPECT_EQ(std::get<2>(fmi3), std::get<2>(fmi2));
    EXPECT_EQ(std::get<1>(fmi2), 2);  // impacts at 0.4515 s and 1.174 s (e = 0.8)

    const auto loop = [](const std::vector<std::filesystem::path>& dirs) {
        Ssd ssd(component("int", "test_integrator") + component("gain", "test_gain"),
                connect("int", "y", "gain", "u") + connect("gain", "y", "int", "u"));
        SystemOptions o = options();
        o.fmu_dirs = dirs;
        o.settings = {"gain.k=-0.5"};
        System system(read_system_description(ssd.path), o);
        Recorder rec(system, "int", {"y"});
        run(system, rec, 2.0, 0.5);
        return rec.rows;
    };
    // Only the integrator's FMI 3.0 archive in the first folder searched: it runs beside the FMI 2.0 gain.
    const auto mixed_dir = std::filesystem::temp_directory_path() / "cosim_fmi3_mixed";
    std::filesystem::create_directories(mixed_dir);
    std::filesystem::copy_file(fmu_dir / "fmi3" / "test_integrator.fmu", mixed_dir / "test_integrator.fmu",
                               std::filesystem::copy_options::overwrite_existing);
    const auto mixed = loop({mixed_dir, fmu_dir});
    std::filesystem::remove_all(mixed_dir);
    EXPECT_EQ(mixed, loop({fmu_dir}));
    ASSERT_EQ(mixed.size(), 5u);
    for (std::size_t i = 0; i < mixed.size(); ++i) EXPECT_NEAR(std::stod(mixed[i][0]), std::exp(-0.25 * i), 1e-6);
}

// The .ssp packer takes FMI 3.0 components (an Enumeration bound by name, an array element connected)
// and the packed system runs as the .ssd does, value for value.
TEST(CosimFmi3, PackedSystemWithFmi3ComponentsRunsAsTheSsd) {
    Ssd ssd(
        "<ssd:Component name=\"p\" source=\"fmi3_probe.fmu\"><ssd:ParameterBindings><ssd:ParameterBinding>"
        "<ssd:ParameterValues><ssv:ParameterSet xmlns:ssv=\"http://ssp-standard.org/SSP1/"
        "SystemStructureParameterValues\" version=\"1.0\" name=\"p\"><ssv:Parameters>"
        "<ssv:Parameter name=\"pace\"><ssv:Enumeration value=\"double\"/></ssv:Parameter>"
        "</ssv:Parameters></ssv:ParameterSet></ssd:ParameterValues></ssd:ParameterBinding>"
        "</ssd:ParameterBindings></ssd:Component>" +
            component("gain", "test_gain"),
        connect("p", "x[1]", "gain", "u"));
    const auto ssp = std::filesystem::temp_directory_path() / "cosim_fmi3_packed.ssp";
    std::ostringstream log;
    pack_system(ssd.path, ssp, PackOptions{{fmu_dir}, 0.01}, log);
    const auto rows = [](const std::filesystem::path& file) {
        System system(read_system_description(file), options());
        Recorder rec(system, "p", {"counter", "x[1]"});
        run(system, rec, 1.1, 0.55);
        return rec.rows;
    };
    const auto packed = rows(ssp);
    std::filesystem::remove(ssp);
    EXPECT_EQ(packed, rows(ssd.path));
    EXPECT_EQ(packed.back()[0], "8");  // four ticks of two (pace = double from the binding)
}

TEST(CosimFmi3, UnsupportedFeaturesAreRefusedByName) {
    const auto refusal = [](const std::string& interfaces, const std::string& variables) {
        const auto md = fmi_loader::parse_model_description(
            "<fmiModelDescription fmiVersion=\"3.0\" modelName=\"m\" instantiationToken=\"t\">" + interfaces +
            "<ModelVariables>" + variables + "</ModelVariables></fmiModelDescription>");
        try {
            refuse_unsupported_fmi3(md, "m");
        } catch (const fmi_loader::LoaderError& e) {
            // A refused FMU, as a bad archive is: `cosim` exits 3 for it (README, Errors), not 1.
            EXPECT_EQ(e.code(), fmi_loader::LoaderErrc::unsupported);
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(refusal("<ScheduledExecution modelIdentifier=\"m\"/>", "").find("Scheduled Execution"),
              std::string::npos);
    EXPECT_NE(refusal("<CoSimulation modelIdentifier=\"m\"/>",
                      "<Clock name=\"c\" valueReference=\"1\" causality=\"input\" intervalVariability=\"triggered\"/>")
                  .find("clocks are not supported"),
              std::string::npos);
    EXPECT_NE(
        refusal("<CoSimulation modelIdentifier=\"m\"/>",
                "<String name=\"s\" valueReference=\"1\" causality=\"parameter\"><Dimension start=\"2\"/></String>")
            .find("arrays of String and Binary"),
        std::string::npos);
    EXPECT_EQ(refusal("<CoSimulation modelIdentifier=\"m\"/>", ""), "");
}

}  // namespace cosim
