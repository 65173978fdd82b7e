#include "core/shapes/disc.h"

#include "core/shapes/roundoff.h"

#include <algorithm>
#include <cmath>

namespace prism {

std::optional<std::string> discProblem(const Vec3& center, const Vec3& normal, double radius) {
  if (!isFinite(center) || !isFinite(normal) || !std::isfinite(radius)) return "not finite";
  if (radius < 0.0) return "negative radius";
  if (radius == 0.0) return "the radius is zero";
  if (normal == Vec3(0.0)) return "the normal is the zero vector";
  return std::nullopt;
}

Disc makeDisc(const Vec3& center, const Vec3& normal, double radius, const Mat3& linear,
              const Vec3& offset) {
  Vec3 w(0.0, 0.0, 1.0), u, v;
  unitDirection(normal, w); // discProblem found a direction
  perpendicularPair(w, u, v);
  Disc d;
  d.frame = makeAffineFrame(linear * Mat3(u, v, w), linear * center + offset);
  d.radius = radius;
  d.normal = d.frame.normalToWorldUnit(Vec3(0.0, 0.0, 1.0));
  const AffineFrame& f = d.frame;
  d.roundoff = frameRoundoffScale(f.objectToWorld, f.worldToObject, f.objectToWorldOffset,
                                  std::max(1.0, radius));
  // An ellipse: along world axis i it reaches radius sqrt(X_i^2 + Y_i^2)
  // from the centre (X, Y the frame's in-plane axes).
  const Mat3& m = f.objectToWorld;
  const Vec3 spread(std::hypot(m[0].x, m[1].x), std::hypot(m[0].y, m[1].y),
                    std::hypot(m[0].z, m[1].z));
  d.bounds.extend(f.objectToWorldOffset - radius * spread);
  d.bounds.extend(f.objectToWorldOffset + radius * spread);
  return d;
}

bool intersect(const Disc& disc, const Ray& ray, Interval range, double& t) {
  Vec3 o = disc.frame.pointToObject(ray.origin);
  const Vec3 d = disc.frame.directionToObject(ray.dir);
  // A ray in the disc's plane (or parallel to it) never crosses it.
  if (d.z == 0.0) return false;
  // From the point of the ray nearest the centre (as for cones): the
  // containment test then works with numbers of the disc's size.
  const double shift = -glm::dot(o, d) / glm::dot(d, d);
  o += shift * d;
  const double along = -o.z / d.z;
  const double candidate = shift + along;
  if (!range.contains(candidate)) return false;
  const double x = o.x + along * d.x, y = o.y + along * d.y;
  if (!(x * x + y * y <= disc.radius * disc.radius)) return false;
  t = candidate;
  return true;
}

Vec2 uvAt(const Disc& d, const Vec3& point) {
  const Vec3 p = d.frame.pointToObject(point);
  return {turnFraction(p.x, p.y), std::min(std::hypot(p.x, p.y) / d.radius, 1.0)};
}

bool isCircular(const Disc& d) {
  const Vec3& x = d.frame.objectToWorld[0];
  const Vec3& y = d.frame.objectToWorld[1];
  const double lx = glm::length(x), ly = glm::length(y);
  constexpr double kTolerance = 1e-12;
  return std::abs(lx - ly) <= kTolerance * lx && std::abs(glm::dot(x, y)) <= kTolerance * lx * ly;
}

} // namespace prism
