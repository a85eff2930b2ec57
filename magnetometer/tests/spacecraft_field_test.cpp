// The spacecraft's own field against independent computations: the infinite wire, a numerical
// Biot–Savart integration done here (composite Simpson over the wire, not the closed form), the textbook
// on-axis field of a square loop, and a small loop's far field for the dipole formula.
#include "magnetometer/spacecraft_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace magnetometer {
namespace {

constexpr double mu0 = 4.0e-7 * std::numbers::pi;

double length(const Vec3& v) {
    return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

// Biot–Savart by quadrature: B(p) = μ0 I / 4π ∫ dl × (p − l) / |p − l|³ along the straight wire a → b,
// composite Simpson's rule on n (even) intervals.
Vec3 quadrature_segment_field(const Vec3& a, const Vec3& b, double current, const Vec3& p, int n) {
    const Vec3 dl = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    Vec3 sum{};
    for (int k = 0; k <= n; ++k) {
        const double s = static_cast<double>(k) / n;
        const Vec3 r = {p[0] - (a[0] + s * dl[0]), p[1] - (a[1] + s * dl[1]), p[2] - (a[2] + s * dl[2])};
        const double r3 = std::pow(length(r), 3);
        const Vec3 integrand = {(dl[1] * r[2] - dl[2] * r[1]) / r3, (dl[2] * r[0] - dl[0] * r[2]) / r3,
                                (dl[0] * r[1] - dl[1] * r[0]) / r3};
        const double w = (k == 0 || k == n) ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0);
        for (int i = 0; i < 3; ++i) sum[i] += w * integrand[i];
    }
    const double scale = mu0 / (4.0 * std::numbers::pi) * current / (3.0 * n);
    return {scale * sum[0], scale * sum[1], scale * sum[2]};
}

TEST(SpacecraftField, LongSegmentIsTheInfiniteWire) {
    // 2 km of wire along z carrying 0.6 A, seen from 50 mm on +x: μ0 I / (2π d) = 2.4 µT along +y (right-hand
    // rule, z × x = y). The finite length (half-length h = 1 km) makes it smaller by (d/h)²/2 = 1.25e-9
    // relative: the textbook finite wire, μ0 I / (4π d) · 2h / √(h² + d²). The closed form must keep its
    // digits there (r1 · r2 ≈ −|r1| |r2|).
    const double d = 0.05, current = 0.6;
    const Vec3 b = segment_field({0.0, 0.0, -1000.0}, {0.0, 0.0, 1000.0}, current, {d, 0.0, 0.0});
    const double expected = mu0 * current / (2.0 * std::numbers::pi * d);
    EXPECT_NEAR(b[1], expected, 2e-9 * expected);
    const double h = 1000.0;
    const double finite = mu0 * current / (4.0 * std::numbers::pi * d) * 2.0 * h / std::sqrt(h * h + d * d);
    EXPECT_NEAR(b[1], finite, 1e-14 * expected);
    EXPECT_NEAR(b[0], 0.0, 1e-12 * expected);
    EXPECT_NEAR(b[2], 0.0, 1e-12 * expected);
    // Reversed current: reversed field.
    const Vec3 r = segment_field({0.0, 0.0, 1000.0}, {0.0, 0.0, -1000.0}, current, {d, 0.0, 0.0});
    EXPECT_NEAR(r[1], -finite, 1e-14 * expected);
}

TEST(SpacecraftField, SegmentAgreesWithANumericalBiotSavartIntegration) {
    const Vec3 a = {0.01, -0.02, 0.03}, b = {-0.04, 0.05, 0.12};
    const Vec3 points[] = {{0.05, 0.05, 0.05}, {0.0, 0.0, 0.0}, {-0.1, 0.02, 0.3}, {0.03, -0.06, -0.08}};
    for (const Vec3& p : points) {
        const Vec3 closed = segment_field(a, b, 1.3, p);
        const Vec3 numeric = quadrature_segment_field(a, b, 1.3, p, 20000);
        const double scale = length(numeric);
        ASSERT_GT(scale, 0.0);
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(closed[i], numeric[i], 1e-10 * scale) << "axis " << i;
    }
}

TEST(SpacecraftField, PointOnTheLineBeyondTheSegmentSeesNoField) {
    const Vec3 b = segment_field({0.0, 0.0, 0.0}, {0.0, 0.0, 0.1}, 2.0, {0.0, 0.0, 0.3});
    EXPECT_EQ(b, (Vec3{0.0, 0.0, 0.0}));
}

TEST(SpacecraftField, SquareLoopOnAxisIsTheTextbookField) {
    // Square of side s in the plane z = 0, current counter-clockwise seen from +z: on the axis,
    // B_z = μ0 I s² / (2π (z² + s²/4) √(z² + s²/2)) (the four sides' fields summed by hand).
    const double s = 0.08, current = 0.7;
    const CurrentLoop loop{{0.0, 0.0, 0.0}, {s, 0.0, 0.0}, {0.0, s, 0.0}};
    for (const double z : {0.0, 0.01, 0.05, -0.05, 0.3}) {
        const Vec3 b = loop_field(loop, current, {0.0, 0.0, z});
        const double expected =
            mu0 * current * s * s / (2.0 * std::numbers::pi * (z * z + s * s / 4.0) * std::sqrt(z * z + s * s / 2.0));
        EXPECT_NEAR(b[2], expected, 1e-12 * expected) << "z = " << z;
        EXPECT_NEAR(b[0], 0.0, 1e-12 * expected);
        EXPECT_NEAR(b[1], 0.0, 1e-12 * expected);
    }
    // Its centre: 2√2 μ0 I / (π s).
    EXPECT_NEAR(loop_field(loop, current, {0.0, 0.0, 0.0})[2],
                2.0 * std::sqrt(2.0) * mu0 * current / (std::numbers::pi * s), 1e-18);
}

TEST(SpacecraftField, DipoleIsTheFarFieldOfASmallLoop) {
    // A 1 mm square loop of 2 A has m = 2e-6 A·m² along its normal; at 0.5 m its field differs from the
    // point dipole's by O((s/r)²) = 4e-6 relative.
    const double s = 1e-3, current = 2.0;
    const CurrentLoop loop{{0.0, 0.0, 0.0}, {0.0, s, 0.0}, {0.0, 0.0, s}};  // normal +x
    const Vec3 m = loop_moment(loop, current);
    EXPECT_NEAR(m[0], current * s * s, 1e-20);
    EXPECT_EQ(m[1], 0.0);
    EXPECT_EQ(m[2], 0.0);
    const Vec3 points[] = {{0.5, 0.0, 0.0}, {0.0, 0.5, 0.0}, {0.3, -0.2, 0.35}, {-0.1, 0.4, -0.25}};
    for (const Vec3& p : points) {
        const Vec3 loop_b = loop_field(loop, current, p);
        const Vec3 dipole_b = dipole_field(m, p);
        const double scale = length(loop_b);
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(dipole_b[i], loop_b[i], 2e-5 * scale) << "axis " << i;
    }
    // And the dipole's own axial and equatorial values by hand: 2 μ0 m / (4π r³) and −μ0 m / (4π r³).
    const Vec3 axial = dipole_field({0.0, 0.0, 0.05}, {0.0, 0.0, 0.12});
    EXPECT_NEAR(axial[2], 2e-7 * 0.05 / std::pow(0.12, 3), 1e-20);
    const Vec3 equatorial = dipole_field({0.0, 0.0, 0.05}, {0.12, 0.0, 0.0});
    EXPECT_NEAR(equatorial[2], -1e-7 * 0.05 / std::pow(0.12, 3), 1e-20);
    EXPECT_EQ(equatorial[0], 0.0);
}

TEST(SpacecraftField, ZeroCurrentsAndNoDipoleGiveExactlyZero) {
    const SpacecraftField field(default_layout());
    const Vec3 b = field.at_sensor({});
    EXPECT_EQ(b, (Vec3{0.0, 0.0, 0.0}));
}

TEST(SpacecraftField, EachFaceStringCarriesItsCellCurrentAndTheShuntPathTheShuntsSum) {
    // One loop at a time, the rest made zero-sized (no loop): the sensor's field is that loop's, by the
    // closed form checked above, times the current the model gives it.
    SpacecraftLayout l = default_layout();
    const SpacecraftLayout full = l;
    for (auto& s : l.string_loop) s = {};
    l.shunt_loop = l.battery_loop = l.load_loop = {};
    PlantCurrents i;
    i.string = {0.1, 0.2, 0.4, 0.0, 0.5, 0.0};
    i.shunt = {0.05, 0.0, 0.1, 0.2, 0.0, 0.0};
    i.battery = -0.3;
    i.load = 0.17;
    {
        SpacecraftLayout one = l;
        one.string_loop[2] = full.string_loop[2];
        const Vec3 b = SpacecraftField(one).at_sensor(i);
        const Vec3 expected = loop_field(full.string_loop[2], 0.4, full.sensor_position);
        for (int a = 0; a < 3; ++a) EXPECT_NEAR(b[a], expected[a], 1e-13 * length(expected));
    }
    {
        SpacecraftLayout one = l;
        one.shunt_loop = full.shunt_loop;
        const Vec3 b = SpacecraftField(one).at_sensor(i);
        const Vec3 expected = loop_field(full.shunt_loop, 0.35, full.sensor_position);
        for (int a = 0; a < 3; ++a) EXPECT_NEAR(b[a], expected[a], 1e-13 * length(expected));
    }
    {
        SpacecraftLayout one = l;
        one.battery_loop = full.battery_loop;
        one.load_loop = full.load_loop;
        const Vec3 b = SpacecraftField(one).at_sensor(i);
        const Vec3 batt = loop_field(full.battery_loop, -0.3, full.sensor_position);
        const Vec3 load = loop_field(full.load_loop, 0.17, full.sensor_position);
        for (int a = 0; a < 3; ++a) EXPECT_NEAR(b[a], batt[a] + load[a], 1e-13 * length(batt));
    }
}

TEST(SpacecraftField, DefaultStringLoopsFaceOutwardOnTheirFaces) {
    // The README's sketch: each face's loop lies in its face (|centre| = half the box along the normal) with
    // its normal outward, so a positive current's moment points away from the box.
    const SpacecraftLayout l = default_layout();
    const double half[3] = {0.05, 0.05, 0.17};
    for (std::size_t k = 0; k < face_count; ++k) {
        const int axis = static_cast<int>(k / 2);
        const double sign = k % 2 == 0 ? 1.0 : -1.0;
        const Vec3 m = loop_moment(l.string_loop[k], 1.0);
        EXPECT_GT(sign * m[axis], 0.0) << "face " << k;
        EXPECT_NEAR(length(m), std::abs(m[axis]), 1e-15) << "face " << k;
        EXPECT_DOUBLE_EQ(l.string_loop[k].center[axis], sign * half[axis]) << "face " << k;
    }
}

TEST(SpacecraftField, WireOrDipoleAtTheSensorIsRefused) {
    SpacecraftLayout l = default_layout();
    l.sensor_position = {0.02, 0.02, 0.11};
    l.load_loop = {{0.02, 0.0255, 0.11}, {0.0, 0.0, 0.1}, {0.0, 0.01, 0.0}};  // a wire 0.5 mm from the sensor
    EXPECT_THROW(SpacecraftField{l}, std::invalid_argument);
    SpacecraftLayout d = default_layout();
    d.dipole_moment = {0.0, 0.0, 0.05};
    d.dipole_position = d.sensor_position;
    EXPECT_THROW(SpacecraftField{d}, std::invalid_argument);
    d.dipole_position = {0.0, 0.0, 0.0};
    EXPECT_NO_THROW(SpacecraftField{d});
}

}  // namespace
}  // namespace magnetometer
