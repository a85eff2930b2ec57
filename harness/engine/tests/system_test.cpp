// The master on small systems with closed-form answers, and its refusals of broken systems.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "engine/cosim_error.hpp"
#include "engine/execution.hpp"
#include "engine/system.hpp"
#include "engine/system_description.hpp"

namespace cosim {
namespace {

const std::filesystem::path fmu_dir = COSIM_TEST_FMU_DIR;

// Writes an .ssd with the given components ("name=fmu" pairs), connections and parameters.
struct SsdFile {
    std::filesystem::path path;
    explicit SsdFile(const std::string& body) {
        path = std::filesystem::temp_directory_path() /
               ("cosim_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".ssd");
        std::ofstream(path) << R"(<?xml version="1.0" encoding="UTF-8"?>
<ssd:SystemStructureDescription xmlns:ssd="http://ssp-standard.org/SSP1/SystemStructureDescription"
    xmlns:ssc="http://ssp-standard.org/SSP1/SystemStructureCommon"
    xmlns:ssv="http://ssp-standard.org/SSP1/SystemStructureParameterValues" version="1.0" name="test">
  <ssd:System name="test">)" << body
                            << R"(  </ssd:System>
  <ssd:DefaultExperiment startTime="0" stopTime="1"/>
</ssd:SystemStructureDescription>
)";
    }
    ~SsdFile() { std::filesystem::remove(path); }
};

std::string component(const std::string& name, const std::string& fmu, const std::string& params = "") {
    std::string s = "<ssd:Component name=\"" + name + "\" source=\"" + fmu + ".fmu\">";
    if (!params.empty())
        s +=
            "<ssd:ParameterBindings><ssd:ParameterBinding><ssd:ParameterValues><ssv:ParameterSet version=\"1.0\" "
            "name=\"p\"><ssv:Parameters>" +
            params +
            "</ssv:Parameters></ssv:ParameterSet></ssd:ParameterValues></ssd:ParameterBinding></ssd:ParameterBindings>";
    return s + "</ssd:Component>\n";
}
std::string real(const std::string& name, double value) {
    return "<ssv:Parameter name=\"" + name + "\"><ssv:Real value=\"" + std::to_string(value) + "\"/></ssv:Parameter>";
}
std::string connect(const std::string& a, const std::string& ac, const std::string& b, const std::string& bc) {
    return "<ssd:Connection startElement=\"" + a + "\" startConnector=\"" + ac + "\" endElement=\"" + b +
           "\" endConnector=\"" + bc + "\"/>\n";
}
std::string system_body(const std::string& elements, const std::string& connections = "") {
    return "<ssd:Elements>" + elements + "</ssd:Elements><ssd:Connections>" + connections + "</ssd:Connections>";
}

// Records one variable at every sample.
struct Probe : Observer {
    std::size_t component;
    fmi2ValueReference vr;
    std::vector<std::pair<double, double>> samples;
    Probe(System& s, const std::string& comp, const std::string& var)
        : component(s.component_index(comp)),
          vr(s.components()[component].description().find_variable(var)->value_reference) {}
    void sample(double t, System& s) override {
        samples.emplace_back(t, s.components()[component].instance->get_real(vr));
    }
};

SystemOptions options(std::vector<std::string> cs = {}) {
    SystemOptions o;
    o.fmu_dirs = {fmu_dir};
    o.co_simulation = std::move(cs);
    return o;
}

RunStatistics run(System& system, Observer& probe, double stop, double interval, double tol = 1e-9) {
    ExecutionOptions ex;
    ex.stop_time = stop;
    ex.output_interval = interval;
    ex.relative_tolerance = tol;
    return Execution(system, ex).run({&probe});
}

// A choice (an FMI Enumeration) is set by item name from an ssv:Enumeration or ssv:String binding, by
// number from an ssv:Integer one, and by name from --set; anything else is refused with the items named.
TEST(CosimSystem, ChoiceIsSetByItemNameOrNumberFromBindingsAndSettings) {
    auto gain_output = [](const std::string& binding, std::vector<std::string> settings = {}) {
        const std::string params =
            binding.empty() ? "" : "<ssv:Parameter name=\"sign\">" + binding + "</ssv:Parameter>";
        SsdFile ssd(system_body(component("gain", "test_gain", params)));
        SystemOptions o = options();
        o.settings = std::move(settings);
        System system(read_system_description(ssd.path), o);
        Probe probe(system, "gain", "y");
        run(system, probe, 0.5, 0.5);
        return probe.samples.back().second;  // y = sign k u with k = 2, u = 1
    };
    EXPECT_EQ(gain_output(""), 2.0);
    EXPECT_EQ(gain_output("<ssv:Enumeration value=\"minus\"/>"), -2.0);
    EXPECT_EQ(gain_output("<ssv:String value=\"minus\"/>"), -2.0);
    EXPECT_EQ(gain_output("<ssv:Integer value=\"2\"/>"), -2.0);
    EXPECT_EQ(gain_output("", {"gain.sign=minus"}), -2.0);
    EXPECT_EQ(gain_output("<ssv:Enumeration value=\"minus\"/>", {"gain.sign=plus"}), 2.0);  // --set last
    EXPECT_THROW(gain_output("<ssv:Enumeration value=\"zero\"/>"), CosimError);
    EXPECT_THROW(gain_output("<ssv:Integer value=\"3\"/>"), CosimError);
    EXPECT_THROW(gain_output("<ssv:Real value=\"2\"/>"), CosimError);  // the binding's type is checked
    EXPECT_THROW(gain_output("", {"gain.sign"}), CosimError);          // not component.variable=value
}

TEST(CosimSystem, FeedbackLoopThroughAnIntegratorIsAnExponential) {
    // integrator.x' = gain.y / tau = k x / tau: x(t) = exp(k t / tau) with k = -0.5, tau = 1.
    SsdFile ssd(system_body(component("int", "test_integrator") + component("gain", "test_gain", real("k", -0.5)),
                            connect("int", "y", "gain", "u") + connect("gain", "y", "int", "u")));
    System system(read_system_description(ssd.path), options());
    Probe probe(system, "int", "y");
    const auto stats = run(system, probe, 2.0, 0.5);
    ASSERT_EQ(probe.samples.size(), 5u);
    for (const auto& [t, y] : probe.samples) EXPECT_NEAR(y, std::exp(-0.5 * t), 1e-6) << "t = " << t;
    EXPECT_GT(stats.rhs_evaluations, 0);
}

TEST(CosimSystem, CoSimulationComponentFeedsModelExchangeWithAZeroOrderHold) {
    // gain as Co-Simulation: y = k u = 2 (u's start is 1) from t = 0; the integrator ramps at 2/tau.
    SsdFile ssd(system_body(component("gain", "test_gain") + component("int", "test_integrator", real("tau", 4.0)),
                            connect("gain", "y", "int", "u")));
    System system(read_system_description(ssd.path), options({"gain"}));
    Probe probe(system, "int", "y");
    const auto stats = run(system, probe, 1.0, 0.25);
    EXPECT_NEAR(probe.samples.back().second, 1.0 + 2.0 / 4.0, 1e-9);
    EXPECT_EQ(stats.communication_points, 4);  // steps over [0, 0.25], ..., [0.75, 1], each taken at its end
}

TEST(CosimSystem, CoSimulationComponentInterpolatesItsInputsOverAStep) {
    // ramp (ME): x = 1 + t, since its input u = 1. acc (CS, declared in the .ssd with its own 0.25 s
    // step) integrates the ramp: x = 1 + t + t^2 / 2, 2.5 at t = 1. Linear input interpolation makes
    // that exact; a zero-order hold of each step's start value would give 1 + 0.25 (1 + 1.25 + 1.5 +
    // 1.75) = 2.375.
    const std::string acc =
        "<ssd:Component name=\"acc\" source=\"test_integrator.fmu\"><ssd:Annotations>"
        "<ssc:Annotation type=\"org.pvatt.execution\"><ex:Execution xmlns:ex=\"urn:pvatt:execution\" "
        "interface=\"CoSimulation\" communicationStep=\"0.25\"/></ssc:Annotation></ssd:Annotations>"
        "</ssd:Component>\n";
    SsdFile ssd(system_body(component("ramp", "test_integrator") + acc, connect("ramp", "y", "acc", "u")));
    auto o = options();
    o.settings = {"ramp.u=1"};
    o.tolerance = 1e-10;  // the CS component's own integrator
    System system(read_system_description(ssd.path), o);
    ASSERT_EQ(system.components()[1].interface, Interface::co_simulation);
    Probe probe(system, "acc", "y");
    const auto stats = run(system, probe, 1.0, 0.5);
    EXPECT_EQ(stats.communication_points, 4);
    EXPECT_NEAR(probe.samples.back().second, 2.5, 1e-7);
    EXPECT_NEAR(probe.samples[1].second, 1.0 + 0.5 + 0.125, 1e-7);  // t = 0.5

    // The reference execution ignores the annotation: all Model Exchange, the same answer.
    o.model_exchange_only = true;
    System all_me(read_system_description(ssd.path), o);
    EXPECT_EQ(all_me.components()[1].interface, Interface::model_exchange);
    Probe probe_me(all_me, "acc", "y");
    run(all_me, probe_me, 1.0, 0.5);
    EXPECT_NEAR(probe_me.samples.back().second, 2.5, 1e-7);
}

TEST(CosimSystem, StateEventsOfAComponentAreLocated) {
    SsdFile ssd(system_body(component("ball", "test_ball")));
    System system(read_system_description(ssd.path), options());
    Probe probe(system, "ball", "y");
    const auto stats = run(system, probe, 1.0, 0.1);
    // The ball's first impact at sqrt(2/9.81) = 0.4515 s; 0.25 s ticks are time events (4 of them).
    EXPECT_EQ(stats.state_events, 1);
    EXPECT_EQ(stats.time_events, 4);
    const auto& md = system.components()[0].description();
    EXPECT_EQ(system.components()[0].instance->get_integer(md.find_variable("bounces")->value_reference), 1);
}

TEST(CosimSystem, SettingsOverrideTheSystemsParameters) {
    SsdFile ssd(system_body(component("int", "test_integrator") + component("gain", "test_gain", real("k", -0.5)),
                            connect("int", "y", "gain", "u") + connect("gain", "y", "int", "u")));
    auto o = options();
    o.settings = {"gain.k=1"};
    System system(read_system_description(ssd.path), o);
    Probe probe(system, "int", "y");
    run(system, probe, 1.0, 0.5);
    EXPECT_NEAR(probe.samples.back().second, std::exp(1.0), 1e-6);
}

void expect_refused(const std::string& body, const std::string& fragment) {
    SsdFile ssd(body);
    try {
        System system(read_system_description(ssd.path), options());
        FAIL() << "accepted a system that should be refused for: " << fragment;
    } catch (const CosimError& e) {
        EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
}

TEST(CosimSystem, AlgebraicLoopIsRefused) {
    expect_refused(system_body(component("a", "test_gain") + component("b", "test_gain"),
                               connect("a", "y", "b", "u") + connect("b", "y", "a", "u")),
                   "algebraic loop");
}

TEST(CosimSystem, BrokenConnectionsAreRefused) {
    const auto two = component("a", "test_gain") + component("b", "test_integrator") + component("ball", "test_ball");
    expect_refused(system_body(two, connect("a", "y", "nobody", "u")), "no component named 'nobody'");
    expect_refused(system_body(two, connect("a", "nothing", "b", "u")), "a: no variable named 'nothing'");
    expect_refused(system_body(two, connect("a", "u", "b", "u")), "must be an output");
    expect_refused(system_body(two, connect("ball", "y", "b", "u")), "unit mismatch");
    expect_refused(system_body(two, connect("ball", "bounces", "b", "u")), "type mismatch");
    expect_refused(system_body(two, connect("a", "y", "b", "u") + connect("b", "y", "b", "u")), "already has a source");
    expect_refused(system_body(component("a", "no_such_fmu")), "not found");
}

TEST(CosimSystem, MalformedFilesAreRefused) {
    const auto path = std::filesystem::temp_directory_path() / "cosim_test_malformed.ssd";
    std::ofstream(path) << "<ssd:SystemStructureDescription><unclosed>";
    EXPECT_THROW(read_system_description(path), CosimError);
    std::ofstream(path) << R"(<?xml version="1.0"?>
<!DOCTYPE x [<!ENTITY e SYSTEM "file:///etc/passwd">]>
<ssd:SystemStructureDescription xmlns:ssd="http://ssp-standard.org/SSP1/SystemStructureDescription" version="1.0" name="x">
<ssd:System name="&e;"/></ssd:SystemStructureDescription>)";
    // External entities are never loaded: the name stays unexpanded (empty), never the file's content.
    try {
        const auto d = read_system_description(path);
        EXPECT_EQ(d.name.find("root"), std::string::npos);
    } catch (const CosimError&) {}
    std::filesystem::remove(path);
    EXPECT_THROW(read_system_description("/nonexistent/system.ssd"), CosimError);
}

}  // namespace
}  // namespace cosim
