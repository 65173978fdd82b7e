// A ray X = origin + t * dir with a unit-length direction, so t is a distance.
#pragma once

#include "core/math/math.h"

namespace prism {

struct Ray {
  Vec3 origin{0.0};
  Vec3 dir{0.0, 0.0, -1.0};

  Vec3 at(double t) const { return origin + t * dir; }
};

// A ray with a NaN or infinite component hits nothing. Hierarchies check this
// first: in their box tests a NaN culls nothing, so such a ray would enter
// every box, unused child slots included, and never finish.
inline bool isFinite(const Ray& ray) { return isFinite(ray.origin) && isFinite(ray.dir); }

// How far a hierarchy widens every box for `ray` (in space, on each side).
// Primitive tests compute relative to the ray's origin, and with a far origin
// (a ray that starts 1e16 away from a unit sphere) their rounding, a few
// ulps of the origin's coordinates, can exceed a box's size and padding: the
// box test would cull a primitive that its own test hits. 2^-46 of the
// largest origin coordinate (64 of its ulps) keeps every box test
// conservative; for ordinary scenes it is far below any modelled detail.
constexpr double kBoxSlackPerCoordinate = 0x1p-46;
inline double boxSlack(const Ray& ray) {
  return kBoxSlackPerCoordinate * maxAbsComponent(ray.origin);
}

// What a traced ray is for; statistics and the --pixel ray tree are kept by kind.
enum class RayKind { Eye, Shadow, Reflected, Transmitted };

const char* rayKindName(RayKind kind);

} // namespace prism
