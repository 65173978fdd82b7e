#include "core/shapes/sphere.h"

#include "core/shapes/quadric.h"

namespace prism {

bool intersect(const Sphere& s, const Ray& ray, Interval range, double& t) {
  return nearestQuadricRoot(ray.origin - s.center, ray.dir, s.radius * s.radius, range, t);
}

Vec3 normalAt(const Sphere& s, const Vec3& point) { return glm::normalize(point - s.center); }

Aabb boundsOf(const Sphere& s) {
  Aabb box;
  box.extend(s.center - Vec3(s.radius));
  box.extend(s.center + Vec3(s.radius));
  return box;
}

} // namespace prism
