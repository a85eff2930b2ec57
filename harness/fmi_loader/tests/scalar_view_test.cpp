// scalar_view: FMI 3.0 arrays as one scalar per element. The names, start values, references and the
// re-indexed ModelStructure below are worked out by hand from the XML.
#include <gtest/gtest.h>

#include "fmi_loader/loader_error.hpp"
#include "fmi_loader/scalar_view.hpp"

using namespace fmi_loader;

namespace {

const char* const arrays_xml = R"xml(<fmiModelDescription fmiVersion="3.0" modelName="A" instantiationToken="t">
  <ModelExchange modelIdentifier="a"/>
  <ModelVariables>
    <Float64 name="time" valueReference="0" causality="independent" variability="continuous"/>
    <UInt64 name="n" valueReference="1" causality="structuralParameter" start="2"/>
    <Float64 name="M" valueReference="2" causality="parameter" start="1 2 3 4 5 6"><Dimension valueReference="1"/><Dimension start="3"/></Float64>
    <Float64 name="x" valueReference="3" start="7"><Dimension valueReference="1"/></Float64>
    <Float64 name="der(x)" valueReference="4" derivative="3"><Dimension valueReference="1"/></Float64>
    <Float32 name="u" valueReference="5" causality="input" start="0"/>
    <Int32 name="y" valueReference="6" causality="output"><Dimension start="2"/></Int32>
  </ModelVariables>
  <ModelStructure>
    <Output valueReference="6" dependencies="5 3"/>
    <ContinuousStateDerivative valueReference="4"/>
  </ModelStructure>
</fmiModelDescription>)xml";

}  // namespace

TEST(LoaderScalarView, ArraysBecomeNamedElementsInRowMajorOrder) {
    const ModelDescription md = parse_model_description(arrays_xml);
    const ScalarView view = scalar_view(md);
    const auto& vars = view.description.model_variables;
    // time, n, M (2x3 = 6), x (2), der(x) (2), u, y (2): 15 scalars.
    ASSERT_EQ(vars.size(), 15u);
    EXPECT_EQ(vars[2].name, "M[1,1]");
    EXPECT_EQ(vars[4].name, "M[1,3]");
    EXPECT_EQ(vars[5].name, "M[2,1]");
    EXPECT_EQ(vars[7].name, "M[2,3]");
    EXPECT_EQ(vars[5].start, "4");
    EXPECT_EQ(vars[8].name, "x[1]");
    EXPECT_EQ(vars[9].start, "7");  // one start value for every element
    EXPECT_EQ(vars[12].name, "u");
    for (std::size_t i = 0; i < vars.size(); ++i) EXPECT_EQ(vars[i].value_reference, i);
    const ScalarElement& m21 = view.elements[5];
    EXPECT_EQ(m21.value_reference, 2u);
    EXPECT_EQ(m21.offset, 3u);
    EXPECT_EQ(m21.count, 6u);
    EXPECT_EQ(view.elements[12].count, 1u);
    EXPECT_EQ(view.elements[12].type, Fmi3Type::float32);
    EXPECT_EQ(view.first_element[6], 13u);  // y
}

TEST(LoaderScalarView, StructureAndDerivativesFollowTheElements) {
    const ScalarView view = scalar_view(parse_model_description(arrays_xml));
    const auto& vars = view.description.model_variables;
    EXPECT_EQ(vars[10].derivative, 9u);  // der(x)[1] is the derivative of x[1], the 9th scalar
    EXPECT_EQ(vars[11].derivative, 10u);
    const auto& s = view.description.model_structure;
    ASSERT_EQ(s.derivatives.size(), 2u);
    EXPECT_EQ(s.derivatives[1].index, 12u);
    ASSERT_EQ(s.outputs.size(), 2u);
    EXPECT_EQ(s.outputs[0].index, 14u);
    EXPECT_EQ(s.outputs[1].index, 15u);
    ASSERT_TRUE(s.outputs[1].dependencies);
    // u (13th) and both elements of x (9th, 10th).
    EXPECT_EQ(*s.outputs[1].dependencies, (std::vector<std::size_t>{13, 9, 10}));
    EXPECT_EQ(view.description.number_of_continuous_states(), 2u);
}

TEST(LoaderScalarView, AStartListOfTheWrongLengthIsRefused) {
    std::string xml = arrays_xml;
    xml.replace(xml.find("1 2 3 4 5 6"), 11, "1 2 3 4 5");
    const ModelDescription md = parse_model_description(xml);
    try {
        scalar_view(md);
        FAIL() << "accepted 5 start values for 6 elements";
    } catch (const LoaderError& e) {
        EXPECT_NE(std::string(e.what()).find("'M' has 6 elements but 5 start values"), std::string::npos) << e.what();
    }
}
