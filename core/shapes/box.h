// Boxes: the .sc `box`, a closed solid. Axis-aligned in its own frame and
// placed by an affine map, so after the scene's transforms any
// parallelepiped.
#pragma once

#include "core/math/aabb.h"
#include "core/math/interval.h"
#include "core/math/ray.h"
#include "core/shapes/affine_frame.h"
#include "core/shapes/primitives.h"
#include "core/shapes/shape_arrays.h"
#include "core/shapes/surface_point.h"

#include <optional>
#include <string>

namespace prism {

// The points lo <= x <= hi (componentwise) of the frame, carried into the
// world by the frame's map. A box written under a transform without rotation
// or shear (a translation and axis scales) is stored in world coordinates
// with the identity frame, so the common case costs no transform's
// round-off.
//
// Parts (SurfacePoint::part, Crossing::part), by the frame's axes:
//   0: x = lo.x   1: x = hi.x   2: y = lo.y   3: y = hi.y   4: z = lo.z   5: z = hi.z
// Coordinates on face `axis` i (j = i + 1, k = i + 2, mod 3), each in [0, 1]
// across the face: on the hi face u = (x_j - lo_j) / (hi_j - lo_j) and v the
// same along k; on the lo face u = 1 - that. Seen from outside, u then v turn
// counterclockwise on every face (u x v is the outward normal in the frame).
struct Box {
  static constexpr const char* kName = "box";
  static constexpr const char* kPlural = "boxes"; // in counts (Scene::kindCounts)
  static constexpr bool kFlat = false;            // a ray leaving the inside meets it again

  AffineFrame frame;
  Vec3 lo{-1.0};
  Vec3 hi{1.0};
  // roundoffScale (core/shapes/roundoff.h), computed once: it takes square roots.
  double roundoff = 0.0;
  Aabb bounds;
  std::uint32_t material = 0;
  Origin origin;
};

// Why these opposite corners cannot make a box (not finite, equal in some
// coordinate so the box has no volume), or nothing if they can.
std::optional<std::string> boxProblem(const Vec3& corner0, const Vec3& corner1);

// The box with opposite corners `corner0` and `corner1` (in any order),
// carried by x -> linear x + offset (the current transform). Requires
// boxProblem to find nothing and `linear` to be invertible.
Box makeBox(const Vec3& corner0, const Vec3& corner1, const Mat3& linear = Mat3(1.0),
            const Vec3& offset = Vec3(0.0));

// Where the ray is inside the box: [t0, t1], entering through part0 and
// leaving through part1; false when the line misses it (t0 == t1 when it
// only touches an edge or a corner).
struct BoxSpan {
  double t0, t1;
  std::uint32_t part0, part1;
};
bool boxSpan(const Box& b, const Ray& ray, BoxSpan& span);
// The same for the line o + t d and the box lo <= x <= hi of its own
// coordinates (the clip box of a quadric).
bool slabSpan(const Vec3& o, const Vec3& d, const Vec3& lo, const Vec3& hi, BoxSpan& span);

// The nearest t inside `range` where the ray meets the surface.
bool intersect(const Box& b, const Ray& ray, Interval range, double& t);
// The face a surface point lies on (the nearest, measured in the world).
std::uint32_t partAt(const Box& b, const Vec3& point);
// The unit outward normal of that face.
Vec3 normalAt(const Box& b, const Vec3& point);
Vec2 uvAt(const Box& b, const Vec3& point);
inline Aabb boundsOf(const Box& b) { return b.bounds; }
// The surface record with the face's part.
SurfacePoint surfaceAt(const Box& b, const ShapeArrays&, const Vec3& point);

// True when the frame is the identity, so the box is written as its corners.
bool isWorldAligned(const Box& b);

} // namespace prism
