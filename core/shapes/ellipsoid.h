// Ellipsoids: spheres under a transform that is not a similarity.
#pragma once

#include "core/math/aabb.h"
#include "core/math/interval.h"
#include "core/math/ray.h"
#include "core/shapes/primitives.h"

namespace prism {

// A sphere under a non-uniform scale: the image of the unit sphere under an
// affine map. Stored as the inverse map, which takes rays into the unit sphere's
// space, and the matrix that carries object normals back to world space; the
// map itself is kept too, for writing the ellipsoid back as text (inverting the
// inverse overflows for very flat ellipsoids).
struct Ellipsoid {
  static constexpr const char* kName = "ellipsoid";
  static constexpr bool kFlat = false;

  Mat3 worldToObject{1.0};
  Vec3 worldToObjectOffset{0.0};
  Mat3 normalToWorld{1.0}; // transpose of worldToObject
  Aabb bounds;
  Mat3 objectToWorld{1.0};
  Vec3 center{0.0}; // objectToWorld's offset
  // roundoffScale (core/shapes/roundoff.h), computed once: it takes square roots.
  double roundoff = 0.0;
  std::uint32_t material = 0;
  Origin origin;
};

bool intersect(const Ellipsoid& e, const Ray& ray, Interval range, double& t);
Vec3 normalAt(const Ellipsoid& e, const Vec3& point);
// The longitude and latitude (see Sphere) of the point on the unit sphere the
// ellipsoid is the image of: they move with the ellipsoid.
Vec2 uvAt(const Ellipsoid& e, const Vec3& point);
// The ellipsoid that is the unit sphere under `objectToWorld` (linear part
// `linear`, then `offset`); `linear` must be invertible.
Ellipsoid makeEllipsoid(const Mat3& linear, const Vec3& offset);

inline Aabb boundsOf(const Ellipsoid& e) { return e.bounds; }

} // namespace prism
