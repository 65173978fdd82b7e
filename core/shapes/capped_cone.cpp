#include "core/shapes/capped_cone.h"

#include "core/shapes/affine_frame.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace prism {

CappedCone makeCappedCone(const Vec3& base, double baseRadius, const Vec3& apex, double apexRadius,
                          const Mat3& linear, const Vec3& offset) {
  CappedCone c;
  c.side = makeCone(base, baseRadius, apex, apexRadius, linear, offset);
  return c;
}

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Where the ray (o + t d, in the frame) is inside the infinite double cone
// x^2 + y^2 <= r(z)^2: up to two intervals, ends possibly infinite.
int quadricIntervals(const Cone& c, const Vec3& o, const Vec3& d, double lo[2], double hi[2]) {
  const double k = c.apexRadius - c.baseRadius; // radius gained per unit of z
  const double ro = c.baseRadius + k * o.z;     // radius at the origin's height
  const double a = d.x * d.x + d.y * d.y - k * k * d.z * d.z;
  const double b = o.x * d.x + o.y * d.y - k * d.z * ro; // half of the usual b
  const double cc = o.x * o.x + o.y * o.y - ro * ro;
  if (a == 0.0) {
    // Parallel to a line of the surface: a half-line, the whole line (in the
    // surface or inside a cylinder along its axis) or nothing.
    if (b == 0.0) {
      if (!(cc <= 0.0)) return 0;
      lo[0] = -kInfinity, hi[0] = kInfinity;
      return 1;
    }
    const double root = -cc / (2.0 * b);
    lo[0] = b > 0.0 ? -kInfinity : root;
    hi[0] = b > 0.0 ? root : kInfinity;
    return 1;
  }
  double disc = b * b - a * cc;
  if (disc < 0.0) {
    if (a > 0.0) return 0;
    // Steeper than the surface, the line crosses both nappes, so the true
    // discriminant is not negative: round-off near the tip.
    disc = 0.0;
  }
  // The stable pair of roots, as for the open cone.
  const double q = -(b + std::copysign(std::sqrt(disc), b));
  const double r0 = q / a;
  const double r1 = q != 0.0 ? cc / q : r0;
  const double first = std::min(r0, r1), second = std::max(r0, r1);
  if (a > 0.0) {
    lo[0] = first, hi[0] = second;
    return 1;
  }
  // Inside at both ends: one half-line in each nappe. Only one nappe meets
  // the slab 0 <= z <= 1 (the other lies beyond the tip), so clipping by the
  // slab keeps the right one.
  lo[0] = -kInfinity, hi[0] = first;
  lo[1] = second, hi[1] = kInfinity;
  return 2;
}

} // namespace

int coneSpans(const CappedCone& capped, const Ray& ray, ConeSpan spans[2]) {
  const Cone& c = capped.side;
  Vec3 o = c.worldToObject * ray.origin + c.worldToObjectOffset;
  const Vec3 d = c.worldToObject * ray.dir;
  // Solve from the point of the ray nearest the middle (as the open cone
  // does): every number below is then of the cone's size.
  const double shift = glm::dot(Vec3(0.0, 0.0, 0.5) - o, d) / glm::dot(d, d);
  o += shift * d;

  // The slab between the caps' planes.
  double s0 = -kInfinity, s1 = kInfinity;
  // A cap of radius 0 is only the tip, which belongs to the side.
  std::uint32_t enterCap = c.baseRadius > 0.0 ? CappedCone::kBaseCap : CappedCone::kSide;
  std::uint32_t leaveCap = c.apexRadius > 0.0 ? CappedCone::kApexCap : CappedCone::kSide;
  if (d.z == 0.0) {
    if (!(o.z >= 0.0 && o.z <= 1.0)) return 0;
  } else {
    const double toBase = -o.z / d.z, toApex = (1.0 - o.z) / d.z;
    if (d.z > 0.0) {
      s0 = toBase, s1 = toApex;
    } else {
      s0 = toApex, s1 = toBase;
      std::swap(enterCap, leaveCap);
    }
  }

  // The solid is the slab's interval intersected with the double cone's:
  // one max and one min, so where the side meets a cap the two agree on
  // which is crossed and no ray passes between them at a rim.
  double lo[2], hi[2];
  const int intervals = quadricIntervals(c, o, d, lo, hi);
  int count = 0;
  for (int i = 0; i < intervals; ++i) {
    ConeSpan span;
    span.t0 = std::max(s0, lo[i]);
    span.part0 = s0 >= lo[i] ? enterCap : CappedCone::kSide;
    span.t1 = std::min(s1, hi[i]);
    span.part1 = s1 <= hi[i] ? leaveCap : CappedCone::kSide;
    // Both ends are finite: a ray with d.z = 0 has a > 0 (a finite interval).
    if (!(span.t0 <= span.t1)) continue;
    span.t0 += shift;
    span.t1 += shift;
    spans[count++] = span;
  }
  return count;
}

bool intersect(const CappedCone& c, const Ray& ray, Interval range, double& t) {
  ConeSpan spans[2];
  const int count = coneSpans(c, ray, spans);
  for (int i = 0; i < count; ++i) {
    for (const double candidate : {spans[i].t0, spans[i].t1}) {
      if (range.contains(candidate)) {
        t = candidate;
        return true;
      }
    }
  }
  return false;
}

std::uint32_t partAt(const CappedCone& capped, const Vec3& point) {
  const Cone& c = capped.side;
  const Vec3 p = c.worldToObject * point + c.worldToObjectOffset;
  const Mat3& m = c.objectToWorld;
  // Distances in the frame, scaled by the world length of its axes.
  const double height = glm::length(m[2]);
  const double across = std::max(glm::length(m[0]), glm::length(m[1]));
  const double radius = c.baseRadius + (c.apexRadius - c.baseRadius) * p.z;
  std::uint32_t part = CappedCone::kSide;
  double nearest = std::abs(std::hypot(p.x, p.y) - radius) * across;
  if (c.baseRadius > 0.0 && std::abs(p.z) * height < nearest) {
    nearest = std::abs(p.z) * height;
    part = CappedCone::kBaseCap;
  }
  if (c.apexRadius > 0.0 && std::abs(1.0 - p.z) * height < nearest) part = CappedCone::kApexCap;
  return part;
}

namespace {

// The normals scaled before they are normalised (unitLength): a very flat
// cone's gradients are long.
Vec3 partNormal(const CappedCone& c, std::uint32_t part, const Vec3& point) {
  switch (part) {
  case CappedCone::kBaseCap: return unitLength(-c.side.normalToWorld[2]);
  case CappedCone::kApexCap: return unitLength(c.side.normalToWorld[2]);
  default: return unitLength(c.side.normalToWorld * sideGradient(c.side, point));
  }
}

} // namespace

Vec3 normalAt(const CappedCone& c, const Vec3& point) {
  return partNormal(c, partAt(c, point), point);
}

SurfacePoint surfaceAt(const CappedCone& c, const ShapeArrays&, const Vec3& point) {
  SurfacePoint s;
  s.point = point;
  s.part = partAt(c, point);
  s.outward = partNormal(c, s.part, point);
  s.shading = s.outward;
  s.roundoffScale = c.side.roundoff;
  return s;
}

Vec2 uvAt(const CappedCone& capped, const Vec3& point) {
  const Cone& c = capped.side;
  const std::uint32_t part = partAt(capped, point);
  if (part == CappedCone::kSide) return uvAt(c, point);
  const Vec3 p = c.worldToObject * point + c.worldToObjectOffset;
  const double radius = part == CappedCone::kBaseCap ? c.baseRadius : c.apexRadius;
  return {turnFraction(p.x, p.y), std::min(std::hypot(p.x, p.y) / radius, 1.0)};
}

} // namespace prism
