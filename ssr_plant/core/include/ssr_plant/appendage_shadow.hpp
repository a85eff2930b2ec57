// The shadow a body-fixed appendage (a deployed antenna, a boom's plate) casts on one face of the box, from
// its geometry: the fraction of the face's area the sun cannot reach through it.
#pragma once

#include <array>
#include <cstddef>

namespace ssr_plant {

using Vec3 = std::array<double, 3>;

// A flat rectangular plate in body axes (m, from the box's centre): the points center + s side_a + t side_b,
// s and t in [−1/2, 1/2].
struct Plate {
    Vec3 center = {};
    Vec3 side_a = {};
    Vec3 side_b = {};
};

// Fraction of face k (0 … 5 = +x, −x, +y, −y, +z, −z) of a box of edges `box` (m, centred on the origin; the
// panel covers the whole face) in the plate's shadow, for the unit sun direction `sun` (body axes). The part
// of the plate in front of the face's plane is projected along the sun onto that plane (a parallel
// projection: the sun is far) and clipped to the face (Sutherland–Hodgman); the fraction is the area left
// over the face's. 0 when the face turns away from the sun (it has no direct sun to lose) or the plate is
// behind the face's plane.
double appendage_shadow_fraction(const Plate& plate, const Vec3& box, std::size_t face, const Vec3& sun);

}  // namespace ssr_plant
