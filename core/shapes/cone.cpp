#include "core/shapes/cone.h"

#include "core/shapes/affine_frame.h"
#include "core/shapes/axis_frame.h"
#include "core/shapes/roundoff.h"

#include <algorithm>
#include <cmath>

namespace prism {

std::optional<std::string> coneProblem(const Vec3& base, double baseRadius, const Vec3& apex,
                                       double apexRadius) {
  if (!isFinite(base) || !isFinite(apex) || !std::isfinite(baseRadius) ||
      !std::isfinite(apexRadius))
    return "not finite";
  if (baseRadius < 0.0 || apexRadius < 0.0) return "negative radius";
  if (baseRadius == 0.0 && apexRadius == 0.0) return "both radii are zero";
  const Vec3 axis = apex - base;
  if (axis == Vec3(0.0)) return "base and apex are the same point";
  // The frame needs a unit axis; a length that underflows or overflows has none.
  const double scale = maxAbsComponent(axis);
  if (!std::isfinite(glm::length(axis / scale) * scale)) return "the axis is too long";
  return std::nullopt;
}

Cone makeCone(const Vec3& base, double baseRadius, const Vec3& apex, double apexRadius,
              const Mat3& linear, const Vec3& offset) {
  const Vec3 axis = apex - base;
  // Unit x and y keep the radii in world units; z spans the whole height.
  Mat3 frame = frameAround(axis);
  frame[2] = axis;
  Cone c;
  placeFrame(c, frame, base, linear, offset);
  c.baseRadius = baseRadius;
  c.apexRadius = apexRadius;
  c.roundoff = frameRoundoffScale(c.objectToWorld, c.worldToObject, c.objectToWorldOffset,
                                  std::max({1.0, baseRadius, apexRadius}));
  c.bounds = sliceBounds(c, 0.0, 1.0);
  return c;
}

Aabb sliceBounds(const Cone& c, double z0, double z1) {
  // The slice is the convex hull of its two end ellipses, so their boxes'
  // union bounds it. An ellipse at height z has centre m, semi-axes r X and
  // r Y (the frame's x and y axes); along world axis i it reaches
  // r sqrt(X_i^2 + Y_i^2) from m.
  const Mat3& m = c.objectToWorld;
  const Vec3 spread(std::hypot(m[0].x, m[1].x), std::hypot(m[0].y, m[1].y),
                    std::hypot(m[0].z, m[1].z));
  Aabb box;
  for (const double z : {z0, z1}) {
    // Both forms are exact at z = 0 and z = 1: the ends are the base and apex
    // circles themselves there.
    const Vec3 centre = c.objectToWorldOffset + z * m[2];
    const double radius = (1.0 - z) * c.baseRadius + z * c.apexRadius;
    box.extend(centre - radius * spread);
    box.extend(centre + radius * spread);
  }
  return box;
}

bool intersect(const Cone& c, const Ray& ray, Interval range, double& t) {
  Vec3 o = c.worldToObject * ray.origin + c.worldToObjectOffset;
  const Vec3 d = c.worldToObject * ray.dir;
  const double dd = glm::dot(d, d);
  // Solve from the point of the ray nearest the cone's middle: the quadratic's
  // coefficients then stay of the cone's size even for a far-away origin, and
  // no precision is lost to cancellation between huge terms.
  const double shift = glm::dot(Vec3(0.0, 0.0, 0.5) - o, d) / dd;
  o += shift * d;

  const double k = c.apexRadius - c.baseRadius; // radius gained per unit of z
  const double ro = c.baseRadius + k * o.z;     // radius at the origin's height
  const double a = d.x * d.x + d.y * d.y - k * k * d.z * d.z;
  const double b = o.x * d.x + o.y * d.y - k * d.z * ro; // half of the usual b
  const double cc = o.x * o.x + o.y * o.y - ro * ro;

  double roots[2];
  int count = 0;
  if (a == 0.0) {
    // Parallel to a line of the surface (for a cylinder: to the axis). One
    // crossing, unless the ray lies in the surface or never meets it.
    if (b == 0.0) return false;
    roots[count++] = -cc / (2.0 * b);
  } else {
    const double disc = b * b - a * cc;
    if (disc < 0.0) return false;
    // The stable pair of roots: q / a and cc / q never subtract close numbers.
    const double q = -(b + std::copysign(std::sqrt(disc), b));
    const double r0 = q / a;
    const double r1 = q != 0.0 ? cc / q : r0;
    roots[0] = std::min(r0, r1);
    roots[1] = std::max(r0, r1);
    count = 2;
  }
  for (int i = 0; i < count; ++i) {
    const double z = o.z + roots[i] * d.z;
    // Outside 0 <= z <= 1 is the cone's continuation (or its mirror nappe
    // beyond a tip), not the surface. Both ends are open.
    if (!(z >= 0.0 && z <= 1.0)) continue;
    const double candidate = shift + roots[i];
    if (range.contains(candidate)) {
      t = candidate;
      return true;
    }
  }
  return false;
}

Vec3 sideGradient(const Cone& c, const Vec3& point) {
  const Vec3 p = c.worldToObject * point + c.worldToObjectOffset;
  const double k = c.apexRadius - c.baseRadius;
  // The gradient of x^2 + y^2 - r(z)^2 (halved), pointing out of the solid.
  Vec3 g(p.x, p.y, -k * (c.baseRadius + k * p.z));
  if (g.x == 0.0 && g.y == 0.0) g = Vec3(0.0, 0.0, k < 0.0 ? 1.0 : -1.0); // the tip
  return g;
}

Vec3 normalAt(const Cone& c, const Vec3& point) {
  return glm::normalize(c.normalToWorld * sideGradient(c, point));
}

Vec2 uvAt(const Cone& c, const Vec3& point) {
  const Vec3 p = c.worldToObject * point + c.worldToObjectOffset;
  return {turnFraction(p.x, p.y), std::clamp(p.z, 0.0, 1.0)};
}

bool isCircular(const Cone& c) { return hasRoundSections(c.objectToWorld); }

} // namespace prism
