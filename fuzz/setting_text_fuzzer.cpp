// The text the C API's setters take (pvatt_system_set, pvatt_simulation_set_text, pvatt_campaign_run's
// settings) as the engine reads it: "component.variable=value" split, the variable looked up, the value
// parsed for its type (a choice by name or number) and checked against its type and range, as
// pvatt_simulation_set_text does before the FMU sees it. Any bytes give a value or a CosimError.
// (The C API itself needs an FMU binary to open a system; this target runs its text path on a
// description with one variable of each type.)
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <variant>

#include "engine/cosim_error.hpp"
#include "engine/setting.hpp"
#include "engine/value_text.hpp"
#include "fmi_loader/model_description.hpp"

namespace {

const fmi_loader::ModelDescription& description() {
    static const auto md = fmi_loader::parse_model_description(R"(<?xml version="1.0" encoding="UTF-8"?>
<fmiModelDescription fmiVersion="2.0" modelName="gain" guid="{g}">
  <ModelExchange modelIdentifier="gain"/>
  <TypeDefinitions>
    <SimpleType name="Sign"><Enumeration><Item name="plus" value="1"/><Item name="minus" value="2"/></Enumeration></SimpleType>
  </TypeDefinitions>
  <ModelVariables>
    <ScalarVariable name="k" valueReference="0" causality="parameter" variability="tunable"><Real start="2" min="-10" max="10"/></ScalarVariable>
    <ScalarVariable name="sign" valueReference="1" causality="parameter" variability="fixed"><Enumeration declaredType="Sign" start="1"/></ScalarVariable>
    <ScalarVariable name="on" valueReference="2" causality="input" variability="discrete"><Boolean start="true"/></ScalarVariable>
    <ScalarVariable name="count" valueReference="3" causality="input" variability="discrete"><Integer start="0" min="-100" max="100"/></ScalarVariable>
    <ScalarVariable name="label" valueReference="4" causality="parameter" variability="fixed"><String start=""/></ScalarVariable>
  </ModelVariables>
  <ModelStructure/>
</fmiModelDescription>
)",
                                                               "gain.xml");
    return md;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto& md = description();
    try {
        const auto s = cosim::parse_setting(std::string_view(reinterpret_cast<const char*>(data), size), true);
        const auto* v = md.find_variable(s.variable);
        if (!v) return 0;
        const auto x = cosim::typed_value(md, *v, s, s.component + "." + s.variable);
        if (const auto* r = std::get_if<double>(&x)) cosim::check_value(md, *v, *r, s.variable);
        if (const auto* i = std::get_if<fmi2Integer>(&x)) cosim::check_value(md, *v, *i, s.variable);
    } catch (const cosim::CosimError&) {}
    return 0;
}
