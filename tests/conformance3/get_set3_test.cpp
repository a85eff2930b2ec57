// Get and set of every variable of an FMI 3.0 archive, whole arrays at a time, in the types FMI 3.0
// gives them (Float64, Int32, Int64 for an Enumeration, Boolean, String), against the FMI 2.0 archive.
#include <cstring>
#include <memory>

#include "fixture3.hpp"

namespace {

using conformance3::Instance3;
using Kind = Instance3::Kind;

CONFORMANCE3_SUITE(Conformance3GetSet);

// Reads every variable whole; returns the status of the first failure.
fmi3Status read_all(Instance3& inst, std::string& failed) {
    for (const auto& v : inst.md().variables) {
        const fmi3ValueReference vr = v.value_reference;
        fmi3Status s = fmi3OK;
        if (v.type == "Float64") {
            std::vector<fmi3Float64> x(v.count);
            s = inst.f().get_float64(inst.c(), &vr, 1, x.data(), x.size());
        } else if (v.type == "Int32") {
            std::vector<fmi3Int32> x(v.count);
            s = inst.f().get_int32(inst.c(), &vr, 1, x.data(), x.size());
        } else if (v.type == "Enumeration") {
            std::vector<fmi3Int64> x(v.count);
            s = inst.f().get_int64(inst.c(), &vr, 1, x.data(), x.size());
        } else if (v.type == "Boolean") {
            std::unique_ptr<fmi3Boolean[]> x(new fmi3Boolean[v.count]);  // not vector<bool>: packed bits
            s = inst.f().get_boolean(inst.c(), &vr, 1, x.get(), v.count);
        } else if (v.type == "String") {
            std::vector<fmi3String> x(v.count);
            s = inst.f().get_string(inst.c(), &vr, 1, x.data(), x.size());
        }
        if (s != fmi3OK) {
            failed = v.name;
            return s;
        }
    }
    return fmi3OK;
}

TEST_P(Conformance3GetSet, EveryVariableReadsWholeInBothInterfaces) {
    for (const Kind kind : {Kind::model_exchange, Kind::co_simulation}) {
        Instance3 inst(fmu3(), kind);
        ASSERT_NE(inst.c(), nullptr) << inst.log().dump();
        ASSERT_EQ(inst.initialize(), fmi3OK) << inst.log().dump();
        std::string failed;
        EXPECT_EQ(read_all(inst, failed), fmi3OK) << failed << "\n" << inst.log().dump();
    }
}

// The values after initialization are the FMI 2.0 archive's, element by element, bit for bit.
TEST_P(Conformance3GetSet, Float64ValuesAreTheFmi2ArchivesElements) {
    Instance3 inst(fmu3(), Kind::co_simulation);
    ASSERT_EQ(inst.initialize(), fmi3OK) << inst.log().dump();
    conformance::Instance inst2(fmu2(), fmi_loader::FmuKind::co_simulation);
    ASSERT_TRUE(inst2.ok());
    ASSERT_EQ(inst2.initialize(md().start_time, md().stop_time), fmi2OK);
    for (const auto& v : md().variables) {
        if (v.type != "Float64" || v.causality == "independent" || v.name == "event_indicators") continue;
        const auto values = inst.get_float64(v);
        for (std::size_t i = 0; i < v.count; ++i) {
            double x2 = 0.0;
            ASSERT_EQ(inst2.get_real(v.value_reference + static_cast<std::uint32_t>(i), x2), fmi2OK);
            EXPECT_EQ(std::memcmp(&x2, &values[i], sizeof x2), 0) << v.name << " element " << i + 1;
        }
    }
    double t = -1.0;
    const auto& time = *std::find_if(md().variables.begin(), md().variables.end(),
                                     [](const auto& v) { return v.causality == "independent"; });
    ASSERT_EQ(inst.f().get_float64(inst.c(), &time.value_reference, 1, &t, 1), fmi3OK);
    EXPECT_EQ(t, md().start_time);
}

// Every variable with a start value takes it back before initialization, whole arrays at once.
TEST_P(Conformance3GetSet, StartValuesAreSettableBeforeInitialization) {
    Instance3 inst(fmu3(), Kind::co_simulation);
    for (const auto& v : md().variables) {
        if (v.start.empty() || v.variability == "constant") continue;
        const fmi3ValueReference vr = v.value_reference;
        fmi3Status s = fmi3OK;
        if (v.type == "Float64") {
            std::vector<fmi3Float64> x;
            for (const auto& w : v.start) x.push_back(std::stod(w));
            s = inst.f().set_float64(inst.c(), &vr, 1, x.data(), x.size());
        } else if (v.type == "Int32") {
            std::vector<fmi3Int32> x;
            for (const auto& w : v.start) x.push_back(std::stoi(w));
            s = inst.f().set_int32(inst.c(), &vr, 1, x.data(), x.size());
        } else if (v.type == "Enumeration") {
            std::vector<fmi3Int64> x;
            for (const auto& w : v.start) x.push_back(std::stoll(w));
            s = inst.f().set_int64(inst.c(), &vr, 1, x.data(), x.size());
        } else if (v.type == "Boolean") {
            std::unique_ptr<fmi3Boolean[]> x(new fmi3Boolean[v.start.size()]);
            for (std::size_t i = 0; i < v.start.size(); ++i) x[i] = v.start[i] == "true" || v.start[i] == "1";
            s = inst.f().set_boolean(inst.c(), &vr, 1, x.get(), v.start.size());
        } else if (v.type == "String") {
            std::vector<fmi3String> x;
            for (const auto& w : v.start) x.push_back(w.c_str());
            s = inst.f().set_string(inst.c(), &vr, 1, x.data(), x.size());
        }
        EXPECT_EQ(s, fmi3OK) << v.name << "\n" << inst.log().dump();
    }
    EXPECT_EQ(inst.initialize(), fmi3OK) << inst.log().dump();
}

// nValues counts the elements: one too few for an array, or a value reference of another type, is refused.
TEST_P(Conformance3GetSet, WrongCountsAndTypesAreRefused) {
    Instance3 inst(fmu3(), Kind::co_simulation);
    ASSERT_EQ(inst.initialize(), fmi3OK);
    for (const auto& v : md().variables) {
        if (v.type != "Float64" || !v.array) continue;
        std::vector<double> x(v.count);
        EXPECT_EQ(inst.f().get_float64(inst.c(), &v.value_reference, 1, x.data(), v.count - 1), fmi3Error) << v.name;
        break;
    }
    Instance3 inst2(fmu3(), Kind::co_simulation);
    ASSERT_EQ(inst2.initialize(), fmi3OK);
    const auto& first = md().variables[1];
    float f = 0.0f;
    EXPECT_EQ(inst2.f().get_float32(inst2.c(), &first.value_reference, 1, &f, 1), fmi3Error);
}

}  // namespace
