// Tori: the surface swept by a circle of radius `minor` whose centre runs
// around a circle of radius `major` (the .sc `torus`). A ring torus only:
// minor < major, so the surface does not cross itself (a horn or spindle
// torus, minor >= major, is refused where one is made). It bounds a solid, so
// rays entering and leaving it are told apart as for a sphere.
#pragma once

#include "core/math/aabb.h"
#include "core/math/interval.h"
#include "core/math/ray.h"
#include "core/shapes/primitives.h"

#include <optional>
#include <string>

namespace prism {

// A torus lives in its own frame, where its axis is z and its centre the
// origin: the points with (sqrt(x^2 + y^2) - major)^2 + z^2 = minor^2. The
// frame is placed in the world by an affine map, so every transform of the
// scene language keeps a torus a Torus (a non-uniform scale stretches it),
// and the stored inverse takes rays into the frame, where a ray keeps its
// parameter t (as for Cone and Ellipsoid).
struct Torus {
  static constexpr const char* kName = "torus";
  static constexpr const char* kPlural = "tori"; // in counts (Scene::kindCounts)
  static constexpr bool kFlat = false;

  Mat3 objectToWorld{1.0};       // columns: the frame's x, y and z axes in the world
  Vec3 objectToWorldOffset{0.0}; // where the centre is
  Mat3 worldToObject{1.0};
  Vec3 worldToObjectOffset{0.0};
  Mat3 normalToWorld{1.0}; // transpose of worldToObject: carries gradients
  double major = 1.0;
  double minor = 0.5;
  // The power of two that brings major + minor into [1, 2): the intersection
  // works at that scale (exact), so its numbers are of order 1 at any size.
  double frameScale = 1.0;
  // roundoffScale (core/shapes/roundoff.h), computed once: it takes square roots.
  double roundoff = 0.0;
  Aabb bounds;
  std::uint32_t material = 0;
  Origin origin;
};

// Why these numbers cannot make a torus (not finite, a radius not positive,
// minor >= major, a zero or unusable axis), or nothing if they can.
std::optional<std::string> torusProblem(const Vec3& center, const Vec3& axis, double major,
                                        double minor);

// The torus around `center` with its axis along `axis` (any length), then
// carried by x -> linear x + offset (the current transform). Requires
// torusProblem to find nothing and `linear` to be invertible.
Torus makeTorus(const Vec3& center, const Vec3& axis, double major, double minor,
                const Mat3& linear = Mat3(1.0), const Vec3& offset = Vec3(0.0));

// Every crossing of the ray with the surface with t inside `range`, in
// increasing t, with whether the ray enters the solid there; a tangent touch
// is no crossing. At most 4. What appendCrossings (crossings.h) lists.
struct TorusCrossings {
  double t[4];
  bool entering[4];
  int count = 0;
};
TorusCrossings torusCrossings(const Torus& torus, const Ray& ray, Interval range);

// The nearest crossing with t inside `range`.
bool intersect(const Torus& torus, const Ray& ray, Interval range, double& t);

// The unit outward normal: from the nearest point of the tube's centre circle
// through the point, carried to the world by the inverse transpose.
Vec3 normalAt(const Torus& torus, const Vec3& point);

// In the torus's frame, both angles as fractions of a turn: u around the main
// axis (0.5 on the frame's +x axis, growing toward +y, as for Cone), v around
// the tube (0 on the outer equator, 0.25 on the top, 0.5 on the inner
// equator, 0.75 on the bottom).
Vec2 uvAt(const Torus& torus, const Vec3& point);

inline Aabb boundsOf(const Torus& torus) { return torus.bounds; }

// True when the frame is a similarity (a rotation and a uniform scale), so
// that the torus is round in the world and can be written as centre, axis
// and radii.
bool isRound(const Torus& torus);

} // namespace prism
