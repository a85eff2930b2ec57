// Messages that lead somewhere (issue 31): a misspelt name gets the names it was close to, an array's
// base name its elements, a typo is reported before the checks it would trip, a missing FMU once with
// the folders looked in, and a run shorter than the system's output interval runs with it shortened.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "engine/cosim_error.hpp"
#include "engine/csv_table.hpp"
#include "engine/name_hint.hpp"
#include "info_command.hpp"
#include "run_command.hpp"
#include "system_diagram.hpp"

namespace cosim {
namespace {

namespace fs = std::filesystem;
const fs::path fmu_dir = COSIM_TEST_FMU_DIR;

fmi_loader::ModelDescription variables(std::initializer_list<const char*> names) {
    fmi_loader::ModelDescription md;
    for (const char* n : names) {
        fmi_loader::ScalarVariable v;
        v.name = n;
        md.model_variables.push_back(v);
    }
    return md;
}

TEST(Messages, AMisspeltVariableGetsTheClosestNames) {
    const auto md = variables({"sun_method", "sun_meas[1]", "sun_meas[2]", "sun_meas[3]", "samples"});
    EXPECT_EQ(unknown_variable_message(md, "est", "sun_methd"),
              "est: no variable named 'sun_methd' (did you mean 'sun_method'?)");
    // Nothing close: no guess.
    EXPECT_EQ(unknown_variable_message(md, "est", "inertia"), "est: no variable named 'inertia'");
}

TEST(Messages, AnArraysBaseNameGetsItsElements) {
    const auto md = variables({"q0[1]", "q0[2]", "q0[3]", "q0[4]", "omega0[1]"});
    EXPECT_EQ(unknown_variable_message(md, "env", "q0"), "env: no variable named 'q0' (an array: q0[1] .. q0[4])");
    // A misspelt array element keeps the index asked for.
    EXPECT_EQ(unknown_variable_message(md, "env", "omega1[1]"),
              "env: no variable named 'omega1[1]' (did you mean 'omega0[1]'?)");
}

TEST(Messages, ClosestNamesAreOrderedAndListedOnce) {
    EXPECT_EQ(name_hint("ets", {"env", "est", "plant", "est"}), " (did you mean 'est'?)");
    EXPECT_EQ(name_hint("cone", {"difference", "inverse_response", "cones", "three_faces"}),
              " (did you mean 'cones'?)");
}

struct Scratch {
    fs::path root;
    Scratch() {
        std::string pattern = (fs::temp_directory_path() / "cosim_messages_XXXXXX").string();
        root = ::mkdtemp(pattern.data());
    }
    ~Scratch() { fs::remove_all(root); }
    // A system of components with an output interval of 10 s in its execution annotation.
    fs::path ssd(const std::string& elements) const {
        const fs::path path = root / "system.ssd";
        std::ofstream(path) << R"(<?xml version="1.0" encoding="UTF-8"?>
<ssd:SystemStructureDescription xmlns:ssd="http://ssp-standard.org/SSP1/SystemStructureDescription"
    xmlns:ssc="http://ssp-standard.org/SSP1/SystemStructureCommon" version="1.0" name="test">
  <ssd:System name="test"><ssd:Elements>)"
                            << elements << R"(</ssd:Elements></ssd:System>
  <ssd:DefaultExperiment startTime="0" stopTime="100">
    <ssd:Annotations><ssc:Annotation type="org.pvatt.execution">
      <ex:Output xmlns:ex="urn:pvatt:execution" interval="10"/>
    </ssc:Annotation></ssd:Annotations>
  </ssd:DefaultExperiment>
</ssd:SystemStructureDescription>
)";
        return path;
    }
};

const std::string gain = R"(<ssd:Component name="gain" source="test_gain.fmu"/>)";

RunOptions options_for(const fs::path& ssd) {
    RunOptions o;
    o.ssd = ssd;
    o.system.fmu_dirs = {fmu_dir};
    o.progress = false;
    return o;
}

std::string refusal(const RunOptions& o) {
    std::ostringstream report;
    try {
        run_system(o, report);
    } catch (const CosimError& e) {
        return e.what();
    }
    return "accepted";
}

TEST(Messages, ASetNameIsCheckedBeforeTheIntervals) {
    // Both wrong: the misspelt name is the cause the user must hear first (it was the interval).
    Scratch s;
    auto o = options_for(s.ssd(gain));
    o.system.settings = {"gain.kk=2"};
    o.stop_time = 5.0;
    o.output_interval = 50.0;
    EXPECT_EQ(refusal(o), "gain: no variable named 'kk' (did you mean 'k'?)");
}

TEST(Messages, AnEnumerationValueThatIsNoItemGetsTheClosestItem) {
    Scratch s;
    auto o = options_for(s.ssd(gain));
    o.system.settings = {"gain.sign=minu"};
    const std::string says = refusal(o);
    EXPECT_NE(says.find("'minu' is not an item"), std::string::npos) << says;
    EXPECT_NE(says.find("(did you mean 'minus'?)"), std::string::npos) << says;
}

TEST(Messages, ABadBindingNamesItsFileAndLine) {
    // The binding sits on line 7 of the written .ssd (the component starts on line 5, after the 4 header lines).
    Scratch s;
    const auto ssd = s.ssd(R"(
<ssd:Component name="gain" source="test_gain.fmu"><ssd:ParameterBindings><ssd:ParameterBinding>
<ssd:ParameterValues><ssv:ParameterSet xmlns:ssv="http://ssp-standard.org/SSP1/SystemStructureParameterValues" version="1.0" name="p"><ssv:Parameters>
<ssv:Parameter name="sing"><ssv:String value="minus"/></ssv:Parameter>
</ssv:Parameters></ssv:ParameterSet></ssd:ParameterValues></ssd:ParameterBinding></ssd:ParameterBindings></ssd:Component>)");
    EXPECT_EQ(refusal(options_for(ssd)), ssd.string() + ":7: gain: no variable named 'sing' (did you mean 'sign'?)");
}

TEST(Messages, AnFmusRefusalIsSaidOnceWithTheValue) {
    // The integrator's tau has a minimum of 1e-6 s: -1 is refused by the FMU. Its message comes once, in
    // the error (it was also printed on stderr as the FMU's log line), and names the value.
    Scratch s;
    auto o = options_for(s.ssd(R"(<ssd:Component name="int" source="test_integrator.fmu"/>)"));
    o.system.settings = {"int.tau=-1"};
    ::testing::internal::CaptureStderr();
    const std::string says = refusal(o);
    const std::string printed = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(says.find("int: fmi2SetReal returned Error"), std::string::npos) << says;
    EXPECT_NE(says.find("-1"), std::string::npos) << says;
    EXPECT_EQ(printed.find("[Error]"), std::string::npos) << printed;
}

TEST(Messages, AnFmi3FmusRefusalIsSaidOnceToo) {
    // The same refusal from the integrator's FMI 3.0 archive: its error log line is held for the
    // exception, not printed as well.
    Scratch s;
    auto o = options_for(s.ssd(R"(<ssd:Component name="int" source="fmi3/test_integrator.fmu"/>)"));
    o.system.settings = {"int.tau=-1"};
    ::testing::internal::CaptureStderr();
    const std::string says = refusal(o);
    const std::string printed = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(says.find("int: fmi3SetFloat64 returned Error"), std::string::npos) << says;
    EXPECT_NE(says.find("-1"), std::string::npos) << says;
    EXPECT_EQ(printed.find("[Error]"), std::string::npos) << printed;
}

TEST(Messages, EachMissingFmuOnceWithTheFoldersLookedIn) {
    Scratch s;
    auto o =
        options_for(s.ssd(R"(<ssd:Component name="a" source="ghost.fmu"/><ssd:Component name="b" source="ghost.fmu"/>
<ssd:Component name="c" source="phantom.fmu"/>)"));
    o.system.fmu_dirs = {fmu_dir, fmu_dir / "."};  // the same folder twice: one place
    const std::string says = refusal(o);
    EXPECT_NE(says.find("2 FMUs not found: ghost.fmu phantom.fmu; looked in:\n  " + s.root.string() + "\n  " +
                        fmu_dir.lexically_normal().string() + "\n"),
              std::string::npos)
        << says;
}

TEST(Messages, AStopTimeShorterThanTheSystemsIntervalRunsWithItShortened) {
    // The system's 10 s rows over a 5 s run: a row every 0.05 s instead (101 rows), not a refusal.
    Scratch s;
    auto o = options_for(s.ssd(gain));
    o.stop_time = 5.0;
    o.csv = s.root / "out.csv";
    std::ostringstream report;
    run_system(o, report);
    const auto table = read_csv(*o.csv);
    EXPECT_EQ(table.rows(), 101u);
}

TEST(Messages, InfoShowsTheExperimentTheConnectionsAndEnumerationItems) {
    Scratch s;
    const auto ssd =
        s.ssd(R"(<ssd:Component name="a" source="test_gain.fmu"/><ssd:Component name="b" source="test_gain.fmu"/>
</ssd:Elements><ssd:Connections><ssd:Connection startElement="a" startConnector="y" endElement="b" endConnector="u"/>
</ssd:Connections><ssd:Elements>)");
    std::ostringstream system;
    print_info(ssd, system);
    EXPECT_NE(system.str().find("experiment: start 0 s, stop 100 s, output interval 10 s"), std::string::npos)
        << system.str();
    EXPECT_NE(system.str().find("  a  test_gain.fmu  Model Exchange"), std::string::npos) << system.str();
    EXPECT_NE(system.str().find("connections:\n  a.y -> b.u\n"), std::string::npos) << system.str();
    // The gain's sign: plus = 1 (its default), minus = 2 (harness/engine/tests/fmus/test_blocks.hpp).
    std::ostringstream fmu;
    print_info(fmu_dir / "test_gain.fmu", fmu);
    EXPECT_NE(fmu.str().find("plus (1)"), std::string::npos) << fmu.str();
    EXPECT_NE(fmu.str().find("[plus = 1, minus = 2]"), std::string::npos) << fmu.str();
}

}  // namespace
}  // namespace cosim

namespace cosim {
namespace {

// Issue 40: --columns names variables whether a CSV is written or not; a typo was ignored without --output.
TEST(Messages, AColumnsTypoIsRefusedAlsoWithoutOutput) {
    Scratch s;
    auto o = options_for(s.ssd(gain));
    o.columns = {"gain.yy"};
    EXPECT_EQ(refusal(o), "--columns: gain: no variable named 'yy' (did you mean 'y'?)");
}

// Issue 40: a system's <ex:Measures report=".."/> names what its runs say at the end; a name that is no
// measure is refused before the run with the closest one.
TEST(Messages, AMeasureTheSystemDeclaresMustExist) {
    Scratch s;
    const fs::path ssd = s.ssd(gain);
    std::string text;
    {
        std::ifstream in(ssd);
        text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    const std::string stop = "</ssc:Annotation>";
    text.insert(text.find(stop) + stop.size(),
                R"(<ssc:Annotation type="org.pvatt.execution"><ex:Measures xmlns:ex="urn:pvatt:execution" )"
                R"(report="attitude faults constistency"/></ssc:Annotation>)");
    std::ofstream(ssd) << text;
    const std::string says = refusal(options_for(ssd));
    EXPECT_NE(says.find("<ex:Measures report> names 'constistency', not a measure (did you mean 'consistency'?)"),
              std::string::npos)
        << says;
}

}  // namespace
}  // namespace cosim

namespace cosim {
namespace {

// Issue 40: the system as a picture. One arrow per connected pair, labelled with what it carries (an
// array's elements once), names quoted (a quote in a name cannot end the string); dot draws it.
TEST(Diagram, OneArrowPerPairOfComponentsLabelledWithWhatItCarries) {
    SystemDescription d;
    d.name = "sys";
    for (const char* n : {"env", "est \"1\""}) {
        ComponentDescription c;
        c.name = n;
        c.source = "x.fmu";
        d.components.push_back(c);
    }
    for (const char* k : {"sun_body[1]", "sun_body[2]", "sun_body[3]", "irradiance"})
        d.connections.push_back({"env", k, "est \"1\"", k, ""});
    const std::string dot = system_dot(d);
    EXPECT_NE(dot.find("\"env\" -> \"est \\\"1\\\"\" [label=\"sun_body [..]\\nirradiance\"]"), std::string::npos)
        << dot;
    EXPECT_EQ(dot.find("sun_body[2]"), std::string::npos) << dot;

    Scratch s;
    const auto files = write_system_diagram(s.ssd(gain), s.root / "diagram");
    ASSERT_EQ(files.size(), 2u);
    std::ifstream svg(s.root / "diagram.svg");
    const std::string text((std::istreambuf_iterator<char>(svg)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("<svg"), std::string::npos);
    EXPECT_NE(text.find("gain"), std::string::npos);
}

}  // namespace
}  // namespace cosim
