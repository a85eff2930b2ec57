// FMI 3.0 modelDescription.xml parsing: the types, arrays with fixed and structural dimensions, the
// interface elements with their capability flags, the ModelStructure (value references turned into
// indices) and the FMI 3.0 defaults. The expected values are read by hand off the XML below and the
// FMI 3.0.2 standard's tables (section 2.4.7.4), not produced by the reader.
#include <gtest/gtest.h>

#include <string>

#include "fmi_loader/loader_error.hpp"
#include "fmi_loader/model_description.hpp"

using namespace fmi_loader;

namespace {

const char* const fmi3_xml = R"xml(<?xml version="1.0" encoding="UTF-8"?>
<fmiModelDescription fmiVersion="3.0" modelName="Probe3" instantiationToken="{tok}" generationTool="hand">
  <ModelExchange modelIdentifier="probe3" canGetAndSetFMUState="true" needsCompletedIntegratorStep="true"
      providesEvaluateDiscreteStates="true"/>
  <CoSimulation modelIdentifier="probe3" canHandleVariableCommunicationStepSize="true" hasEventMode="true"
      canReturnEarlyAfterIntermediateUpdate="true" providesIntermediateUpdate="true" fixedInternalStepSize="0.01"
      canSerializeFMUState="true"/>
  <UnitDefinitions><Unit name="m"><BaseUnit m="1"/></Unit></UnitDefinitions>
  <TypeDefinitions>
    <Float64Type name="Length" unit="m" min="0" nominal="2"/>
    <EnumerationType name="Mode"><Item name="off" value="1"/><Item name="on" value="2" description="running"/></EnumerationType>
  </TypeDefinitions>
  <DefaultExperiment startTime="0" stopTime="3" stepSize="0.1"/>
  <ModelVariables>
    <Float64 name="time" valueReference="0" causality="independent" variability="continuous"/>
    <UInt64 name="n" valueReference="7" causality="structuralParameter" variability="tunable" start="3"/>
    <Float64 name="x" valueReference="11" declaredType="Length"><Dimension valueReference="7"/></Float64>
    <Float64 name="der(x)" valueReference="12" derivative="11"><Dimension valueReference="7"/></Float64>
    <Float32 name="u" valueReference="3" causality="input" start="0.5"/>
    <Int8 name="i8" valueReference="4" causality="output"/>
    <UInt16 name="m" valueReference="5" causality="parameter" start="1 2 3 4 5 6"><Dimension start="2"/><Dimension start="3"/></UInt16>
    <Boolean name="b" valueReference="6" causality="output"/>
    <String name="s" valueReference="8" causality="parameter"><Start value="hello"/></String>
    <Binary name="bin" valueReference="9" causality="input" maxSize="4"><Start value="0a0b"/></Binary>
    <Enumeration name="mode" valueReference="10" declaredType="Mode" causality="parameter" variability="tunable" start="2"/>
    <Float64 name="h" valueReference="13" causality="output" unit="m"/>
    <Float64 name="k" valueReference="14" causality="calculatedParameter"/>
    <Float64 name="z" valueReference="15"/>
  </ModelVariables>
  <ModelStructure>
    <Output valueReference="4" dependencies="3 11" dependenciesKind="dependent fixed"/>
    <Output valueReference="6" dependencies=""/>
    <Output valueReference="13"/>
    <ContinuousStateDerivative valueReference="12"/>
    <InitialUnknown valueReference="11"/>
    <EventIndicator valueReference="15"/>
  </ModelStructure>
</fmiModelDescription>
)xml";

std::string with(std::string xml, const std::string& from, const std::string& to) {
    const auto at = xml.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return xml.replace(at, from.size(), to);
}

std::string error_of(const std::string& xml) {
    try {
        parse_model_description(xml, "probe3.xml");
    } catch (const LoaderError& e) {
        EXPECT_EQ(e.code(), LoaderErrc::xml_invalid);
        return e.what();
    }
    return "";
}

}  // namespace

TEST(LoaderModelDescription3, ReadsTheHeaderAndInterfaces) {
    const ModelDescription md = parse_model_description(fmi3_xml);
    EXPECT_TRUE(md.is_fmi3());
    EXPECT_EQ(md.model_name, "Probe3");
    EXPECT_EQ(md.guid, "{tok}");  // instantiationToken
    ASSERT_TRUE(md.model_exchange && md.co_simulation);
    EXPECT_FALSE(md.scheduled_execution);
    EXPECT_TRUE(md.model_exchange->can_get_and_set_fmu_state);
    EXPECT_FALSE(md.model_exchange->completed_integrator_step_not_needed);
    EXPECT_TRUE(md.model_exchange->provides_evaluate_discrete_states);
    const auto& cs = *md.co_simulation;
    EXPECT_TRUE(cs.has_event_mode);
    EXPECT_TRUE(cs.can_return_early_after_intermediate_update);
    EXPECT_TRUE(cs.provides_intermediate_update);
    EXPECT_FALSE(cs.might_return_early_from_do_step);
    EXPECT_TRUE(cs.can_serialize_fmu_state);
    EXPECT_FALSE(cs.can_get_and_set_fmu_state);
    EXPECT_EQ(cs.fixed_internal_step_size, 0.01);
    ASSERT_TRUE(md.default_experiment);
    EXPECT_EQ(md.default_experiment->step_size, 0.1);
}

TEST(LoaderModelDescription3, TypesKeepTheirNameAndTheirBaseKind) {
    const ModelDescription md = parse_model_description(fmi3_xml);
    const auto type_of = [&](const char* name) {
        const ScalarVariable* v = md.find_variable(name);
        EXPECT_TRUE(v && v->fmi3_type) << name;
        return std::pair{*v->fmi3_type, v->type};
    };
    EXPECT_EQ(type_of("u"), std::pair(Fmi3Type::float32, VariableType::real));
    EXPECT_EQ(type_of("i8"), std::pair(Fmi3Type::int8, VariableType::integer));
    EXPECT_EQ(type_of("m"), std::pair(Fmi3Type::uint16, VariableType::integer));
    EXPECT_EQ(type_of("n"), std::pair(Fmi3Type::uint64, VariableType::integer));
    EXPECT_EQ(type_of("b"), std::pair(Fmi3Type::boolean, VariableType::boolean));
    EXPECT_EQ(type_of("s"), std::pair(Fmi3Type::string, VariableType::string));
    EXPECT_EQ(type_of("bin"), std::pair(Fmi3Type::binary, VariableType::string));
    EXPECT_EQ(type_of("mode"), std::pair(Fmi3Type::enumeration, VariableType::enumeration));
    EXPECT_EQ(to_string(Fmi3Type::uint16), "UInt16");

    const SimpleType* mode = md.find_type("Mode");
    ASSERT_NE(mode, nullptr);
    EXPECT_EQ(mode->fmi3_type, Fmi3Type::enumeration);
    ASSERT_EQ(mode->items.size(), 2u);
    EXPECT_EQ(mode->items[1].name, "on");
    EXPECT_EQ(mode->items[1].value, 2);
    // Inherited from Float64Type "Length".
    const ScalarVariable* x = md.find_variable("x");
    EXPECT_EQ(x->unit, "m");
    EXPECT_EQ(x->min, 0.0);
    EXPECT_EQ(x->nominal, 2.0);
}

TEST(LoaderModelDescription3, StartValuesAndBinaryAttributes) {
    const ModelDescription md = parse_model_description(fmi3_xml);
    EXPECT_EQ(md.find_variable("u")->start_as_real(), 0.5);
    EXPECT_EQ(md.find_variable("s")->start, "hello");
    const ScalarVariable* bin = md.find_variable("bin");
    ASSERT_EQ(bin->start_values.size(), 1u);
    EXPECT_EQ(bin->start_values[0], "0a0b");
    EXPECT_EQ(bin->max_size, 4u);
    EXPECT_EQ(bin->mime_type, "application/octet-stream");   // the schema's default
    EXPECT_EQ(md.find_variable("m")->start, "1 2 3 4 5 6");  // an array's start stays one list
}

TEST(LoaderModelDescription3, ArraysCountTheirElements) {
    const ModelDescription md = parse_model_description(fmi3_xml);
    const ScalarVariable* x = md.find_variable("x");
    ASSERT_EQ(x->dimensions.size(), 1u);
    EXPECT_EQ(x->dimensions[0].value_reference, 7u);
    EXPECT_EQ(md.element_count(*x), 3u);  // n's start
    const ScalarVariable* m = md.find_variable("m");
    EXPECT_EQ(md.extents(*m), (std::vector<std::size_t>{2, 3}));
    EXPECT_EQ(md.element_count(*m), 6u);
    EXPECT_EQ(md.element_count(*md.find_variable("u")), 1u);
    // One ContinuousStateDerivative of 3 elements is 3 states.
    EXPECT_EQ(md.number_of_continuous_states(), 3u);
    EXPECT_EQ(md.number_of_event_indicators, 1u);
}

// Section 2.4.7.4: variability defaults to fixed for parameters, continuous for Float, discrete for the
// rest; initial defaults to exact for inputs and parameters, calculated for outputs and locals.
TEST(LoaderModelDescription3, DefaultsFollowTheFmi3Tables) {
    const ModelDescription md = parse_model_description(fmi3_xml);
    const auto* u = md.find_variable("u");
    EXPECT_EQ(u->causality, Causality::input);
    EXPECT_EQ(u->variability, Variability::continuous);
    EXPECT_EQ(u->initial, Initial::exact);
    const auto* i8 = md.find_variable("i8");
    EXPECT_EQ(i8->variability, Variability::discrete);
    EXPECT_EQ(i8->initial, Initial::calculated);
    const auto* k = md.find_variable("k");
    EXPECT_EQ(k->variability, Variability::fixed);
    EXPECT_EQ(k->initial, Initial::calculated);
    EXPECT_EQ(md.find_variable("m")->variability, Variability::fixed);
    EXPECT_EQ(md.find_variable("m")->initial, Initial::exact);
    EXPECT_EQ(md.find_variable("n")->causality, Causality::structural_parameter);
    EXPECT_EQ(md.find_variable("z")->causality, Causality::local);
    EXPECT_EQ(md.find_variable("z")->variability, Variability::continuous);
}

TEST(LoaderModelDescription3, ModelStructureReferencesBecomeIndices) {
    const ModelDescription md = parse_model_description(fmi3_xml);
    const auto& s = md.model_structure;
    ASSERT_EQ(s.outputs.size(), 3u);
    // vr 4 is the 6th variable; its dependencies vr 3 (u, 5th) and vr 11 (x, 3rd).
    EXPECT_EQ(s.outputs[0].index, 6u);
    ASSERT_TRUE(s.outputs[0].dependencies);
    EXPECT_EQ(*s.outputs[0].dependencies, (std::vector<std::size_t>{5, 3}));
    EXPECT_EQ(s.outputs[0].dependencies_kind, (std::vector<std::string>{"dependent", "fixed"}));
    ASSERT_TRUE(s.outputs[1].dependencies);
    EXPECT_TRUE(s.outputs[1].dependencies->empty());
    EXPECT_FALSE(s.outputs[2].dependencies);
    ASSERT_EQ(s.derivatives.size(), 1u);
    EXPECT_EQ(s.derivatives[0].index, 4u);
    // derivative="11" (x's reference) is turned into x's index.
    EXPECT_EQ(md.find_variable("der(x)")->derivative, 3u);
    ASSERT_EQ(s.event_indicators.size(), 1u);
    EXPECT_EQ(s.event_indicators[0].index, 14u);  // z, the 14th variable
    ASSERT_EQ(s.initial_unknowns.size(), 1u);
}

TEST(LoaderModelDescription3, ScheduledExecutionIsReadSoItCanBeNamed) {
    const auto md = parse_model_description(
        with(fmi3_xml, "<DefaultExperiment", "<ScheduledExecution modelIdentifier=\"probe3\"/>\n  <DefaultExperiment"));
    ASSERT_TRUE(md.scheduled_execution);
    EXPECT_EQ(md.scheduled_execution->model_identifier, "probe3");
}

TEST(LoaderModelDescription3, BrokenDescriptionsAreRefusedWithTheCause) {
    EXPECT_NE(
        error_of(with(fmi3_xml, "valueReference=\"15\"/>", "valueReference=\"14\"/>")).find("share valueReference 14"),
        std::string::npos);
    EXPECT_NE(error_of(with(fmi3_xml, "<Dimension valueReference=\"7\"/></Float64>\n    <Float64 name=\"der(x)\"",
                            "<Dimension valueReference=\"3\"/></Float64>\n    <Float64 name=\"der(x)\""))
                  .find("not a UInt64 structural parameter"),
              std::string::npos);
    EXPECT_NE(
        error_of(with(fmi3_xml, "<EventIndicator valueReference=\"15\"/>", "<EventIndicator valueReference=\"99\"/>"))
            .find("valueReference 99 names no variable"),
        std::string::npos);
    EXPECT_NE(error_of(with(fmi3_xml, "<Int8 name=\"i8\" valueReference=\"4\" causality=\"output\"/>",
                            "<Int8 name=\"i8\" valueReference=\"4\" causality=\"output\" variability=\"continuous\"/>"))
                  .find("only Float32 and Float64 may be continuous"),
              std::string::npos);
    EXPECT_NE(error_of(with(fmi3_xml, "instantiationToken", "guid")).find("instantiationToken"), std::string::npos);
    EXPECT_NE(error_of(with(fmi3_xml, "<Float32 name=\"u\"", "<Float16 name=\"u\"")).find("unknown variable element"),
              std::string::npos);
    EXPECT_NE(error_of(with(fmi3_xml, "fmiVersion=\"3.0\"", "fmiVersion=\"4.0\"")).find("neither 2.x nor 3.x"),
              std::string::npos);
}

TEST(LoaderModelDescription3, StructuralParameterIsNoFmi2Causality) {
    const std::string fmi2 = R"xml(<fmiModelDescription fmiVersion="2.0" modelName="a" guid="g">
  <CoSimulation modelIdentifier="a"/>
  <ModelVariables><ScalarVariable name="n" valueReference="0" causality="structuralParameter"><Integer/></ScalarVariable></ModelVariables>
</fmiModelDescription>)xml";
    EXPECT_NE(error_of(fmi2).find("unknown causality 'structuralParameter'"), std::string::npos);
}

// Issue 38: an array's size from a file is checked, never cast or multiplied unchecked. Two dimensions
// whose product wraps 64 bits (2^32 x 2^32 + 2 elements would be 2 after the wrap) and a structural
// parameter whose start is not a whole UInt64 are refused, naming the variable.
TEST(LoaderModelDescription3, ArraySizesAreCheckedNotWrappedNorCast) {
    const auto bad_start = [](const std::string& start) {
        return error_of(with(fmi3_xml, "causality=\"structuralParameter\" variability=\"tunable\" start=\"3\"",
                             "causality=\"structuralParameter\" variability=\"tunable\" start=\"" + start + "\""));
    };
    for (const char* start : {"1e30", "abc", "-5"}) {
        const auto message = bad_start(start);
        EXPECT_NE(message.find("refers to 'n', whose start"), std::string::npos) << start << ": " << message;
        EXPECT_NE(message.find("UInt64 array size"), std::string::npos) << start << ": " << message;
    }
    // 2^32 * (2^32 + 1) wraps to 2^32; 2^33 * 2^31 wraps to 0: each refused by the element limit.
    for (const auto& [a, b] : {std::pair{"4294967296", "4294967297"}, std::pair{"8589934592", "2147483648"}}) {
        std::string message;
        try {
            parse_model_description(
                with(fmi3_xml, "<Dimension start=\"2\"/><Dimension start=\"3\"/>",
                     std::string("<Dimension start=\"") + a + "\"/><Dimension start=\"" + b + "\"/>"),
                "probe3.xml");
        } catch (const LoaderError& e) {
            EXPECT_EQ(e.code(), LoaderErrc::limit);
            message = e.what();
        }
        EXPECT_NE(message.find("the array 'm' has more than the limit of"), std::string::npos) << message;
        EXPECT_NE(message.find("(max_variables)"), std::string::npos) << message;
    }
    // Within the limit, the sizes are as written (2 x 3 = 6; n = 3 with blanks around it).
    const auto md = parse_model_description(
        with(fmi3_xml, "variability=\"tunable\" start=\"3\"", "variability=\"tunable\" start=\" 3 \""));
    EXPECT_EQ(md.element_count(*md.find_variable("m")), 6u);
    EXPECT_EQ(md.element_count(*md.find_variable("x")), 3u);
}
