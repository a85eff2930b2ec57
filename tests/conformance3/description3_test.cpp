// The FMI 3.0 descriptions: valid against the standard's schemas, and the same table as the FMI 2.0
// archive's (each 3.0 array is the 2.0 elements name[1] ... name[N], with their value references and
// start values; nothing more, nothing less, besides time and the event indicators).
#include <map>

#include "fixture3.hpp"
#include "xml_schema.hpp"

namespace {

CONFORMANCE3_SUITE(Conformance3Description);

TEST_P(Conformance3Description, ValidatesAgainstTheFmi3Schema) {
    const auto schema = std::filesystem::path(FMI3_SCHEMA_DIR) / "fmi3ModelDescription.xsd";
    EXPECT_EQ(test_support::xml_schema_errors(schema, fmu3().archive().model_description_path()), "");
}

// The element name of array element i: "mag_body[2]", "der(b_filt[2])".
std::string element_name(const conformance3::Variable3& v, std::size_t i) {
    const std::string index = "[" + std::to_string(i + 1) + "]";
    if (v.name.rfind("der(", 0) == 0) return v.name.substr(0, v.name.size() - 1) + index + ")";
    return v.name + index;
}

TEST_P(Conformance3Description, IsTheFmi2ArchivesTableWithArrays) {
    const auto& md2 = fmu2().description();
    std::size_t elements = 0;
    for (const auto& v : md().variables) {
        if (v.causality == "independent" || v.name == "event_indicators") continue;
        for (std::size_t i = 0; i < v.count; ++i) {
            const std::string name = v.array ? element_name(v, i) : v.name;
            const auto* v2 = md2.find_variable(name);
            ASSERT_NE(v2, nullptr) << name << " is not in the FMI 2.0 archive";
            EXPECT_EQ(v2->value_reference, v.value_reference + i) << name;
            EXPECT_EQ(std::string(fmi_loader::to_string(v2->causality)), v.causality) << name;
            if (v2->start) {
                ASSERT_EQ(v.start.size(), v.count) << name;
                EXPECT_EQ(*v2->start, v.start[i]) << name;
            } else {
                EXPECT_TRUE(v.start.empty()) << name;
            }
            ++elements;
        }
    }
    EXPECT_EQ(elements, md2.model_variables.size());
    std::size_t independents = 0;
    for (const auto& v : md().variables) independents += v.causality == "independent";
    EXPECT_EQ(independents, 1u);
    EXPECT_EQ(md().count_of(md().event_indicators), md2.number_of_event_indicators);
    EXPECT_EQ(md().count_of(md().derivatives), md2.number_of_continuous_states());
}

}  // namespace
