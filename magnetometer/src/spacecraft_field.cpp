#include "magnetometer/spacecraft_field.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace magnetometer {
namespace {

Vec3 operator+(const Vec3& a, const Vec3& b) {
    return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
Vec3 operator-(const Vec3& a, const Vec3& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
Vec3 operator*(double s, const Vec3& a) {
    return {s * a[0], s * a[1], s * a[2]};
}
double dot(const Vec3& a, const Vec3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const Vec3& a) {
    return std::sqrt(dot(a, a));
}

bool finite(const Vec3& v) {
    return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

// The loop's field per ampere at the sensor, after checking that no wire passes within
// min_source_distance of it.
Vec3 per_amp(const CurrentLoop& loop, const Vec3& sensor, const std::string& name) {
    if (!finite(loop.center) || !finite(loop.side_a) || !finite(loop.side_b))
        throw std::invalid_argument(name + ": a coordinate is not finite");
    const auto c = loop_corners(loop);
    for (std::size_t k = 0; k < c.size(); ++k) {
        if (distance_to_segment(c[k], c[(k + 1) % c.size()], sensor) < min_source_distance)
            throw std::invalid_argument(name + ": a wire passes within min_source_distance (1 mm) of the sensor");
    }
    return loop_field(loop, 1.0, sensor);
}

}  // namespace

Vec3 segment_field(const Vec3& a, const Vec3& b, double current, const Vec3& p) {
    const Vec3 r1 = a - p;
    const Vec3 r2 = b - p;
    const double l1 = norm(r1);
    const double l2 = norm(r2);
    const double l12 = l1 * l2;
    const double c = dot(r1, r2);
    const Vec3 n = cross(r1, r2);
    // Seen from beside a long wire r1 · r2 ≈ −|r1| |r2|, and l12 + c loses its digits; there it is computed
    // as |r1 × r2|² / (l12 − c), the same number (l12² − c² = |r1 × r2|²).
    const double n2 = dot(n, n);
    if (n2 == 0.0) return {};  // on the line outside the segment, or a segment of zero length
    const double factor = c < 0.0 ? (l12 - c) / (l12 * n2) : 1.0 / (l12 * (l12 + c));
    return (mu0_over_4pi * current * (l1 + l2) * factor) * n;
}

std::array<Vec3, 4> loop_corners(const CurrentLoop& loop) {
    const Vec3 ha = 0.5 * loop.side_a;
    const Vec3 hb = 0.5 * loop.side_b;
    return {loop.center - ha - hb, loop.center + ha - hb, loop.center + ha + hb, loop.center - ha + hb};
}

Vec3 loop_field(const CurrentLoop& loop, double current, const Vec3& p) {
    const auto c = loop_corners(loop);
    Vec3 b{};
    for (std::size_t k = 0; k < c.size(); ++k) b = b + segment_field(c[k], c[(k + 1) % c.size()], current, p);
    return b;
}

Vec3 loop_moment(const CurrentLoop& loop, double current) {
    return current * cross(loop.side_a, loop.side_b);
}

Vec3 dipole_field(const Vec3& moment, const Vec3& r) {
    const double d = norm(r);
    const Vec3 u = (1.0 / d) * r;
    return (mu0_over_4pi / (d * d * d)) * (3.0 * dot(moment, u) * u - moment);
}

double distance_to_segment(const Vec3& a, const Vec3& b, const Vec3& p) {
    const Vec3 ab = b - a;
    const double length2 = dot(ab, ab);
    const double s = length2 > 0.0 ? std::clamp(dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
    return norm(p - (a + s * ab));
}

SpacecraftField::SpacecraftField(const SpacecraftLayout& layout) {
    const Vec3& sensor = layout.sensor_position;
    if (!finite(sensor)) throw std::invalid_argument("sensor_position: a coordinate is not finite");
    static constexpr const char* faces[face_count] = {"+x", "-x", "+y", "-y", "+z", "-z"};
    for (std::size_t k = 0; k < face_count; ++k)
        per_amp_string_[k] = per_amp(layout.string_loop[k], sensor, std::string("string loop of face ") + faces[k]);
    per_amp_shunt_ = per_amp(layout.shunt_loop, sensor, "shunt loop");
    per_amp_battery_ = per_amp(layout.battery_loop, sensor, "battery loop");
    per_amp_load_ = per_amp(layout.load_loop, sensor, "load loop");
    if (!finite(layout.dipole_moment) || !finite(layout.dipole_position))
        throw std::invalid_argument("residual dipole: a coordinate is not finite");
    if (layout.dipole_moment != Vec3{}) {
        const Vec3 r = sensor - layout.dipole_position;
        if (norm(r) < min_source_distance)
            throw std::invalid_argument("residual dipole: within min_source_distance (1 mm) of the sensor");
        dipole_ = dipole_field(layout.dipole_moment, r);
    }
}

Vec3 SpacecraftField::at_sensor(const PlantCurrents& i) const {
    // Each face's string carries the whole current of its cells (what goes to the bus and what the shunt
    // switch takes); the shunt switches' common path carries the sum of the faces' shunt currents.
    double shunt_total = 0.0;
    for (double s : i.shunt) shunt_total += s;
    Vec3 b = dipole_;
    for (std::size_t k = 0; k < face_count; ++k) b = b + i.string[k] * per_amp_string_[k];
    b = b + shunt_total * per_amp_shunt_;
    b = b + i.battery * per_amp_battery_;
    b = b + i.load * per_amp_load_;
    return b;
}

}  // namespace magnetometer
