// Discs: the .sc `disc`, a flat circular disc (an ellipse after a
// non-uniform scale). Like polygons, two-sided: which side a ray hits is the
// tracer's entering/leaving test.
#pragma once

#include "core/math/aabb.h"
#include "core/math/interval.h"
#include "core/math/ray.h"
#include "core/shapes/affine_frame.h"
#include "core/shapes/primitives.h"

#include <optional>
#include <string>

namespace prism {

// In its own frame the disc is x^2 + y^2 <= radius^2 at z = 0, its normal +z;
// the frame's x and y axes are unit vectors in the plane (before the
// transform), so `radius` is in the units the disc was written in.
// Coordinates: u the angle around the centre as a fraction of a turn (0.5 on
// the frame's +x axis, growing toward +y, as for cones), v the distance from
// the centre as a fraction of the radius (0 at the centre, 1 on the rim).
struct Disc {
  static constexpr const char* kName = "disc";
  static constexpr bool kFlat = true; // a ray leaving it cannot meet it again

  AffineFrame frame; // z: the normal written, carried by the transform
  double radius = 1.0;
  Vec3 normal{0.0, 0.0, 1.0}; // unit world normal (the frame's z gradient)
  // roundoffScale (core/shapes/roundoff.h), computed once: it takes square roots.
  double roundoff = 0.0;
  Aabb bounds;
  std::uint32_t material = 0;
  Origin origin;
};

// Why these cannot make a disc (not finite, a zero normal, a radius not
// positive), or nothing if they can.
std::optional<std::string> discProblem(const Vec3& center, const Vec3& normal, double radius);

// The disc of `radius` around `center` facing `normal`, carried by x ->
// linear x + offset. Requires discProblem to find nothing and `linear` to be
// invertible.
Disc makeDisc(const Vec3& center, const Vec3& normal, double radius, const Mat3& linear = Mat3(1.0),
              const Vec3& offset = Vec3(0.0));

bool intersect(const Disc& d, const Ray& ray, Interval range, double& t);
inline Vec3 normalAt(const Disc& d, const Vec3&) { return d.normal; }
Vec2 uvAt(const Disc& d, const Vec3& point);
inline Aabb boundsOf(const Disc& d) { return d.bounds; }

// True when the disc is a circle in the world (the frame's x and y axes
// orthogonal and of equal length), so it is written as centre, normal, radius.
bool isCircular(const Disc& d);

} // namespace prism
