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

// ---- System parameters (SSP 1.0: the system's own parameter connectors, their values in the system's
// ParameterBindings, connections without startElement to the components' parameters) ----

// A system parameter connector of `type` ("Real unit=\"1\"", "Enumeration name=\"Sign\"").
std::string system_parameter(const std::string& name, const std::string& type) {
    return "<ssd:Connector name=\"" + name + "\" kind=\"parameter\"><ssc:" + type + "/></ssd:Connector>";
}
std::string system_connectors(const std::string& connectors) {
    return "<ssd:Connectors>" + connectors + "</ssd:Connectors>";
}
std::string system_bindings(const std::string& params) {
    return "<ssd:ParameterBindings><ssd:ParameterBinding><ssd:ParameterValues><ssv:ParameterSet version=\"1.0\" "
           "name=\"s\"><ssv:Parameters>" +
           params +
           "</ssv:Parameters></ssv:ParameterSet></ssd:ParameterValues></ssd:ParameterBinding></ssd:ParameterBindings>";
}
std::string feed(const std::string& parameter, const std::string& component, const std::string& variable) {
    return "<ssd:Connection startConnector=\"" + parameter + "\" endElement=\"" + component + "\" endConnector=\"" +
           variable + "\"/>\n";
}

// Two gains in series (a.u = 1 by its start value): the system parameter gain_k feeds both, y = k^2.
std::string two_gains(const std::string& bound = "3", const std::string& extra_a = "") {
    return system_connectors(system_parameter("gain_k", "Real unit=\"1\"")) +
           (bound.empty() ? "" : system_bindings(real("gain_k", std::stod(bound)))) +
           system_body(component("a", "test_gain", extra_a) + component("b", "test_gain"),
                       connect("a", "y", "b", "u") + feed("gain_k", "a", "k") + feed("gain_k", "b", "k"));
}

double last_y(const std::string& body, SystemOptions o = options()) {
    SsdFile ssd(body);
    System system(read_system_description(ssd.path), o);
    Probe probe(system, "b", "y");
    run(system, probe, 0.5, 0.5);
    return probe.samples.back().second;
}

// A parameter set file (.ssv) beside the test's .ssd.
struct SsvFile {
    std::filesystem::path path;
    SsvFile(const std::string& tag, const std::string& parameters) {
        path = std::filesystem::temp_directory_path() /
               ("cosim_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" + tag + ".ssv");
        std::ofstream(path)
            << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
               "<ssv:ParameterSet xmlns:ssv=\"http://ssp-standard.org/SSP1/SystemStructureParameterValues\" "
               "version=\"1.0\" name=\""
            << tag << "\">\n<ssv:Parameters>\n"
            << parameters << "\n</ssv:Parameters>\n</ssv:ParameterSet>\n";
    }
    ~SsvFile() { std::filesystem::remove(path); }
};

TEST(CosimSystemParameters, ASystemParameterFeedsEveryComponentParameterItIsConnectedTo) {
    EXPECT_EQ(last_y(two_gains("3")), 9.0);  // y = k k u with u = 1
    SystemOptions o = options();
    o.settings = {"gain_k=2"};  // --set NAME=VALUE without a component: the system parameter
    EXPECT_EQ(last_y(two_gains("3"), o), 4.0);
    // A component parameter set directly wins over the system parameter, for that component only.
    o.settings = {"gain_k=2", "a.k=5"};
    EXPECT_EQ(last_y(two_gains("3"), o), 10.0);
    SsdFile ssd(two_gains("3"));
    const System system(read_system_description(ssd.path), o);
    ASSERT_EQ(system.fed_parameters_set_directly().size(), 1u);
    EXPECT_EQ(system.fed_parameters_set_directly()[0], "a.k (system parameter gain_k)");
    EXPECT_EQ(system.initial_value(system.component_index("b"), "k"), "2");
    EXPECT_EQ(system.initial_value(system.component_index("a"), "k"), "5");
    EXPECT_EQ(system.system_parameter_values().at(0).value, "2");
}

TEST(CosimSystemParameters, AnEnumerationTravelsByItemName) {
    const std::string body =
        system_connectors(system_parameter("sign", "Enumeration name=\"Sign\"")) +
        system_bindings("<ssv:Parameter name=\"sign\"><ssv:Enumeration value=\"minus\"/></ssv:Parameter>") +
        system_body(component("a", "test_gain") + component("b", "test_gain"),
                    connect("a", "y", "b", "u") + feed("sign", "a", "sign") + feed("sign", "b", "sign"));
    EXPECT_EQ(last_y(body), 4.0);  // (-2) (-2) 1
    SystemOptions o = options();
    o.settings = {"sign=plus"};
    EXPECT_EQ(last_y(body, o), 4.0);
    o.settings = {"b.sign=plus"};
    EXPECT_EQ(last_y(body, o), -4.0);
    o.settings = {"sign=zero"};
    EXPECT_THROW(last_y(body, o), SettingError);
}

TEST(CosimSystemParameters, ParameterFilesComeAfterTheSystemsValuesLaterFilesWinAndSetComesLast) {
    const SsvFile two("two", real("gain_k", 2)), four("four", real("gain_k", 4) + real("a.k", 1));
    SystemOptions o = options();
    o.parameter_files = {two.path};
    EXPECT_EQ(last_y(two_gains("3"), o), 4.0);
    o.parameter_files = {two.path, four.path};
    EXPECT_EQ(last_y(two_gains("3"), o), 4.0);  // a.k = 1 directly, b.k = 4
    o.parameter_files = {four.path, two.path};
    EXPECT_EQ(last_y(two_gains("3"), o), 2.0);  // a.k = 1 still (nothing later names it), b.k = 2
    o.settings = {"gain_k=10"};
    EXPECT_EQ(last_y(two_gains("3"), o), 10.0);
    // A system parameter without a value in the .ssd takes it from a file.
    o = options();
    o.parameter_files = {two.path};
    EXPECT_EQ(last_y(two_gains(""), o), 4.0);
}

void expect_refused_with(const std::string& body, const std::string& fragment, SystemOptions o = options()) {
    SsdFile ssd(body);
    try {
        System system(read_system_description(ssd.path), o);
        FAIL() << "accepted a system that should be refused for: " << fragment;
    } catch (const CosimError& e) {
        EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
}

TEST(CosimSystemParameters, MalformedSystemParametersAreRefusedByName) {
    const auto gains = component("a", "test_gain") + component("b", "test_gain");
    const auto k = system_connectors(system_parameter("gain_k", "Real unit=\"1\""));
    const auto bound = system_bindings(real("gain_k", 3));
    expect_refused_with(system_connectors("<ssd:Connector name=\"x\" kind=\"input\"><ssc:Real/></ssd:Connector>") +
                            system_body(gains, feed("x", "a", "u")),
                        "system connector 'x' is of kind input");
    expect_refused_with(
        system_connectors("<ssd:Connector name=\"x\" kind=\"parameter\"/>") + system_body(gains, feed("x", "a", "k")),
        "system parameter 'x' needs its type");
    expect_refused_with(system_connectors(system_parameter("a.k", "Real")) + system_body(gains, feed("a.k", "a", "k")),
                        "must be non-empty without '.'");
    expect_refused_with(k + bound + system_body(gains, feed("gain_k", "a", "u")), "the end must be a parameter");
    expect_refused_with(k + bound + system_body(gains, feed("gain_k", "a", "sign")),
                        "type mismatch (Real to Enumeration)");
    expect_refused_with(system_connectors(system_parameter("gain_k", "Real unit=\"V\"")) + bound +
                            system_body(gains, feed("gain_k", "a", "k")),
                        "unit mismatch (V to 1)");
    expect_refused_with(k + bound + system_body(gains, feed("gian_k", "a", "k") + feed("gain_k", "b", "k")),
                        "no parameter connector 'gian_k' (did you mean 'gain_k'?)");
    expect_refused_with(k + bound + system_body(gains, feed("gain_k", "a", "kk")), "a: no variable named 'kk'");
    expect_refused_with(k + bound + system_body(gains, feed("gain_k", "c", "k")), "no component named 'c'");
    expect_refused_with(k + system_body(gains, feed("gain_k", "a", "k")), "system parameter 'gain_k' has no value");
    expect_refused_with(k + bound + system_body(component("a", "test_gain", real("k", 2)), feed("gain_k", "a", "k")),
                        "also bound in its component's ParameterBindings");
    expect_refused_with(k + bound + system_body(gains, feed("gain_k", "a", "k") + feed("gain_k", "a", "k")),
                        "a.k is fed twice");
    expect_refused_with(k + bound + system_body(gains), "system parameter 'gain_k' is connected to no component");
    expect_refused_with(
        k + bound + system_body(gains, "<ssd:Connection startConnector=\"gain_k\" endConnector=\"x\"/>"),
        "a connection between two connectors of the system itself");
    expect_refused_with(k + system_bindings(real("gain_kk", 3)) + system_body(gains, feed("gain_k", "a", "k")),
                        "'gain_kk' is no system parameter of");
    expect_refused_with(
        k + system_bindings("<ssv:Parameter name=\"gain_k\"><ssv:String value=\"x\"/></ssv:Parameter>") +
            system_body(gains, feed("gain_k", "a", "k")),
        "an ssv:String value cannot set a variable of type Real");
    SystemOptions typo = options();
    typo.settings = {"gain_kk=1"};
    try {
        SsdFile ssd(two_gains());
        System system(read_system_description(ssd.path), typo);
        FAIL() << "a misspelt system parameter was taken";
    } catch (const SettingError& e) {
        EXPECT_NE(std::string(e.what()).find("'gain_kk' is no system parameter"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("did you mean 'gain_k'?"), std::string::npos) << e.what();
    }
}

TEST(CosimSystemParameters, MalformedParameterFilesAreRefusedWithTheFileLineAndName) {
    auto refused = [](const std::string& parameters, const std::string& fragment) {
        const SsvFile file("bad", parameters);
        SystemOptions o = options();
        o.parameter_files = {file.path};
        try {
            SsdFile ssd(two_gains());
            System system(read_system_description(ssd.path), o);
            ADD_FAILURE() << "accepted a file that should be refused for: " << fragment;
        } catch (const CosimError& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find(file.path.string() + ":"), std::string::npos) << what;
            EXPECT_NE(what.find(fragment), std::string::npos) << what;
        }
    };
    refused("<ssv:Parameter name=\"gain_k\"/>", ":4: parameter 'gain_k' has no typed value");
    refused("<ssv:Parameter name=\"gain_k\"><ssv:Real/></ssv:Parameter>", ":4: parameter 'gain_k': <ssv:Real> lacks");
    refused("<ssv:Parameter name=\"gain_k\"><ssv:Real value=\"fast\"/></ssv:Parameter>", ":4: system parameter gain_k");
    refused("<ssv:Parameter name=\"gian_k\"><ssv:Real value=\"1\"/></ssv:Parameter>",
            ":4: 'gian_k' is no system parameter of");
    refused("<ssv:Parameter name=\"a.kk\"><ssv:Real value=\"1\"/></ssv:Parameter>", ":4: a: no variable named 'kk'");
    refused("<ssv:Parameter><ssv:Real value=\"1\"/></ssv:Parameter>", ":4: <Parameter> lacks the attribute 'name'");
    const auto wrong_root = std::filesystem::temp_directory_path() / "cosim_test_wrong_root.ssv";
    std::ofstream(wrong_root) << "<?xml version=\"1.0\"?>\n<Parameters/>\n";
    EXPECT_THROW(read_parameter_values(wrong_root), CosimError);
    std::filesystem::remove(wrong_root);
    EXPECT_THROW(read_parameter_values("/nonexistent/p.ssv"), CosimError);
}

}  // namespace
}  // namespace cosim
