// Open truncated cones and cylinders: the side surface between two circles,
// without the discs that would close it (NFF `c`, the .sc `cone`). Like
// polygons they are two-sided: which side a ray hits is the tracer's
// entering/leaving test, so a ray reaching the inside of a tube counts as
// leaving it, as it would leave a lone polygon.
#pragma once

#include "core/shapes/primitives.h"

#include <optional>
#include <string>

namespace prism {

// A cone lives in its own frame, where the axis is z, the base circle (radius
// baseRadius) lies at z = 0 and the apex circle (radius apexRadius) at z = 1:
// the points with x^2 + y^2 = (baseRadius + (apexRadius - baseRadius) z)^2,
// 0 <= z <= 1. The frame is placed in the world by an affine map, so every
// transform of the scene language keeps a cone a Cone (a non-uniform scale
// makes its cross-sections ellipses), and the stored inverse takes rays into
// the frame, where a ray keeps its parameter t (as for Ellipsoid).
struct Cone {
  static constexpr const char* kName = "cone";
  static constexpr bool kFlat = false; // a ray leaving the inside meets it again

  Mat3 objectToWorld{1.0};       // columns: the frame's x, y and z axes in the world
  Vec3 objectToWorldOffset{0.0}; // where the base centre is
  Mat3 worldToObject{1.0};
  Vec3 worldToObjectOffset{0.0};
  Mat3 normalToWorld{1.0}; // transpose of worldToObject: carries gradients
  double baseRadius = 1.0;
  double apexRadius = 1.0;
  // roundoffScale (core/shapes/roundoff.h), computed once: it takes square roots.
  double roundoff = 0.0;
  Aabb bounds;
  std::uint32_t material = 0;
  Origin origin;
};

// Why these end circles cannot make a cone (not finite, a negative radius,
// both radii zero, base and apex centres equal), or nothing if they can.
std::optional<std::string> coneProblem(const Vec3& base, double baseRadius, const Vec3& apex,
                                       double apexRadius);

// The cone between the circle of `baseRadius` around `base` and that of
// `apexRadius` around `apex`, both perpendicular to the axis, then carried by
// x -> linear x + offset (the current transform). Requires coneProblem to
// find nothing and `linear` to be invertible.
Cone makeCone(const Vec3& base, double baseRadius, const Vec3& apex, double apexRadius,
              const Mat3& linear = Mat3(1.0), const Vec3& offset = Vec3(0.0));

// The nearest t inside `range` where the ray meets the side surface.
bool intersect(const Cone& c, const Ray& ray, Interval range, double& t);

// The unit normal at a point on the side, pointing away from the axis (for a
// cone also tilted toward the narrow end). At a pointed tip, where the
// surface has no normal, the axis direction out of the tip.
Vec3 normalAt(const Cone& c, const Vec3& point);
// That normal before it is carried to the world and normalised: the
// gradient in the cone's frame.
Vec3 sideGradient(const Cone& c, const Vec3& point);

// In the cone's frame: u the angle around the axis as a fraction of a turn
// (0.5 on the frame's +x axis, growing toward +y), v the height from the base
// circle (0) to the apex circle (1).
Vec2 uvAt(const Cone& c, const Vec3& point);

inline Aabb boundsOf(const Cone& c) { return c.bounds; }

// A box around the part of the cone between heights z0 and z1 of its frame
// (0 <= z0 <= z1 <= 1): sliceBounds(c, 0, 1) is c.bounds. A long thin cone
// lying across the axes fills little of its box; the hierarchy bounds it
// slice by slice (core/accel/primitive_boxes.h).
Aabb sliceBounds(const Cone& c, double z0, double z1);

// True when the cross-sections are circles in the world (the frame's x and y
// axes orthogonal, of equal length, and perpendicular to the axis), so the
// cone can be written as base, radius, apex, radius.
bool isCircular(const Cone& c);

} // namespace prism
