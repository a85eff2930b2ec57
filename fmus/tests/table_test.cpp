// The variable table: structured names, value references, dependency checks and refusals.
#include <gtest/gtest.h>

#include <array>
#include <span>

#include "fmu/table.hpp"
#include "fmu/units.hpp"
#include "fmu/value_check.hpp"

namespace {

struct Data {
    std::array<double, 3> a{1, 2, 3};
    double x = 0, der_x = 0;
    double out = 0;
    double p = 4;
};

TEST(Table, ArraysBecomeStructuredNamesWithSequentialValueReferences) {
    fmu::Table<Data> t;
    t.input("a", &Data::a, "V", "vector");
    t.state("x", &Data::x, &Data::der_x, "m", "state");
    const auto& vars = t.variables();
    ASSERT_EQ(vars.size(), 5u);
    EXPECT_EQ(vars[0].name, "a[1]");
    EXPECT_EQ(vars[2].name, "a[3]");
    EXPECT_EQ(vars[4].name, "der(x)");
    EXPECT_EQ(vars[4].unit, "m/s");
    for (std::size_t i = 0; i < vars.size(); ++i) EXPECT_EQ(vars[i].value_reference, i);
    EXPECT_EQ(vars[1].offset - vars[0].offset, sizeof(double));
    EXPECT_EQ(*vars[4].derivative_of, 3u);
    EXPECT_TRUE(vars[3].is_state());
}

TEST(Table, DependenciesMustBeInputsOrStates) {
    fmu::Table<Data> t;
    t.input("a", &Data::a, "V", "vector");
    t.parameter("p", &Data::p, "V", "parameter");
    auto out = t.output("out", &Data::out, "V", "output");
    EXPECT_THROW(out.depends_on({"p"}), fmu::Error);
    EXPECT_THROW(out.depends_on({"nothing"}), fmu::Error);
    out.depends_on({"a[2]"});
    EXPECT_EQ(*t.by_name("out").dependencies, std::vector<std::size_t>{1});
}

TEST(Table, RefusesDuplicatesUnknownUnitsAndMisplacedQualifiers) {
    fmu::Table<Data> t;
    t.parameter("p", &Data::p, "V", "parameter");
    EXPECT_THROW(t.parameter("p", &Data::p, "V", "again"), fmu::Error);
    EXPECT_THROW(t.output("out", &Data::out, "furlong", "bad unit"), fmu::Error);
    auto in = t.input("a", &Data::a, "V", "vector");
    EXPECT_THROW(in.tunable(), fmu::Error);
    EXPECT_THROW(in.calculated_start(), fmu::Error);
}

TEST(Units, SiExponentsOfDerivedUnits) {
    const auto volt = fmu::find_unit("V");
    ASSERT_TRUE(volt);
    EXPECT_EQ(volt->kg, 1);
    EXPECT_EQ(volt->m, 2);
    EXPECT_EQ(volt->s, -3);
    EXPECT_EQ(volt->A, -1);
    const auto tesla_rate = fmu::find_unit("T/s");
    ASSERT_TRUE(tesla_rate);
    EXPECT_EQ(tesla_rate->s, -3);
    EXPECT_FALSE(fmu::find_unit("degC/s"));  // an offset unit has no plain rate
}

}  // namespace

// Issue 40: a value out of range is said with its unit, as a person reads it ("300 K is above its maximum
// 125 K"); a dimensionless one ("1" or no unit) without.
TEST(ValueCheck, RangeErrorsCarryTheVariablesUnit) {
    fmu::Table<Data> t;
    t.parameter("p", &Data::p, "K", "temperature").range(-100.0, 125.0);
    t.parameter("x", &Data::x, "1", "fraction").range(0.0, 1.0);
    const auto message = [&](std::size_t i, double value) {
        try {
            fmu::check_real(t.variables()[i], value);
        } catch (const fmu::Error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_EQ(message(0, 300.0), "p = 300 K is above its maximum 125 K");
    EXPECT_EQ(message(0, -300.0), "p = -300 K is below its minimum -100 K");
    EXPECT_EQ(message(1, 2.0), "x = 2 is above its maximum 1");
    EXPECT_EQ(message(0, 20.0), "");
}

// Issue 40: a legal setting a person most likely did not mean is said (once per declared name), not refused:
// a parameter that the chosen mode ignores, set away from its default, and one outside its plausible range.
enum class Orbit : std::int32_t { circular = 0, tle = 1 };
struct ModeData {
    Orbit orbit = Orbit::circular;
    double altitude = 570e3;
    std::array<double, 3> omega{0.0, 0.0, 0.0};
};

TEST(ValueCheck, SettingNotesForIgnoredAndUnlikelyParameters) {
    fmu::Table<ModeData> t;
    t.choice("orbit", &ModeData::orbit, {{"circular", Orbit::circular}, {"tle", Orbit::tle}}, "orbit model");
    t.parameter("altitude", &ModeData::altitude, "m", "circular orbit's altitude").applies_when("orbit", {"circular"});
    t.parameter("omega", &ModeData::omega, "rad/s", "start rate").range(-100, 100).plausible(-1, 1, "a violent tumble");
    const ModeData defaults;
    const auto bytes = [](const ModeData& d) { return std::as_bytes(std::span(&d, 1)); };
    const auto notes = [&](const ModeData& d) { return fmu::setting_notes(t.variables(), bytes(d), bytes(defaults)); };
    EXPECT_TRUE(notes(defaults).empty());
    ModeData d;
    d.altitude = 400e3;  // applies: circular
    EXPECT_TRUE(notes(d).empty());
    d.orbit = Orbit::tle;  // now ignored
    ASSERT_EQ(notes(d).size(), 1u);
    EXPECT_EQ(notes(d)[0], "altitude = 4e+05 m has no effect: it applies when orbit is circular, and orbit is tle");
    d.altitude = defaults.altitude;  // left at its default: nothing to say
    EXPECT_TRUE(notes(d).empty());
    d.omega = {5.0, 6.0, 0.0};  // two elements out: one note
    ASSERT_EQ(notes(d).size(), 1u);
    EXPECT_EQ(notes(d)[0], "omega[1] = 5 rad/s is legal but unlikely (outside -1 rad/s to 1 rad/s): a violent tumble");
    fmu::Table<ModeData> u;  // a value the choice does not have is a mistake in the table
    u.choice("orbit", &ModeData::orbit, {{"circular", Orbit::circular}, {"tle", Orbit::tle}}, "orbit model");
    auto h = u.parameter("altitude", &ModeData::altitude, "m", "x");
    EXPECT_THROW(h.applies_when("orbit", {"elliptic"}), fmu::Error);
}
