// Static conformance: the model description's rules and the binary's exported functions; plus unit
// tests showing each rule of the checker fires on a hand-made violation.
#include <gtest/gtest.h>

#include <csignal>
#include <fstream>
#include <iterator>
#include <string_view>

#include "conformance_fixture.hpp"
#include "description_rules.hpp"
#include "xml_schema.hpp"

using namespace conformance;
using namespace fmi_loader;

TEST(ConformanceDiscovery, FindsAtLeastOneFmu) {
    // An empty catalog would make every parameterized check vanish; that must not look like success.
    EXPECT_FALSE(fmu_files().empty()) << "no .fmu found in " << fmu_directory()
                                      << " (set PVATT_FMU_DIR to point the suite elsewhere)";
}

CONFORMANCE_SUITE(ConformanceDescription);

TEST_P(ConformanceDescription, FollowsFmi2Rules) {
    const auto violations = description_violations(md());
    std::string all;
    for (const auto& v : violations) all += "  " + v + "\n";
    EXPECT_TRUE(violations.empty()) << violations.size() << " violation(s) in " << GetParam() << ":\n" << all;
}

// The description as written into the archive, against the standard's own schema (fmi2/schema, FMI 2.0.4).
TEST_P(ConformanceDescription, ValidatesAgainstTheFmi2Schema) {
    const std::filesystem::path schema = std::filesystem::path(FMI2_SCHEMA_DIR) / "fmi2ModelDescription.xsd";
    const auto description = fmu().archive().model_description_path();
    EXPECT_EQ(test_support::xml_schema_errors(schema, description), "") << GetParam();
    // The same description with one attribute the schema does not know must fail: the check is not vacuous.
    std::ifstream in(description);
    std::string xml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto at = xml.find("<ModelVariables");
    ASSERT_NE(at, std::string::npos);
    xml.insert(at + std::string_view("<ModelVariables").size(), " unknownAttribute=\"1\"");
    const auto doctored = description.parent_path() / "doctored_modelDescription.xml";
    std::ofstream(doctored) << xml;
    EXPECT_NE(test_support::xml_schema_errors(schema, doctored).find("unknownAttribute"), std::string::npos);
}

TEST_P(ConformanceDescription, BinaryExportsEveryFunction) {
    for (FmuKind kind : {FmuKind::model_exchange, FmuKind::co_simulation}) {
        if (!fmu().supports(kind)) continue;
        try {
            const Fmi2Library& lib = fmu().library(kind);
            EXPECT_STREQ(lib->fmi2GetVersion(), "2.0");
            EXPECT_STREQ(lib->fmi2GetTypesPlatform(), "default");
        } catch (const LoaderError& e) {
            ADD_FAILURE() << e.what();
        }
    }
}

namespace {

std::vector<std::string> violations_of(const std::string& variables, const std::string& structure = "",
                                       const std::string& extra_root = "", const std::string& units = "") {
    const std::string xml = "<fmiModelDescription fmiVersion=\"2.0\" modelName=\"m\" guid=\"g\" " + extra_root +
                            "><CoSimulation modelIdentifier=\"m\"/>" + units + "<ModelVariables>" + variables +
                            "</ModelVariables><ModelStructure>" + structure + "</ModelStructure></fmiModelDescription>";
    return description_violations(parse_model_description(xml));
}

bool mentions(const std::vector<std::string>& violations, const std::string& text) {
    for (const auto& v : violations)
        if (v.find(text) != std::string::npos) return true;
    return false;
}

}  // namespace

TEST(ConformanceRules, ConformingDescriptionHasNoViolation) {
    // x' = -k x with output y = x: states, derivative, parameter, output all by the book.
    const auto v = violations_of(
        R"x(<ScalarVariable name="x" valueReference="0" initial="exact"><Real start="1"/></ScalarVariable>
           <ScalarVariable name="der(x)" valueReference="1"><Real derivative="1"/></ScalarVariable>
           <ScalarVariable name="k" valueReference="2" causality="parameter" variability="fixed"><Real start="2" unit="1/s"/></ScalarVariable>
           <ScalarVariable name="y" valueReference="3" causality="output"><Real/></ScalarVariable>)x",
        R"x(<Outputs><Unknown index="4" dependencies="1"/></Outputs><Derivatives><Unknown index="2" dependencies="1"/></Derivatives>
           <InitialUnknowns><Unknown index="2"/><Unknown index="4"/></InitialUnknowns>)x",
        "variableNamingConvention=\"structured\"",
        R"x(<UnitDefinitions><Unit name="1/s"><BaseUnit s="-1"/></Unit></UnitDefinitions>)x");
    EXPECT_TRUE(v.empty()) << (v.empty() ? "" : v.front());
}

TEST(ConformanceRules, DuplicateNamesAndValueReferencesAreFound) {
    // A duplicate name, or an alias set with two start values, the loader itself refuses (issue 14):
    // the rules never see such a file.
    EXPECT_THROW(
        violations_of(
            R"x(<ScalarVariable name="a" valueReference="1" causality="input"><Real start="0"/></ScalarVariable>
           <ScalarVariable name="a" valueReference="2" causality="input"><Real start="0"/></ScalarVariable>)x"),
        fmi_loader::LoaderError);
    EXPECT_THROW(
        violations_of(
            R"x(<ScalarVariable name="a" valueReference="1" causality="input"><Real start="0"/></ScalarVariable>
           <ScalarVariable name="b" valueReference="1" causality="input"><Real start="0"/></ScalarVariable>)x"),
        fmi_loader::LoaderError);
    // A true alias (one start value) loads; our own FMUs must still not use one.
    const auto v = violations_of(
        R"x(<ScalarVariable name="a" valueReference="1" causality="input"><Real start="0"/></ScalarVariable>
           <ScalarVariable name="b" valueReference="1" causality="output"><Real/></ScalarVariable>
           <ScalarVariable name="c" valueReference="1" causality="input" variability="discrete"><Integer start="0"/></ScalarVariable>)x",
        R"x(<Outputs><Unknown index="2"/></Outputs><InitialUnknowns><Unknown index="2"/></InitialUnknowns>)x");
    EXPECT_TRUE(mentions(v, "valueReference 1 of the same type"));
    EXPECT_EQ(v.size(), 1u) << "an Integer may reuse a Real's value reference";
}

TEST(ConformanceRules, StartValueTableIsEnforced) {
    const auto v = violations_of(
        R"x(<ScalarVariable name="p" valueReference="1" causality="parameter" variability="fixed"><Real/></ScalarVariable>
           <ScalarVariable name="u" valueReference="2" causality="input"><Real/></ScalarVariable>
           <ScalarVariable name="y" valueReference="3" causality="output"><Real start="1"/></ScalarVariable>
           <ScalarVariable name="t" valueReference="4" causality="independent"><Real start="0"/></ScalarVariable>
           <ScalarVariable name="bad" valueReference="5" causality="input" variability="fixed"><Real start="0"/></ScalarVariable>)x",
        R"x(<Outputs><Unknown index="3"/></Outputs><InitialUnknowns><Unknown index="3"/></InitialUnknowns>)x");
    EXPECT_TRUE(mentions(v, "'p': start value required"));
    EXPECT_TRUE(mentions(v, "'u': start value required"));
    EXPECT_TRUE(mentions(v, "'y': start value given"));
    EXPECT_TRUE(mentions(v, "'t': start value given"));
    EXPECT_TRUE(mentions(v, "'bad': causality input with variability fixed"));
}

TEST(ConformanceRules, ModelStructureIndicesAreChecked) {
    const auto v = violations_of(
        R"x(<ScalarVariable name="x" valueReference="0" initial="exact"><Real start="1"/></ScalarVariable>
           <ScalarVariable name="y" valueReference="1" causality="output"><Real/></ScalarVariable>
           <ScalarVariable name="z" valueReference="2" causality="output"><Real/></ScalarVariable>)x",
        R"x(<Outputs><Unknown index="1"/><Unknown index="2" dependencies="1 2" dependenciesKind="constant"/></Outputs>
           <Derivatives><Unknown index="2"/></Derivatives><InitialUnknowns><Unknown index="2"/></InitialUnknowns>)x");
    EXPECT_TRUE(mentions(v, "Outputs: index 1 is not causality=output"));
    // An index beyond the variables the loader refuses itself (issue 14).
    EXPECT_THROW(violations_of(R"x(<ScalarVariable name="x" valueReference="0"><Real/></ScalarVariable>)x",
                               R"x(<Outputs><Unknown index="9"/></Outputs>)x"),
                 fmi_loader::LoaderError);
    EXPECT_TRUE(mentions(v, "Derivatives: index 2 has no derivative attribute"));
    EXPECT_TRUE(mentions(v, "Outputs: unknown 2 has a dependenciesKind list that does not pair"));
    EXPECT_TRUE(mentions(v, "Outputs: unknown 2 depends on 2 which is neither input, state nor independent"));
    EXPECT_TRUE(mentions(v, "'z': output missing from ModelStructure/Outputs"));
    EXPECT_TRUE(mentions(v, "'z': missing from ModelStructure/InitialUnknowns"));
}

TEST(ConformanceRules, UndefinedUnitIsFound) {
    const auto v = violations_of(
        R"x(<ScalarVariable name="u" valueReference="0" causality="input"><Real start="0" unit="furlong"/></ScalarVariable>)x");
    EXPECT_TRUE(mentions(v, "unit 'furlong' is not defined"));
}

TEST(ConformanceRules, StructuredNameGrammar) {
    // Examples from the structured-name grammar of FMI 2.0.4 section 2.2.9.
    for (const char* good : {"a", "_a1", "vehicle.engine.speed", "sun_body[1]", "a[1,2].b[3]", "der(x)",
                             "der(a.b[2],2)", "'quoted name'", "a.'b c'[1]", "'it\\'s'"})
        EXPECT_TRUE(is_structured_name(good)) << good;
    for (const char* bad :
         {"", "1a", "a.", ".a", "a[]", "a[1", "a[x]", "der(x", "der()", "a b", "''", "a..b", "sun_body(1)"}) {
        EXPECT_FALSE(is_structured_name(bad)) << bad;
    }
    const auto v = violations_of(
        R"x(<ScalarVariable name="a b" valueReference="0" causality="input"><Real start="0"/></ScalarVariable>)x", "",
        "variableNamingConvention=\"structured\"");
    EXPECT_TRUE(mentions(v, "not a valid structured name"));
}

TEST(ConformanceIsolation, CrashInChildIsReportedNotFatal) {
    // The misuse checks rely on this: a crashing FMU call must come back as a failure description.
    const IsolatedResult crashed = run_isolated([](bool&, std::string&) -> fmi2Status {
        std::raise(SIGSEGV);
        return fmi2OK;
    });
    EXPECT_FALSE(crashed.completed);
    // Plain builds report the signal; under AddressSanitizer its handler turns the crash into an
    // exit with an error code. Either way the failure is described, not lost.
    EXPECT_FALSE(crashed.crash.empty());

    const IsolatedResult fine = run_isolated([](bool& logged, std::string& log) {
        logged = true;
        log = "message";
        return fmi2Discard;
    });
    ASSERT_TRUE(fine.completed) << fine.crash;
    EXPECT_EQ(fine.status, fmi2Discard);
    EXPECT_TRUE(fine.logged);
    EXPECT_EQ(fine.log, "message");
}
