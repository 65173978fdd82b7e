#include "core/shapes/ellipsoid.h"

#include "core/shapes/quadric.h"
#include "core/shapes/roundoff.h"
#include "core/shapes/sphere.h"

#include <cmath>

namespace prism {

bool intersect(const Ellipsoid& e, const Ray& ray, Interval range, double& t) {
  // In the unit sphere's space the ray keeps its parameter: X(t) maps to X'(t).
  const Vec3 o = e.worldToObject * ray.origin + e.worldToObjectOffset;
  const Vec3 d = e.worldToObject * ray.dir;
  return nearestQuadricRoot(o, d, 1.0, range, t);
}

Vec3 normalAt(const Ellipsoid& e, const Vec3& point) {
  const Vec3 objectNormal = e.worldToObject * point + e.worldToObjectOffset;
  return glm::normalize(e.normalToWorld * objectNormal);
}

Vec2 uvAt(const Ellipsoid& e, const Vec3& point) {
  return longitudeLatitude(glm::normalize(e.worldToObject * point + e.worldToObjectOffset));
}

Ellipsoid makeEllipsoid(const Mat3& linear, const Vec3& offset) {
  Ellipsoid e;
  e.worldToObject = glm::inverse(linear);
  e.worldToObjectOffset = -(e.worldToObject * offset);
  e.normalToWorld = glm::transpose(e.worldToObject);
  e.objectToWorld = linear;
  e.center = offset;
  e.roundoff = frameRoundoffScale(linear, e.worldToObject, offset, 1.0);
  // The unit sphere's image extends sqrt(sum_j A_ij^2) along world axis i
  // (hypot: no underflow for a very flat ellipsoid).
  const Mat3& m = linear;
  const Vec3 half(std::hypot(m[0].x, m[1].x, m[2].x), std::hypot(m[0].y, m[1].y, m[2].y),
                  std::hypot(m[0].z, m[1].z, m[2].z));
  e.bounds.extend(offset - half);
  e.bounds.extend(offset + half);
  return e;
}

} // namespace prism
