// The variable table: structured names, value references, dependency checks and refusals.
#include <gtest/gtest.h>

#include <array>

#include "fmu/table.hpp"
#include "fmu/units.hpp"

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
