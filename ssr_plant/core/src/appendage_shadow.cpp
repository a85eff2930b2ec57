#include "ssr_plant/appendage_shadow.hpp"

#include <algorithm>
#include <cmath>

namespace ssr_plant {
namespace {

// A convex polygon of at most 4 + 1 + 4 vertices (a plate clipped by one plane, then by four edges), kept
// in a fixed array: no allocation per evaluation.
template <class Point>
struct Polygon {
    std::array<Point, 12> v{};
    std::size_t n = 0;
    void push(const Point& p) { v[n++] = p; }
};

// Sutherland–Hodgman against one half-space {p : inside(p) >= 0}, `inside` affine along an edge.
template <class Point, class F>
Polygon<Point> clip(const Polygon<Point>& in, F inside) {
    Polygon<Point> out;
    for (std::size_t i = 0; i < in.n; ++i) {
        const Point& a = in.v[i];
        const Point& b = in.v[(i + 1) % in.n];
        const double da = inside(a), db = inside(b);
        if (da >= 0.0) out.push(a);
        if ((da >= 0.0) != (db >= 0.0)) {
            const double s = da / (da - db);  // where the edge crosses the boundary
            Point p{};
            for (std::size_t j = 0; j < p.size(); ++j) p[j] = a[j] + s * (b[j] - a[j]);
            out.push(p);
        }
    }
    return out;
}

}  // namespace

double appendage_shadow_fraction(const Plate& plate, const Vec3& box, std::size_t face, const Vec3& sun) {
    const std::size_t axis = face / 2;
    const double sign = face % 2 == 0 ? 1.0 : -1.0;
    const double cos_sun = sign * sun[axis];  // the sun's cosine to the face's outward normal
    if (!(cos_sun > 0.0)) return 0.0;
    const double plane = 0.5 * box[axis];
    const auto height = [&](const Vec3& p) { return sign * p[axis] - plane; };  // in front of the face: > 0

    Polygon<Vec3> corners;
    for (const auto [s, t] :
         {std::array{-0.5, -0.5}, std::array{0.5, -0.5}, std::array{0.5, 0.5}, std::array{-0.5, 0.5}}) {
        Vec3 p{};
        for (std::size_t j = 0; j < 3; ++j) p[j] = plate.center[j] + s * plate.side_a[j] + t * plate.side_b[j];
        corners.push(p);
    }
    const Polygon<Vec3> front = clip(corners, height);

    // Along the sun onto the face's plane, in the face's own coordinates (the two other axes).
    const std::size_t u = (axis + 1) % 3, w = (axis + 2) % 3;
    using Vec2 = std::array<double, 2>;
    Polygon<Vec2> shadow;
    for (std::size_t i = 0; i < front.n; ++i) {
        const Vec3& p = front.v[i];
        const double back = height(p) / cos_sun;  // distance along the sun to the plane
        shadow.push({p[u] - back * sun[u], p[w] - back * sun[w]});
    }
    const double hu = 0.5 * box[u], hw = 0.5 * box[w];
    shadow = clip(shadow, [&](const Vec2& q) { return hu - q[0]; });
    shadow = clip(shadow, [&](const Vec2& q) { return q[0] + hu; });
    shadow = clip(shadow, [&](const Vec2& q) { return hw - q[1]; });
    shadow = clip(shadow, [&](const Vec2& q) { return q[1] + hw; });

    double twice_area = 0.0;  // shoelace
    for (std::size_t i = 0; i < shadow.n; ++i) {
        const Vec2& a = shadow.v[i];
        const Vec2& b = shadow.v[(i + 1) % shadow.n];
        twice_area += a[0] * b[1] - b[0] * a[1];
    }
    return std::min(1.0, 0.5 * std::abs(twice_area) / (box[u] * box[w]));
}

}  // namespace ssr_plant
