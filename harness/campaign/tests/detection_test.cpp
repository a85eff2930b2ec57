// A detection metric's arithmetic on small tables made by hand: declarations (a word turning nonzero, at
// its time column's value or else the output point), counted from the onset, against the expected element.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "detection.hpp"

using campaign::DetectionTracker;

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// Three elements; w[1] has no time column (NaN: the output point is taken). Declarations:
// w[1] at 9.5 s (its time column), w[3] at 27.25 s (word 4), w[2] at 40 s (word 2, then 3 from 50 s),
// cleared at 60 s and declared again at 70 s (word 2).
DetectionTracker table() {
    DetectionTracker d({"w[1]", "w[2]", "w[3]"});
    const double rows[][7] = {
        // t, words 1..3, times 1..3
        {0, 0, 0, 0, -1, nan, -1},      {10, 1, 0, 0, 9.5, nan, -1},    {20, 1, 0, 0, 9.5, nan, -1},
        {30, 1, 0, 4, 9.5, nan, 27.25}, {40, 1, 2, 4, 9.5, nan, 27.25}, {50, 1, 3, 4, 9.5, nan, 27.25},
        {60, 1, 0, 4, 9.5, nan, 27.25}, {70, 1, 2, 4, 9.5, nan, 27.25},
    };
    for (const auto& r : rows) d.sample(r[0], {r[1], r[2], r[3]}, {r[4], r[5], r[6]});
    return d;
}

}  // namespace

TEST(Detection, CountsFromTheOnsetAndComparesTheElements) {
    const auto d = table();
    // Onset 20 s, w[3] expected: counted from 20 s are w[3] @ 27.25, w[2] @ 40 (word 3 by 50 s), w[2] @ 70;
    // w[1] @ 9.5 came before. Time to detect 27.25 - 20 = 7.25 s; w[2] too, so not isolated. Span 70 - 20
    // = 50 s = 2 periods of 25 s.
    auto o = d.outcome(20.0, {2}, 0.0, 25.0);
    EXPECT_EQ(o.detected, 1.0);
    EXPECT_EQ(o.time, 7.25);
    EXPECT_EQ(o.isolated, 0.0);
    EXPECT_EQ(o.declared, 3.0);
    EXPECT_EQ(o.before, 1.0);
    EXPECT_EQ(o.orbits, 2.0);
    EXPECT_EQ(o.which, "w[3]=4 w[2]=3 w[2]=2");
    // Expecting w[2] and w[3]: exactly what was declared after the onset.
    EXPECT_EQ(d.outcome(20.0, {1, 2}, 0.0, 25.0).isolated, 1.0);
    // Onset after everything but the re-declaration at 70 s: w[2] alone, 70 - 65 = 5 s.
    o = d.outcome(65.0, {1}, 0.0, 25.0);
    EXPECT_EQ(o.time, 5.0);
    EXPECT_EQ(o.isolated, 1.0);
    EXPECT_EQ(o.before, 3.0);
    EXPECT_EQ(o.orbits, 0.2);
}

// No onset (a control): every declaration from `after` on counts (the false alarms), none is a detection
// time; declarations before `after` (a transient) are ignored altogether.
TEST(Detection, AControlCountsEveryDeclarationAfterItsTransient) {
    const auto o = table().outcome(std::nullopt, {}, 15.0, 25.0);
    EXPECT_EQ(o.declared, 3.0);  // 27.25, 40, 70; 9.5 is before 15 s
    EXPECT_EQ(o.before, 0.0);
    EXPECT_TRUE(std::isnan(o.time));
    EXPECT_EQ(o.detected, 1.0);
    EXPECT_EQ(o.isolated, 0.0);
    EXPECT_EQ(o.orbits, 2.2);  // (70 - 15) / 25
}

TEST(Detection, NothingDeclaredIsIsolatedOnlyWhenNothingWasExpected) {
    DetectionTracker d({"f"});
    for (double t : {0.0, 5.0, 10.0}) d.sample(t, {0.0}, {});
    auto o = d.outcome(std::nullopt, {}, 0.0, 5.0);
    EXPECT_EQ(o.detected, 0.0);
    EXPECT_EQ(o.declared, 0.0);
    EXPECT_EQ(o.isolated, 1.0);
    EXPECT_EQ(o.orbits, 2.0);
    EXPECT_EQ(o.which, "");
    o = d.outcome(2.0, {0}, 0.0, 5.0);  // a fault at 2 s that was missed
    EXPECT_EQ(o.detected, 0.0);
    EXPECT_EQ(o.isolated, 0.0);
    EXPECT_TRUE(std::isnan(o.time));
    // A run that sampled nothing has nothing to say.
    EXPECT_TRUE(std::isnan(DetectionTracker({"f"}).outcome(1.0, {}, 0.0, 5.0).declared));
}
