#include "attitude_estimator/string_field.hpp"

#include <algorithm>
#include <cmath>

namespace attitude_estimator {

namespace {

constexpr double kMu0Over4Pi = 1e-7;  // T m/A

using V = Vec3<double>;

V minus(const V& a, const V& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
double dot(const V& a, const V& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
V cross(const V& a, const V& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

std::array<V, 4> corners(const StringLoop& l) {
    std::array<V, 4> c{};
    const double sa[4] = {-0.5, 0.5, 0.5, -0.5};
    const double sb[4] = {-0.5, -0.5, 0.5, 0.5};
    for (std::size_t k = 0; k < 4; ++k)
        for (std::size_t i = 0; i < 3; ++i) c[k][i] = l.center[i] + sa[k] * l.side_a[i] + sb[k] * l.side_b[i];
    return c;
}

// One ampere straight from a to b, at p: with r1 = a − p, r2 = b − p,
// B = μ0/4π (r1 × r2)(|r1| + |r2|) / (|r1| |r2| (|r1| |r2| + r1·r2)). Seen from beside a long wire r1·r2 nears
// −|r1| |r2| and the last factor loses its digits; there it is |r1 × r2|² / (|r1| |r2| − r1·r2), the same number.
V segment_field(const V& a, const V& b, const V& p) {
    const V r1 = minus(a, p);
    const V r2 = minus(b, p);
    const double l1 = std::sqrt(dot(r1, r1));
    const double l2 = std::sqrt(dot(r2, r2));
    const double l12 = l1 * l2;
    const double c = dot(r1, r2);
    const V n = cross(r1, r2);
    const double n2 = dot(n, n);
    if (!(n2 > 0.0)) return V{};  // on the wire's line (or a wire of no length)
    const double factor = c < 0.0 ? (l12 - c) / (l12 * n2) : 1.0 / (l12 * (l12 + c));
    const double s = kMu0Over4Pi * (l1 + l2) * factor;
    return {s * n[0], s * n[1], s * n[2]};
}

double segment_distance(const V& a, const V& b, const V& p) {
    const V ab = minus(b, a);
    const double length2 = dot(ab, ab);
    const double s = length2 > 0.0 ? std::clamp(dot(minus(p, a), ab) / length2, 0.0, 1.0) : 0.0;
    const V d{p[0] - a[0] - s * ab[0], p[1] - a[1] - s * ab[1], p[2] - a[2] - s * ab[2]};
    return std::sqrt(dot(d, d));
}

}  // namespace

Vec3<double> string_loop_field_per_ampere(const StringLoop& loop, const Vec3<double>& p) noexcept {
    const auto c = corners(loop);
    V b{};
    for (std::size_t k = 0; k < c.size(); ++k) {
        const V s = segment_field(c[k], c[(k + 1) % c.size()], p);
        for (std::size_t i = 0; i < 3; ++i) b[i] += s[i];
    }
    return b;
}

double string_loop_wire_distance(const StringLoop& loop, const Vec3<double>& p) noexcept {
    const auto c = corners(loop);
    double d = segment_distance(c[0], c[1], p);
    for (std::size_t k = 1; k < c.size(); ++k) d = std::min(d, segment_distance(c[k], c[(k + 1) % c.size()], p));
    return d;
}

}  // namespace attitude_estimator
