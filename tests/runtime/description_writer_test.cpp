// What the description writer emits is what an importer reads: the generated XML of the test ball,
// parsed by the master's loader, states every variable of the table with the same attributes.
#include <gtest/gtest.h>

#include "description_xml.hpp"
#include "documentation_html.hpp"
#include "fmi_loader/model_description.hpp"
#include "fmu/description.hpp"
#include "fmu/value_access.hpp"
#include "test_blocks.hpp"

FMU_BLOCK(fmu_test::Ball)

namespace {

TEST(Description, ParsedXmlMatchesTheTable) {
    const auto model = fmu::make_model();
    const auto md = fmi_loader::parse_model_description(fmu::model_description_xml(*model));
    const auto& vars = model->table().variables();
    ASSERT_EQ(md.model_variables.size(), vars.size());
    EXPECT_EQ(md.guid, fmu::description_guid(*model));
    EXPECT_EQ(md.variable_naming_convention, "structured");
    EXPECT_EQ(md.number_of_event_indicators, 1u);
    ASSERT_TRUE(md.model_exchange && md.co_simulation);
    EXPECT_TRUE(md.co_simulation->can_serialize_fmu_state);
    for (std::size_t i = 0; i < vars.size(); ++i) {
        const auto& v = vars[i];
        const auto& p = md.model_variables[i];
        EXPECT_EQ(p.name, v.name);
        EXPECT_EQ(p.value_reference, v.value_reference);
        EXPECT_EQ(fmi_loader::to_string(p.causality), fmu::to_string(v.causality)) << v.name;
        EXPECT_EQ(fmi_loader::to_string(p.variability), fmu::to_string(v.variability)) << v.name;
        EXPECT_EQ(p.start.has_value(), v.has_start()) << v.name;
        EXPECT_EQ(p.unit, v.type == fmu::ValueType::Real ? v.unit : "") << v.name;
    }
    EXPECT_EQ(*md.find_variable("g")->start_as_real(), 9.81);
    EXPECT_EQ(*md.find_variable("label")->start, "ball");
    // A choice is an Enumeration with its items in a type definition (FMI 2.0 section 2.2.3).
    const auto* material = md.find_variable("material");
    ASSERT_NE(material, nullptr);
    EXPECT_EQ(material->type, fmi_loader::VariableType::enumeration);
    EXPECT_EQ(material->declared_type, "Material");
    EXPECT_EQ(*material->start, "1");
    const auto* type = md.find_type("Material");
    ASSERT_NE(type, nullptr);
    ASSERT_EQ(type->items.size(), 2u);
    EXPECT_EQ(type->items[0].name, "rubber");
    EXPECT_EQ(type->items[0].value, 1);
    EXPECT_EQ(type->items[1].name, "steel");
    EXPECT_EQ(type->items[1].value, 2);
    // States h, v in declaration order; der(h) depends on v only (1-based indices).
    ASSERT_EQ(md.model_structure.derivatives.size(), 2u);
    const auto& der_h = md.model_structure.derivatives[0];
    EXPECT_EQ(md.model_variables[der_h.index - 1].name, "der(h)");
    ASSERT_TRUE(der_h.dependencies);
    EXPECT_EQ(*der_h.dependencies, std::vector<std::size_t>{model->table().index_of("v") + 1});
    EXPECT_EQ(*md.model_variables[der_h.index - 1].derivative, model->table().index_of("h") + 1);
    // The output y depends on the input u and nothing else.
    for (const auto& out : md.model_structure.outputs) {
        if (md.model_variables[out.index - 1].name == "y") {
            EXPECT_EQ(*out.dependencies, std::vector<std::size_t>{model->table().index_of("u") + 1});
        }
    }
}

TEST(Description, GuidChangesWithTheDescription) {
    auto a = fmu::make_model();
    auto b = fmu::make_model();
    EXPECT_EQ(fmu::description_guid(*a), fmu::description_guid(*b));  // same description, same GUID
    // The fingerprint covers the start values: a different default changes it.
    const auto& g = a->table().by_name("g");
    const std::string before = fmu::description_fingerprint(*a);
    fmu::write_real(a->bytes(), g, 1.62);  // the instance's value is not the default: no change
    EXPECT_EQ(fmu::description_fingerprint(*a), before);
}

TEST(Description, DocumentationListsEveryVariable) {
    const auto model = fmu::make_model();
    const std::string html = fmu::documentation_html(*model);
    for (const auto& v : model->table().variables()) EXPECT_NE(html.find(v.name), std::string::npos) << v.name;
}

TEST(Description, DocumentationGivesEachEnumerationItemItsNumber) {
    // The test ball's material: rubber = 1 (its default), steel = 2 (fmus/tests/test_blocks.hpp). FMPy
    // and fmi2SetInteger take the number, so the page gives it beside the name.
    const std::string html = fmu::documentation_html(*fmu::make_model());
    EXPECT_NE(html.find("rubber = 1, steel = 2"), std::string::npos);
    EXPECT_NE(html.find("rubber (1)"), std::string::npos);
}

}  // namespace
