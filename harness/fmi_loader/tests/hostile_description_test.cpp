// modelDescription.xml written by an attacker (issue 14 cases 2, 3, 9, 10): a modelIdentifier that
// points outside the FMU, counts that would exhaust memory, files too large to read, duplicate names
// and alias sets, indices beyond the variables, and messages that say what is wrong.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "fmi_loader/loader_error.hpp"
#include "fmi_loader/model_description.hpp"

using namespace fmi_loader;

namespace {

std::string document(const std::string& identifier, const std::string& root_attributes, const std::string& variables,
                     const std::string& structure = "") {
    return R"(<fmiModelDescription fmiVersion="2.0" modelName="m" guid="g" )" + root_attributes +
           R"(><CoSimulation modelIdentifier=")" + identifier + R"("/><ModelVariables>)" + variables +
           "</ModelVariables>" + structure + "</fmiModelDescription>";
}

// The error a document raises, or a failure when it is accepted.
LoaderError error_of(const std::string& xml, const Limits& limits = {}) {
    try {
        parse_model_description(xml, "<test>", limits);
    } catch (const LoaderError& e) {
        return e;
    }
    ADD_FAILURE() << "accepted: " << xml.substr(0, 300);
    return LoaderError(LoaderErrc::archive_open, "accepted");
}

void expect_refused(const std::string& xml, LoaderErrc code, const std::string& says, const Limits& limits = {}) {
    const LoaderError e = error_of(xml, limits);
    EXPECT_EQ(e.code(), code) << e.what();
    EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
}

const std::string one_real =
    R"(<ScalarVariable name="y" valueReference="0" causality="output"><Real/></ScalarVariable>)";

TEST(LoaderHostileDescription, ModelIdentifierMustBeACIdentifier) {
    for (const std::string id : {"/abs/path/evil", "../../../x/evil", "a/b", "9lives", "", "a b", "a.so"})
        expect_refused(document(id, "", one_real), LoaderErrc::xml_invalid, "is not a C identifier");
    EXPECT_NO_THROW(parse_model_description(document("_ok_Name9", "", one_real)));
}

TEST(LoaderHostileDescription, EventIndicatorCountIsBounded) {
    expect_refused(document("m", R"(numberOfEventIndicators="1000000000")", one_real), LoaderErrc::limit,
                   "max_event_indicators");
    expect_refused(document("m", R"(numberOfEventIndicators="4611686018427387904")", one_real), LoaderErrc::limit,
                   "max_event_indicators");  // 2^62
}

TEST(LoaderHostileDescription, VariableCountIsBounded) {
    Limits limits;
    limits.max_variables = 2;
    std::string vars;
    for (int i = 0; i < 3; ++i)
        vars += R"(<ScalarVariable name="v)" + std::to_string(i) + R"(" valueReference=")" + std::to_string(i) +
                R"("><Real/></ScalarVariable>)";
    expect_refused(document("m", "", vars), LoaderErrc::limit, "max_variables", limits);
}

TEST(LoaderHostileDescription, OversizedDocumentIsRefusedBeforeParsing) {
    Limits limits;
    limits.max_description_bytes = 1000;
    expect_refused(document("m", "", one_real) + std::string(2000, ' '), LoaderErrc::limit, "max_description_bytes",
                   limits);
    // From a file: refused by its size, before it is read.
    const auto file = std::filesystem::temp_directory_path() / ("hostile_md_" + std::to_string(::getpid()) + ".xml");
    std::ofstream(file) << document("m", "", one_real) << std::string(2000, ' ');
    try {
        read_model_description(file, limits);
        ADD_FAILURE() << "accepted";
    } catch (const LoaderError& e) {
        EXPECT_EQ(e.code(), LoaderErrc::limit) << e.what();
    }
    std::filesystem::remove(file);
}

TEST(LoaderHostileDescription, DuplicateNamesAreRefused) {
    expect_refused(
        document(
            "m", "",
            R"(<ScalarVariable name="k" valueReference="0" causality="parameter" variability="fixed"><Real start="1"/></ScalarVariable>
                               <ScalarVariable name="k" valueReference="1" causality="output"><Real/></ScalarVariable>)"),
        LoaderErrc::xml_invalid, "'k' is declared twice");
}

TEST(LoaderHostileDescription, AliasSetWithTwoStartValuesIsRefused) {
    // Two parameters on one valueReference: --set of one would change the other.
    expect_refused(
        document(
            "m", "",
            R"(<ScalarVariable name="a" valueReference="5" causality="parameter" variability="fixed"><Real start="1"/></ScalarVariable>
                               <ScalarVariable name="b" valueReference="5" causality="parameter" variability="fixed"><Real start="2"/></ScalarVariable>)"),
        LoaderErrc::xml_invalid, "share valueReference 5");
    // A true alias (one start value) and the same number for another base type are fine.
    EXPECT_NO_THROW(parse_model_description(document(
        "m", "",
        R"(<ScalarVariable name="a" valueReference="5" causality="parameter" variability="fixed"><Real start="1"/></ScalarVariable>
                               <ScalarVariable name="a_alias" valueReference="5" causality="calculatedParameter" variability="fixed"><Real/></ScalarVariable>
                               <ScalarVariable name="n" valueReference="5" causality="parameter" variability="fixed"><Integer start="3"/></ScalarVariable>)")));
}

TEST(LoaderHostileDescription, IndicesBeyondTheVariablesAreRefused) {
    expect_refused(document("m", "", one_real,
                            R"(<ModelStructure><Outputs><Unknown index="4000000000"/></Outputs></ModelStructure>)"),
                   LoaderErrc::xml_invalid, "beyond the 1 variables");
    expect_refused(
        document("m", "", one_real,
                 R"(<ModelStructure><Outputs><Unknown index="1" dependencies="7"/></Outputs></ModelStructure>)"),
        LoaderErrc::xml_invalid, "beyond the 1 variables");
    expect_refused(
        document("m", "", R"(<ScalarVariable name="d" valueReference="0"><Real derivative="9"/></ScalarVariable>)"),
        LoaderErrc::xml_invalid, "beyond the 1 variables");
}

TEST(LoaderHostileDescription, OutOfRangeNumbersAreCalledThat) {
    expect_refused(
        document("m", "", R"(<ScalarVariable name="r" valueReference="0"><Real min="1e999"/></ScalarVariable>)"),
        LoaderErrc::xml_invalid, "1e999 is out of range");
    expect_refused(
        document("m", "", R"(<ScalarVariable name="r" valueReference="0"><Real min="abc"/></ScalarVariable>)"),
        LoaderErrc::xml_invalid, "is not a number");
    expect_refused(document("m", R"(numberOfEventIndicators="99999999999999999999")", one_real),
                   LoaderErrc::xml_invalid, "99999999999999999999 is out of range");
}

TEST(LoaderHostileDescription, HugeAttributeGetsTheParsersFirstComplaint) {
    // 12 MB in one attribute is past libxml2's 10 MB limit for a value without XML_PARSE_HUGE; the
    // message must be that complaint, not the later "Extra content at the end of the document".
    const std::string xml =
        document("m", R"(description=")" + std::string(std::size_t{12} << 20, 'x') + R"(")", one_real);
    const LoaderError e = error_of(xml);
    EXPECT_EQ(e.code(), LoaderErrc::xml_parse) << e.what();
    EXPECT_EQ(std::string(e.what()).find("Extra content"), std::string::npos) << e.what();
    EXPECT_LT(std::string(e.what()).size(), 400u);
}

}  // namespace
