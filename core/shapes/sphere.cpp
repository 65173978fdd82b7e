#include "core/shapes/sphere.h"

#include "core/shapes/quadric.h"

namespace prism {

bool intersect(const Sphere& s, const Ray& ray, Interval range, double& t) {
  return nearestQuadricRoot(ray.origin - s.center, ray.dir, s.radius * s.radius, range, t);
}

Vec3 normalAt(const Sphere& s, const Vec3& point) { return glm::normalize(point - s.center); }

Vec2 longitudeLatitude(const Vec3& d) {
  constexpr double kPi = 3.14159265358979323846;
  // atan2 is in [-pi, pi]; asin of the clamped height in [-pi/2, pi/2] (a
  // direction normalised with round-off may have |y| a hair above 1).
  return {0.5 + std::atan2(d.x, d.z) / (2.0 * kPi),
          0.5 + std::asin(std::clamp(d.y, -1.0, 1.0)) / kPi};
}

Vec2 uvAt(const Sphere& s, const Vec3& point) { return longitudeLatitude(normalAt(s, point)); }

Aabb boundsOf(const Sphere& s) {
  Aabb box;
  box.extend(s.center - Vec3(s.radius));
  box.extend(s.center + Vec3(s.radius));
  return box;
}

} // namespace prism
