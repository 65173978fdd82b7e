#include "core/shapes/quadric_surface.h"

#include "core/shapes/box.h" // slabSpan
#include "core/shapes/roundoff.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace prism {

std::optional<std::string> quadricProblem(const std::array<double, 10>& coef, const Vec3& corner0,
                                          const Vec3& corner1) {
  for (const double c : coef)
    if (!std::isfinite(c)) return "not finite";
  if (std::all_of(coef.begin(), coef.begin() + 9, [](double c) { return c == 0.0; }))
    return "the coefficients A to I are all zero (no surface)";
  if (std::optional<std::string> problem = boxProblem(corner0, corner1))
    return "clip box: " + *problem;
  return std::nullopt;
}

Quadric makeQuadric(const std::array<double, 10>& coef, const Vec3& corner0, const Vec3& corner1,
                    const Mat3& linear, const Vec3& offset) {
  Quadric q;
  q.frame = makeAffineFrame(linear, offset);
  q.lo = glm::min(corner0, corner1);
  q.hi = glm::max(corner0, corner1);
  const double size = std::max(maxAbsComponent(q.lo), maxAbsComponent(q.hi));
  // The largest term over the clip box, brought into [1, 2) by a power of
  // two (exact). When it overflows, the largest coefficient instead.
  double largest = std::abs(coef[9]), largestCoef = 0.0;
  for (int i = 0; i < 9; ++i) {
    const double degree = i < 6 ? 2.0 : 1.0;
    largest = std::max(largest, std::abs(coef[i]) * std::pow(size, degree));
    largestCoef = std::max(largestCoef, std::abs(coef[i]));
  }
  if (!std::isfinite(largest) || !(largest > 0.0))
    largest = std::max(largestCoef, std::abs(coef[9]));
  q.exponent = -std::ilogb(largest);
  for (int i = 0; i < 10; ++i)
    q.coef[i] = std::ldexp(coef[i], q.exponent);
  q.roundoff = frameRoundoffScale(q.frame.objectToWorld, q.frame.worldToObject,
                                  q.frame.objectToWorldOffset, size);
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p((corner & 1) ? q.hi.x : q.lo.x, (corner & 2) ? q.hi.y : q.lo.y,
                 (corner & 4) ? q.hi.z : q.lo.z);
    q.bounds.extend(q.frame.objectToWorld * p + q.frame.objectToWorldOffset);
  }
  return q;
}

std::array<double, 10> givenCoefficients(const Quadric& q) {
  std::array<double, 10> given;
  for (int i = 0; i < 10; ++i)
    given[i] = std::ldexp(q.coef[i], -q.exponent);
  return given;
}

double quadricValue(const Quadric& q, const Vec3& p) {
  const auto& k = q.coef;
  return p.x * (k[0] * p.x + k[3] * p.y + k[5] * p.z + k[6]) +
         p.y * (k[1] * p.y + k[4] * p.z + k[7]) + p.z * (k[2] * p.z + k[8]) + k[9];
}

Vec3 quadricGradient(const Quadric& q, const Vec3& p) {
  const auto& k = q.coef;
  return {2.0 * k[0] * p.x + k[3] * p.y + k[5] * p.z + k[6],
          2.0 * k[1] * p.y + k[3] * p.x + k[4] * p.z + k[7],
          2.0 * k[2] * p.z + k[4] * p.y + k[5] * p.x + k[8]};
}

bool intersect(const Quadric& q, const Ray& ray, Interval range, double& t) {
  const Vec3 o = q.frame.pointToObject(ray.origin);
  const Vec3 d = q.frame.directionToObject(ray.dir);
  BoxSpan span;
  if (!slabSpan(o, d, q.lo, q.hi, span) || span.t1 < range.min || span.t0 > range.max) return false;
  // The line restarted inside the clip box, at the middle of its span, with a
  // unit direction: p + s dir, t = middle + s / speed. A far-away origin then
  // leaves numbers of the box's size (as for Cone and Torus).
  const double scale = maxAbsComponent(d);
  const Vec3 dir = glm::normalize(d / scale);
  const double speed = scale * glm::length(d / scale);
  const double middle = 0.5 * (span.t0 + span.t1);
  const Vec3 p = o + middle * d;
  // f(p + s dir) = a s^2 + b s + c.
  const auto& k = q.coef;
  const double a = dir.x * (k[0] * dir.x + k[3] * dir.y + k[5] * dir.z) +
                   dir.y * (k[1] * dir.y + k[4] * dir.z) + k[2] * dir.z * dir.z;
  const double b = glm::dot(quadricGradient(q, p), dir);
  const double c = quadricValue(q, p);
  double roots[2] = {0.0, 0.0}; // initialised only to quiet a false -Wmaybe-uninitialized
  int count = 0;
  if (a == 0.0) {
    // Along a paraboloid's axis or a cylinder's lines: linear (or, with b
    // also zero, parallel to the surface or lying in it: no crossing).
    if (b == 0.0) return false;
    roots[count++] = -c / b;
  } else {
    const double disc = b * b - 4.0 * a * c;
    if (disc < 0.0) return false;
    // The stable pair: no cancellation between b and the square root. A tiny
    // a (nearly along the axis) leaves q / a huge, far outside the box, and
    // c / qq accurate.
    const double qq = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    double r0 = qq / a, r1 = qq != 0.0 ? c / qq : r0;
    if (r0 > r1) std::swap(r0, r1);
    roots[count++] = r0;
    roots[count++] = r1;
  }
  for (int i = 0; i < count; ++i) {
    double s = roots[i];
    // One Newton step from the root, with the polynomial evaluated at the hit
    // point rather than at the box's middle: its round-off is then that of
    // the numbers near the surface (a thin cylinder in a large box keeps its
    // precision). Only a step that cannot reach the other root.
    const Vec3 x = p + s * dir;
    const double slope = glm::dot(quadricGradient(q, x), dir);
    if (slope != 0.0) {
      const double step = quadricValue(q, x) / slope;
      const double gap = count == 2 ? roots[1] - roots[0] : std::numeric_limits<double>::infinity();
      if (std::abs(step) < 0.25 * gap) s -= step;
    }
    const double candidate = middle + s / speed;
    if (candidate >= span.t0 && candidate <= span.t1 && range.contains(candidate)) {
      t = candidate;
      return true;
    }
  }
  return false;
}

Vec3 normalAt(const Quadric& q, const Vec3& point) {
  const Vec3 g = quadricGradient(q, q.frame.pointToObject(point));
  return q.frame.normalToWorldUnit(g == Vec3(0.0) || !isFinite(g) ? Vec3(0.0, 0.0, 1.0) : g);
}

Vec2 uvAt(const Quadric& q, const Vec3& point) {
  const Vec3 p = q.frame.pointToObject(point);
  const Vec3 centre = 0.5 * (q.lo + q.hi);
  return {turnFraction(p.x - centre.x, p.y - centre.y),
          std::clamp((p.z - q.lo.z) / (q.hi.z - q.lo.z), 0.0, 1.0)};
}

bool isUnplaced(const Quadric& q) {
  return q.frame.objectToWorld == Mat3(1.0) && q.frame.objectToWorldOffset == Vec3(0.0);
}

} // namespace prism
