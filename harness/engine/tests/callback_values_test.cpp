// A callback component's outputs are checked against their variables' types and ranges before they are
// kept (issue 38): a Boolean of NaN or 0.5, an Integer of 1e30 or 2.5, an Enumeration that is no item,
// a Real that is not finite or outside min/max are refused with a message naming the variable, never
// rounded into a value that is recorded and fed onward.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "engine/callback_instance.hpp"
#include "engine/cosim_error.hpp"
#include "fmi_loader/model_description.hpp"

namespace cosim {
namespace {

const char* const description_xml = R"(<?xml version="1.0" encoding="UTF-8"?>
<fmiModelDescription fmiVersion="2.0" modelName="outs" guid="{g}">
  <ModelExchange modelIdentifier="outs"/>
  <TypeDefinitions>
    <SimpleType name="Mode"><Enumeration><Item name="off" value="1"/><Item name="on" value="2"/></Enumeration></SimpleType>
  </TypeDefinitions>
  <ModelVariables>
    <ScalarVariable name="flag" valueReference="0" causality="output" variability="discrete"><Boolean/></ScalarVariable>
    <ScalarVariable name="count" valueReference="1" causality="output" variability="discrete"><Integer min="0" max="100"/></ScalarVariable>
    <ScalarVariable name="mode" valueReference="2" causality="output" variability="discrete"><Enumeration declaredType="Mode"/></ScalarVariable>
    <ScalarVariable name="x" valueReference="3" causality="output"><Real min="-1" max="1"/></ScalarVariable>
  </ModelVariables>
  <ModelStructure><Outputs><Unknown index="1"/><Unknown index="2"/><Unknown index="3"/><Unknown index="4"/></Outputs></ModelStructure>
</fmiModelDescription>
)";

// A callback component whose function gives `outputs`, after its first sample (t = 0), and the message
// of that sample's refusal ("" when accepted).
struct Sampled {
    std::vector<double> outputs;
    std::unique_ptr<CallbackInstance> instance;
    std::string refusal;
};

std::unique_ptr<Sampled> sample(const std::vector<double>& outputs) {
    static const auto md = fmi_loader::parse_model_description(description_xml, "outs.xml");
    auto s = std::make_unique<Sampled>();
    s->outputs = outputs;
    s->instance = std::make_unique<CallbackInstance>(
        md, "c", 0.5, [given = &s->outputs](double, std::span<const double>, std::span<double> out) {
            for (std::size_t i = 0; i < out.size(); ++i) out[i] = (*given)[i];
        });
    s->instance->setup_experiment(0.0, 1.0, std::nullopt);
    try {
        s->instance->new_discrete_states();
    } catch (const CosimError& e) {
        s->refusal = e.what();
    }
    return s;
}

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

TEST(CosimCallbackValues, ValuesOfTheVariablesTypeAndRangeAreKept) {
    const auto s = sample({1.0, 42.0, 2.0, -0.5});
    EXPECT_EQ(s->refusal, "");
    auto* c = s->instance.get();
    EXPECT_TRUE(c->get_boolean(0));
    EXPECT_EQ(c->get_integer(1), 42);
    EXPECT_EQ(c->get_integer(2), 2);
    EXPECT_EQ(c->get_real(3), -0.5);
}

TEST(CosimCallbackValues, WrongValuesAreRefusedNamingTheVariableNotCoerced) {
    const struct {
        std::vector<double> outputs;
        const char* expected;
    } cases[] = {
        {{nan, 1, 1, 0}, "c.flag from the callback at t = 0 s: nan is not a Boolean (0 or 1)"},
        {{0.5, 1, 1, 0}, "c.flag from the callback at t = 0 s: 0.5 is not a Boolean (0 or 1)"},
        {{1, 1e30, 1, 0}, "c.count from the callback at t = 0 s: 1e+30 is not a whole 32-bit number"},
        {{1, 2.5, 1, 0}, "c.count from the callback at t = 0 s: 2.5 is not a whole 32-bit number"},
        {{1, 101, 1, 0}, "c.count from the callback at t = 0 s: 101 is above its maximum 100"},
        {{1, 1, 3, 0}, "c.mode from the callback at t = 0 s: 3 is not an item of Mode (off = 1, on = 2)"},
        {{1, 1, 1, nan}, "c.x from the callback at t = 0 s: nan is not a finite number"},
        {{1, 1, 1, -2}, "c.x from the callback at t = 0 s: -2 is below its minimum -1"},
    };
    for (const auto& c : cases) {
        const auto s = sample(c.outputs);
        EXPECT_NE(s->refusal.find(c.expected), std::string::npos) << c.expected << "; got: " << s->refusal;
        // Nothing of a refused sample is kept: every output still holds its start (0, false).
        EXPECT_EQ(s->instance->get_real(3), 0.0);
    }
}

}  // namespace
}  // namespace cosim
