// Spheres: a centre and a radius, in world space (a sphere under a similarity
// transform stays one; under any other it becomes an Ellipsoid).
#pragma once

#include "core/math/aabb.h"
#include "core/math/interval.h"
#include "core/math/ray.h"
#include "core/shapes/primitives.h"

namespace prism {

struct Sphere {
  static constexpr const char* kName = "sphere";
  static constexpr bool kFlat = false; // a ray leaving it can meet it again

  Vec3 center{0.0};
  double radius = 1.0;
  std::uint32_t material = 0;
  Origin origin;
};

// The nearest t inside `range` where the ray meets the sphere.
bool intersect(const Sphere& s, const Ray& ray, Interval range, double& t);
// The unit outward normal at a point on the sphere.
Vec3 normalAt(const Sphere& s, const Vec3& point);
// Longitude and latitude, each in [0, 1], of a unit direction from the centre
// (y is up, as for the default camera): u grows counterclockwise seen from
// above, is 0.5 toward +z (facing the default camera, so the seam at u = 0
// and 1 lies behind) and v is 0 at the south pole, 1 at the north pole.
Vec2 longitudeLatitude(const Vec3& unitDirection);
// longitudeLatitude of the point's direction from the centre.
Vec2 uvAt(const Sphere& s, const Vec3& point);
Aabb boundsOf(const Sphere& s);

} // namespace prism
