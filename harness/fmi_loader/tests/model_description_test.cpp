// modelDescription.xml parsing: every section, the FMI 2.0.4 defaults (section 2.2.7 table, written
// down here by hand from the standard), and refusal of malformed or entity-carrying documents.
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "fmi_loader/loader_error.hpp"
#include "fmi_loader/model_description.hpp"

using namespace fmi_loader;

namespace {

const char* const full_xml = R"xml(<?xml version="1.0" encoding="UTF-8"?>
<fmiModelDescription fmiVersion="2.0" modelName="Probe" guid="{abc}" numberOfEventIndicators="2"
    variableNamingConvention="structured" generationTool="hand">
  <ModelExchange modelIdentifier="probe_me" canGetAndSetFMUstate="true" completedIntegratorStepNotNeeded="1"/>
  <CoSimulation modelIdentifier="probe_cs" canHandleVariableCommunicationStepSize="true"
      canSerializeFMUstate="true" maxOutputDerivativeOrder="1"/>
  <UnitDefinitions>
    <Unit name="m/s"><BaseUnit m="1" s="-1"/><DisplayUnit name="km/h" factor="0.2777777777777778"/></Unit>
    <Unit name="rad"><BaseUnit rad="1"/></Unit>
  </UnitDefinitions>
  <TypeDefinitions>
    <SimpleType name="Speed"><Real unit="m/s" min="0" max="100" nominal="10"/></SimpleType>
    <SimpleType name="Mode"><Enumeration><Item name="off" value="1"/><Item name="on" value="2"/></Enumeration></SimpleType>
  </TypeDefinitions>
  <LogCategories><Category name="logAll" description="everything"/></LogCategories>
  <DefaultExperiment startTime="0" stopTime="4" stepSize="0.5"/>
  <ModelVariables>
    <ScalarVariable name="x" valueReference="0"><Real/></ScalarVariable>
    <ScalarVariable name="der(x)" valueReference="1"><Real derivative="1"/></ScalarVariable>
    <ScalarVariable name="k" valueReference="2" causality="parameter" variability="fixed"><Real start="1.5" unit="rad"/></ScalarVariable>
    <ScalarVariable name="u" valueReference="3" causality="input"><Real start="0" declaredType="Speed" max="50"/></ScalarVariable>
    <ScalarVariable name="y" valueReference="4" causality="output"><Real/></ScalarVariable>
    <ScalarVariable name="c" valueReference="5" causality="output" variability="constant"><Integer start="7"/></ScalarVariable>
    <ScalarVariable name="p" valueReference="6" causality="calculatedParameter" variability="fixed"><Real/></ScalarVariable>
    <ScalarVariable name="l" valueReference="7" variability="tunable"><Real/></ScalarVariable>
    <ScalarVariable name="t" valueReference="8" causality="independent"><Real/></ScalarVariable>
    <ScalarVariable name="m" valueReference="9" causality="parameter" variability="tunable"><Enumeration declaredType="Mode" start="2"/></ScalarVariable>
    <ScalarVariable name="b" valueReference="0" causality="output" variability="discrete" initial="exact"><Boolean start="true"/></ScalarVariable>
    <ScalarVariable name="s" valueReference="0" causality="parameter" variability="fixed"><String start="hi"/></ScalarVariable>
  </ModelVariables>
  <ModelStructure>
    <Outputs><Unknown index="5" dependencies="1 4" dependenciesKind="dependent fixed"/><Unknown index="6" dependencies=""/><Unknown index="11"/></Outputs>
    <Derivatives><Unknown index="2"/></Derivatives>
    <InitialUnknowns><Unknown index="2"/><Unknown index="5"/></InitialUnknowns>
  </ModelStructure>
</fmiModelDescription>
)xml";

}  // namespace

TEST(LoaderModelDescription, ParsesEverySection) {
    const ModelDescription md = parse_model_description(full_xml);
    EXPECT_EQ(md.fmi_version, "2.0");
    EXPECT_EQ(md.model_name, "Probe");
    EXPECT_EQ(md.guid, "{abc}");
    EXPECT_EQ(md.variable_naming_convention, "structured");
    EXPECT_EQ(md.number_of_event_indicators, 2u);
    ASSERT_TRUE(md.model_exchange && md.co_simulation);
    EXPECT_EQ(md.model_exchange->model_identifier, "probe_me");
    EXPECT_TRUE(md.model_exchange->can_get_and_set_fmu_state);
    EXPECT_FALSE(md.model_exchange->can_serialize_fmu_state);
    EXPECT_TRUE(md.model_exchange->completed_integrator_step_not_needed);
    EXPECT_EQ(md.co_simulation->model_identifier, "probe_cs");
    EXPECT_TRUE(md.co_simulation->can_handle_variable_communication_step_size);
    EXPECT_TRUE(md.co_simulation->can_serialize_fmu_state);
    EXPECT_FALSE(md.co_simulation->can_get_and_set_fmu_state);
    EXPECT_EQ(md.co_simulation->max_output_derivative_order, 1);

    ASSERT_EQ(md.unit_definitions.size(), 2u);
    ASSERT_TRUE(md.unit_definitions[0].base_unit);
    EXPECT_EQ(md.unit_definitions[0].base_unit->m, 1);
    EXPECT_EQ(md.unit_definitions[0].base_unit->s, -1);
    ASSERT_EQ(md.unit_definitions[0].display_units.size(), 1u);
    EXPECT_DOUBLE_EQ(md.unit_definitions[0].display_units[0].factor, 1.0 / 3.6);
    ASSERT_EQ(md.type_definitions.size(), 2u);
    EXPECT_EQ(md.type_definitions[1].items.size(), 2u);
    ASSERT_EQ(md.log_categories.size(), 1u);
    EXPECT_EQ(md.log_categories[0].name, "logAll");
    ASSERT_TRUE(md.default_experiment);
    EXPECT_EQ(md.default_experiment->stop_time, 4.0);
    EXPECT_EQ(md.default_experiment->step_size, 0.5);
    EXPECT_FALSE(md.default_experiment->tolerance);

    ASSERT_EQ(md.model_variables.size(), 12u);
    EXPECT_EQ(md.model_variables[1].derivative, 1u);
    EXPECT_EQ(md.model_variables[2].start_as_real(), 1.5);
    EXPECT_EQ(md.model_variables[2].unit, "rad");
    // u inherits unit/min/nominal from Speed and keeps its own max (section 2.2.3).
    const ScalarVariable& u = md.model_variables[3];
    EXPECT_EQ(u.declared_type, "Speed");
    EXPECT_EQ(u.unit, "m/s");
    EXPECT_EQ(u.min, 0.0);
    EXPECT_EQ(u.max, 50.0);
    EXPECT_EQ(u.nominal, 10.0);
    EXPECT_EQ(md.model_variables[5].type, VariableType::integer);
    EXPECT_EQ(md.model_variables[9].type, VariableType::enumeration);
    EXPECT_EQ(md.model_variables[10].start_as_boolean(), true);
    EXPECT_EQ(md.model_variables[11].start, "hi");

    ASSERT_EQ(md.model_structure.outputs.size(), 3u);
    EXPECT_EQ(md.model_structure.outputs[0].index, 5u);
    EXPECT_EQ(md.model_structure.outputs[0].dependencies, (std::vector<std::size_t>{1, 4}));
    EXPECT_EQ(md.model_structure.outputs[0].dependencies_kind, (std::vector<std::string>{"dependent", "fixed"}));
    // dependencies="" means "depends on nothing"; no attribute means "may depend on everything".
    ASSERT_TRUE(md.model_structure.outputs[1].dependencies);
    EXPECT_TRUE(md.model_structure.outputs[1].dependencies->empty());
    EXPECT_FALSE(md.model_structure.outputs[2].dependencies);
    EXPECT_EQ(md.number_of_continuous_states(), 1u);
    EXPECT_EQ(md.model_structure.initial_unknowns.size(), 2u);
}

TEST(LoaderModelDescription, AppliesStandardDefaults) {
    const ModelDescription md = parse_model_description(full_xml);
    auto var = [&](const char* name) { return *md.find_variable(name); };
    // No causality/variability given: local, continuous, hence initial calculated (case C).
    EXPECT_EQ(var("x").causality, Causality::local);
    EXPECT_EQ(var("x").variability, Variability::continuous);
    EXPECT_EQ(var("x").initial, Initial::calculated);
    EXPECT_FALSE(var("x").initial_given);
    EXPECT_EQ(var("k").initial, Initial::exact);       // parameter fixed: case A
    EXPECT_EQ(var("u").initial, Initial::none);        // input: case D, no initial
    EXPECT_EQ(var("y").initial, Initial::calculated);  // output continuous: case C
    EXPECT_EQ(var("c").initial, Initial::exact);       // output constant: case A
    EXPECT_EQ(var("p").initial, Initial::calculated);  // calculatedParameter: case B
    EXPECT_EQ(var("l").initial, Initial::calculated);  // local tunable: case B
    EXPECT_EQ(var("t").initial, Initial::none);        // independent: case E
    EXPECT_EQ(var("b").initial, Initial::exact);       // explicit
    EXPECT_TRUE(var("b").initial_given);
}

TEST(LoaderModelDescription, CombinationTableMatchesStandard) {
    // The eleven invalid combinations (a)-(e) of the section 2.2.7 table.
    EXPECT_FALSE(is_valid_combination(Causality::parameter, Variability::constant));
    EXPECT_FALSE(is_valid_combination(Causality::parameter, Variability::discrete));
    EXPECT_FALSE(is_valid_combination(Causality::parameter, Variability::continuous));
    EXPECT_FALSE(is_valid_combination(Causality::calculated_parameter, Variability::constant));
    EXPECT_FALSE(is_valid_combination(Causality::calculated_parameter, Variability::continuous));
    EXPECT_FALSE(is_valid_combination(Causality::input, Variability::constant));
    EXPECT_FALSE(is_valid_combination(Causality::input, Variability::fixed));
    EXPECT_FALSE(is_valid_combination(Causality::output, Variability::tunable));
    EXPECT_FALSE(is_valid_combination(Causality::independent, Variability::constant));
    EXPECT_FALSE(is_valid_combination(Causality::independent, Variability::discrete));
    EXPECT_TRUE(is_valid_combination(Causality::local, Variability::tunable));
    EXPECT_TRUE(is_allowed_initial(Causality::output, Variability::continuous, Initial::approx));
    EXPECT_FALSE(is_allowed_initial(Causality::parameter, Variability::fixed, Initial::calculated));
    EXPECT_FALSE(is_allowed_initial(Causality::local, Variability::fixed, Initial::exact));
    EXPECT_FALSE(is_allowed_initial(Causality::input, Variability::continuous, Initial::exact));
}

TEST(LoaderModelDescription, MalformedXmlIsRefusedWithLine) {
    const std::string xml = "<?xml version=\"1.0\"?>\n<fmiModelDescription fmiVersion=\"2.0\"\n  <broken";
    try {
        parse_model_description(xml, "bad.xml");
        FAIL() << "accepted malformed XML";
    } catch (const LoaderError& e) {
        EXPECT_EQ(e.code(), LoaderErrc::xml_parse);
        EXPECT_NE(std::string(e.what()).find("bad.xml"), std::string::npos) << e.what();
    }
}

TEST(LoaderModelDescription, ExternalEntityIsRefused) {
    // Were the entity expanded, /etc/hostname would end up in modelName.
    const std::string xml = R"(<?xml version="1.0"?>
<!DOCTYPE fmiModelDescription [ <!ENTITY leak SYSTEM "file:///etc/hostname"> ]>
<fmiModelDescription fmiVersion="2.0" modelName="&leak;" guid="g"><CoSimulation modelIdentifier="m"/></fmiModelDescription>)";
    try {
        parse_model_description(xml, "xxe.xml");
        FAIL() << "accepted a document with an external entity";
    } catch (const LoaderError& e) {
        // libxml2 already rejects an external entity in an attribute (xml_parse); anywhere else
        // the DOCTYPE refusal catches it (xml_invalid). Either way the file is never read.
        EXPECT_TRUE(e.code() == LoaderErrc::xml_parse || e.code() == LoaderErrc::xml_invalid) << e.what();
        EXPECT_NE(std::string(e.what()).find("xxe.xml"), std::string::npos) << e.what();
    }
    const std::string in_text = R"(<?xml version="1.0"?>
<!DOCTYPE fmiModelDescription [ <!ENTITY leak SYSTEM "file:///etc/hostname"> ]>
<fmiModelDescription fmiVersion="2.0" modelName="m" guid="g"><CoSimulation modelIdentifier="m"/><VendorAnnotations>&leak;</VendorAnnotations></fmiModelDescription>)";
    try {
        parse_model_description(in_text, "xxe2.xml");
        FAIL() << "accepted a document with an external entity in element content";
    } catch (const LoaderError& e) {
        EXPECT_EQ(e.code(), LoaderErrc::xml_invalid) << e.what();
    }
}

TEST(LoaderModelDescription, ExternalDtdIsNeitherFetchedNorAccepted) {
    // A non-routable address: a fetch attempt would hang for the connect timeout or fail slowly.
    const std::string xml = R"(<?xml version="1.0"?>
<!DOCTYPE fmiModelDescription SYSTEM "http://10.255.255.1/fmi.dtd">
<fmiModelDescription fmiVersion="2.0" modelName="m" guid="g"><CoSimulation modelIdentifier="m"/></fmiModelDescription>)";
    const auto begin = std::chrono::steady_clock::now();
    EXPECT_THROW(parse_model_description(xml, "dtd.xml"), LoaderError);
    // Not a speed target: any network attempt takes seconds, parsing takes microseconds.
    EXPECT_LT(std::chrono::steady_clock::now() - begin, std::chrono::seconds(2));
}

TEST(LoaderModelDescription, EntityExpansionBombIsRefused) {
    const std::string xml = R"(<?xml version="1.0"?>
<!DOCTYPE fmiModelDescription [ <!ENTITY a "aaaaaaaaaa"> <!ENTITY b "&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;">
  <!ENTITY c "&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;"> ]>
<fmiModelDescription fmiVersion="2.0" modelName="&c;" guid="g"><CoSimulation modelIdentifier="m"/></fmiModelDescription>)";
    EXPECT_THROW(parse_model_description(xml), LoaderError);
}

TEST(LoaderModelDescription, SchemaViolationsAreRefused) {
    auto code_of = [](const std::string& xml) {
        try {
            parse_model_description(xml);
        } catch (const LoaderError& e) {
            return e.code();
        }
        return LoaderErrc::archive_open;  // marks "no exception"
    };
    const std::string head =
        R"(<fmiModelDescription fmiVersion="2.0" modelName="m" guid="g"><CoSimulation modelIdentifier="m"/>)";
    EXPECT_EQ(
        code_of(
            R"(<fmiModelDescription fmiVersion="2.0" modelName="m"><CoSimulation modelIdentifier="m"/></fmiModelDescription>)"),
        LoaderErrc::xml_invalid);  // no guid
    EXPECT_EQ(
        code_of(
            R"(<fmiModelDescription fmiVersion="3.0" modelName="m" guid="g"><CoSimulation modelIdentifier="m"/></fmiModelDescription>)"),
        LoaderErrc::xml_invalid);
    EXPECT_EQ(code_of(R"(<fmiModelDescription fmiVersion="2.0" modelName="m" guid="g"/>)"), LoaderErrc::xml_invalid);
    EXPECT_EQ(
        code_of(
            head +
            R"(<ModelVariables><ScalarVariable name="a" valueReference="1" causality="sideways"><Real/></ScalarVariable></ModelVariables></fmiModelDescription>)"),
        LoaderErrc::xml_invalid);
    EXPECT_EQ(
        code_of(
            head +
            R"(<ModelVariables><ScalarVariable name="a" valueReference="1"/></ModelVariables></fmiModelDescription>)"),
        LoaderErrc::xml_invalid);  // no type element
    EXPECT_EQ(
        code_of(
            head +
            R"(<ModelVariables><ScalarVariable name="a" valueReference="1"><Real declaredType="Nope"/></ScalarVariable></ModelVariables></fmiModelDescription>)"),
        LoaderErrc::xml_invalid);
    EXPECT_EQ(
        code_of(head +
                R"(<ModelStructure><Outputs><Unknown index="0"/></Outputs></ModelStructure></fmiModelDescription>)"),
        LoaderErrc::xml_invalid);
}
