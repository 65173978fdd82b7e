// Capped cones and cylinders: the .sc `capped_cone` and `cylinder`, closed
// solids. The side of an open Cone (cone.h) with flat discs closing both
// ends; a radius of 0 makes a pointed cone, whose cap there vanishes.
#pragma once

#include "core/shapes/cone.h"
#include "core/shapes/primitives.h"
#include "core/shapes/shape_arrays.h"
#include "core/shapes/surface_point.h"

#include <cstdint>

namespace prism {

// The side surface, its frame (base circle at z = 0, apex circle at z = 1)
// and bounds are those of `side`; the solid is the part of the frame's
// 0 <= z <= 1 with x^2 + y^2 <= r(z)^2.
//
// Parts (SurfacePoint::part, Crossing::part): 0 the side, 1 the base cap
// (z = 0), 2 the apex cap (z = 1). Coordinates: u the angle around the axis
// as a fraction of a turn (0.5 on the frame's +x axis, growing toward +y) on
// every part; v the height from base (0) to apex (1) on the side, and the
// distance from the axis as a fraction of the cap's radius (0 at the centre,
// 1 on the rim) on a cap.
struct CappedCone {
  static constexpr const char* kName = "capped_cone";
  static constexpr bool kFlat = false; // a ray leaving the inside meets it again

  Cone side;
  std::uint32_t material = 0;
  Origin origin;

  static constexpr std::uint32_t kSide = 0, kBaseCap = 1, kApexCap = 2;
};

// As makeCone (coneProblem decides what can be one).
CappedCone makeCappedCone(const Vec3& base, double baseRadius, const Vec3& apex, double apexRadius,
                          const Mat3& linear = Mat3(1.0), const Vec3& offset = Vec3(0.0));

// Where the ray is inside the solid: up to two spans [t0, t1] (in exact
// arithmetic one; two only within round-off of a pointed tip), entering
// through part0 and leaving through part1, in increasing t. A span with
// t0 == t1 only touches the surface.
struct ConeSpan {
  double t0, t1;
  std::uint32_t part0, part1;
};
int coneSpans(const CappedCone& c, const Ray& ray, ConeSpan spans[2]);

// The nearest t inside `range` where the ray meets the surface.
bool intersect(const CappedCone& c, const Ray& ray, Interval range, double& t);
// The part a surface point lies on (the nearest, measured in the world; a
// cap of radius 0 is never one).
std::uint32_t partAt(const CappedCone& c, const Vec3& point);
// The unit outward normal of that part.
Vec3 normalAt(const CappedCone& c, const Vec3& point);
Vec2 uvAt(const CappedCone& c, const Vec3& point);
inline Aabb boundsOf(const CappedCone& c) { return c.side.bounds; }
// The surface record with the part.
SurfacePoint surfaceAt(const CappedCone& c, const ShapeArrays&, const Vec3& point);

} // namespace prism
